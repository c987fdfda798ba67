#include "support/calibration_file.hpp"

#include "app/resources/calibration.hpp"
#include "io/atomic_file.hpp"
#include "io/json_value.hpp"
#include "io/version.hpp"

#include <ctime>
#include <ostream>
#include <string>

namespace grainload::bench {

void write_calibration(const std::string& path, const CalibrationFile& c) {
    const std::time_t now = std::time(nullptr);
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M", std::localtime(&now));
    io::write_file_atomically(path, [&](std::ostream& out) {
        const auto put = [&](const char* key, double value) {
            out << "  \"" << key << "\": " << io::json_number(value) << ",\n";
        };
        out << "{\n  \"source\": " << io::json_quoted(app::kCalibrationSource) << ",\n"
            << "  \"date\": " << io::json_quoted(date) << ",\n"
            << "  \"git_hash\": " << io::json_quoted(kGitHash) << ",\n";
        put("seconds_per_entry_2d", c.two_d.entry);
        put("seconds_per_body_2d", c.two_d.body);
        put("seconds_per_wall_2d", c.two_d.wall);
        put("seconds_per_contact_entry_2d", c.two_d.contact_entry);
        put("corrected_factor_2d", c.two_d.corrected_factor);
        put("total_lagrangian_factor_2d", c.two_d.total_lagrangian_factor);
        put("seconds_per_entry_3d", c.three_d.entry);
        put("seconds_per_body_3d", c.three_d.body);
        put("seconds_per_wall_3d", c.three_d.wall);
        put("seconds_per_contact_entry_3d", c.three_d.contact_entry);
        put("corrected_factor_3d", c.three_d.corrected_factor);
        put("total_lagrangian_factor_3d", c.three_d.total_lagrangian_factor);
        put("shell_factorisation_seconds", c.shell.factorisation_seconds);
        put("shell_factorisation_dofs", c.shell.factorisation_dofs);
        put("shell_seconds_per_dof_solved_step", c.shell.per_dof_solved_step);
        put("shell_seconds_per_dof_settled_step", c.shell.per_dof_settled_step);
        put("shell_seconds_per_element_assembly", c.shell.per_element_assembly);
        put("shell_seconds_per_dof_back_substitution", c.shell.per_dof_back_substitution);
        // Costs measured by running the grainload executable: absent, and named under
        // "not_measured", when its runs failed (app/resources/calibration.hpp keeps the
        // built-in figures for them and says so).
        std::string not_measured;
        const auto put_measured = [&](bool measured, const char* key, double value) {
            if (measured) {
                put(key, value);
            } else {
                not_measured += (not_measured.empty() ? "" : ", ") + io::json_quoted(key);
            }
        };
        put_measured(c.steps.measured, "seconds_per_step_2d", c.steps.per_step_2d);
        put_measured(c.steps.measured, "seconds_per_step_3d", c.steps.per_step_3d);
        put_measured(c.dem.measured, "dem_seconds_per_step", c.dem.per_step);
        put_measured(c.dem.measured, "dem_seconds_per_grain_step", c.dem.per_grain_step);
        put_measured(c.output.measured, "seconds_per_frame", c.output.per_frame);
        put_measured(c.output.measured, "seconds_per_frame_point", c.output.per_point);
        out << "  \"not_measured\": [" << not_measured << "],\n";
        put("threads_measured", c.threads);
        put("speedup", c.speedup);
        put("load_before", c.load_before);
        put("others_load", c.others_load);
        out << "  \"quiet\": " << (c.quiet ? "true" : "false") << "\n}\n";
    });
}

} // namespace grainload::bench
