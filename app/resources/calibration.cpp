#include "app/resources/calibration.hpp"

#include "io/json_value.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

namespace grainload::app {

namespace {

namespace fs = std::filesystem;

std::string calibration_path() {
    if (const char* path = std::getenv("GRAINLOAD_CALIBRATION")) {
        return path;
    }
    std::error_code error;
    const fs::path exe = fs::read_symlink("/proc/self/exe", error);
    return error ? std::string() : (exe.parent_path().parent_path() / "calibration.json").string();
}

/// Every cost the file holds, each kept at the built-in constant when absent (a file of an
/// older bench lacks the shell's).
void read_costs(const io::JsonValue& file, Calibration& c) {
    const auto get = [&](const char* key, double& value) {
        value = file.number_at(key).value_or(value);
    };
    get("seconds_per_entry_2d", c.seconds_per_entry_2d);
    get("seconds_per_body_2d", c.seconds_per_body_2d);
    get("seconds_per_wall_2d", c.seconds_per_wall_2d);
    get("seconds_per_contact_entry_2d", c.seconds_per_contact_entry_2d);
    get("seconds_per_entry_3d", c.seconds_per_entry_3d);
    get("seconds_per_body_3d", c.seconds_per_body_3d);
    get("seconds_per_wall_3d", c.seconds_per_wall_3d);
    get("seconds_per_contact_entry_3d", c.seconds_per_contact_entry_3d);
    get("corrected_factor_2d", c.corrected_factor_2d);
    get("corrected_factor_3d", c.corrected_factor_3d);
    get("total_lagrangian_factor_2d", c.total_lagrangian_factor_2d);
    get("total_lagrangian_factor_3d", c.total_lagrangian_factor_3d);
    get("seconds_per_step_2d", c.seconds_per_step_2d);
    get("seconds_per_step_3d", c.seconds_per_step_3d);
    get("shell_factorisation_seconds", c.shell_factorisation_seconds);
    get("shell_factorisation_dofs", c.shell_factorisation_dofs);
    get("shell_seconds_per_dof_solved_step", c.shell_seconds_per_dof_solved_step);
    get("shell_seconds_per_dof_settled_step", c.shell_seconds_per_dof_settled_step);
    get("shell_seconds_per_element_assembly", c.shell_seconds_per_element_assembly);
    get("shell_seconds_per_dof_back_substitution", c.shell_seconds_per_dof_back_substitution);
    get("dem_seconds_per_step", c.dem_seconds_per_step);
    get("dem_seconds_per_grain_step", c.dem_seconds_per_grain_step);
    get("seconds_per_frame", c.seconds_per_frame);
    get("seconds_per_frame_point", c.seconds_per_frame_point);
}

/// Appends `text` to the reading's note.
void add_note(Calibration& c, const std::string& text) {
    c.note += (c.note.empty() ? "" : "; ") + text;
}

/// The speed-up and how quiet the machine was; a speed-up below 1 is set aside.
void read_speedup(const io::JsonValue& file, Calibration& c) {
    c.threads_measured = static_cast<int>(file.number_at("threads_measured").value_or(1.0));
    c.speedup = file.number_at("speedup").value_or(1.0);
    c.others_load = file.number_at("others_load").value_or(-1.0);
    const io::JsonValue* quiet = file.find("quiet");
    c.quiet = quiet != nullptr && quiet->type == io::JsonValue::Type::boolean
                  ? quiet->boolean
                  : c.others_load >= 0.0 && c.others_load < kQuietLoad;
    if (c.threads_measured > 1 && !(c.speedup >= 1.0)) {
        // More threads slower than one: the machine was busy while the bench measured.
        char text[200];
        std::snprintf(text, sizeof text,
                      "its speed-up of %d threads, %.2f, is below 1 and contradicts itself: "
                      "discarded, every thread count estimated at one thread's speed",
                      c.threads_measured, c.speedup);
        add_note(c, text);
        c.threads_measured = 1;
        c.speedup = 1.0;
    }
}

/// The costs the bench measures by running the grainload executable, in pairs: a pair named
/// under "not_measured", or, in a file of the bench without that list, both zero (the bench
/// wrote zeros when its runs failed; no step, frame or grain costs nothing), keeps its built-in
/// figures, and the note says so. A file written by hand is taken at its word.
void keep_unmeasured(const io::JsonValue& file, Calibration& c) {
    struct Pair {
        const char* what;
        const char* keys[2];
        double Calibration::*fields[2];
    };
    static const Pair pairs[] = {
        {"a step's fixed cost",
         {"seconds_per_step_2d", "seconds_per_step_3d"},
         {&Calibration::seconds_per_step_2d, &Calibration::seconds_per_step_3d}},
        {"the DEM's costs",
         {"dem_seconds_per_step", "dem_seconds_per_grain_step"},
         {&Calibration::dem_seconds_per_step, &Calibration::dem_seconds_per_grain_step}},
        {"an output instant's cost",
         {"seconds_per_frame", "seconds_per_frame_point"},
         {&Calibration::seconds_per_frame, &Calibration::seconds_per_frame_point}}};
    const io::JsonValue* listed = file.find("not_measured");
    const bool earlier_bench = listed == nullptr && file.string_at("source") == kCalibrationSource;
    const auto is_listed = [&](std::string_view key) {
        if (listed == nullptr || listed->type != io::JsonValue::Type::array) {
            return false;
        }
        for (const io::JsonValue& name : listed->array) {
            if (name.type == io::JsonValue::Type::string && name.string == key) {
                return true;
            }
        }
        return false;
    };
    const Calibration built_in;
    std::string what;
    for (const Pair& pair : pairs) {
        const bool zero = c.*pair.fields[0] == 0.0 && c.*pair.fields[1] == 0.0;
        if ((earlier_bench && zero) || is_listed(pair.keys[0]) || is_listed(pair.keys[1])) {
            c.*pair.fields[0] = built_in.*pair.fields[0];
            c.*pair.fields[1] = built_in.*pair.fields[1];
            what += (what.empty() ? "" : ", ") + std::string(pair.what);
        }
    }
    if (!what.empty()) {
        add_note(c, "incomplete: " + what +
                        " not measured (the bench could not run the grainload executable), the "
                        "built-in figures used; measure again with bench/sph_throughput "
                        "--calibrate on a quiet machine");
    }
}

} // namespace

Calibration load_calibration() {
    Calibration c;
    const std::string path = calibration_path();
    if (path.empty() || !fs::exists(path)) {
        return c;
    }
    try {
        const io::JsonValue file = io::read_json_file(path);
        read_costs(file, c);
        read_speedup(file, c);
        keep_unmeasured(file, c);
        c.source = path + " (" + file.string_at("date").value_or("undated") + ")";
    } catch (const io::JsonError& e) {
        c = Calibration{};
        c.source = std::string("built-in constants (") + e.what() + ")";
    }
    return c;
}

std::string describe_calibration(const Calibration& c) {
    std::string text = c.source;
    char load[160];
    if (c.others_load >= 0.0) {
        std::snprintf(load, sizeof load, "; measured %s (other processes used %.2f cores)",
                      c.quiet ? "on a quiet machine" : "under load, not quiet", c.others_load);
        text += load;
    } else if (c.source.rfind("built-in", 0) != 0) {
        text += "; how busy the machine was is not recorded";
    }
    if (c.threads_measured > 1) {
        std::snprintf(load, sizeof load, "; %d threads %.2fx one", c.threads_measured, c.speedup);
        text += load;
    }
    if (!c.note.empty()) {
        text += "; " + c.note;
    }
    return text;
}

} // namespace grainload::app
