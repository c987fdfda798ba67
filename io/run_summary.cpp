#include "io/run_summary.hpp"

#include "io/atomic_file.hpp"
#include "io/json_value.hpp"
#include "io/version.hpp"

#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace grainload::io {

double RunSummary::point_steps_per_second() const {
    if (!(wall_time > 0.0)) {
        return 0.0;
    }
    if (material_point_steps) {
        return *material_point_steps / wall_time;
    }
    return static_cast<double>(material_points) * static_cast<double>(steps) / wall_time;
}

namespace {

// A phase's times to 17 digits, which read back as the same double: a run restated with fixed
// times in place of a condition (remove_at, a history's points) then takes the same steps.
std::string exact(double value) {
    return json_number(value, 17);
}

void write_phases(std::ostream& out, const std::vector<PhaseRecord>& phases) {
    out << "  \"phases\": [";
    for (std::size_t i = 0; i < phases.size(); ++i) {
        const PhaseRecord& phase = phases[i];
        out << (i == 0 ? "\n    " : ",\n    ") << "{\"name\": " << json_quoted(phase.name)
            << ", \"start\": " << exact(phase.start) << ", \"end\": " << exact(phase.end)
            << ", \"ended_by\": "
            << (phase.ended_by.empty() ? std::string("null") : json_quoted(phase.ended_by)) << '}';
    }
    out << (phases.empty() ? "],\n" : "\n  ],\n");
}

void write_result(std::ostream& out, const ResultFigure& figure) {
    out << "    " << json_quoted(figure.name) << ": {\"value\": " << json_number(figure.value)
        << ", \"unit\": " << json_quoted(figure.unit);
    if (figure.reference) {
        const double reference = *figure.reference;
        out << ", \"reference\": " << json_number(reference)
            << ", \"source\": " << json_quoted(figure.source);
        if (reference != 0.0) {
            out << ", \"relative_error\": "
                << json_number(std::abs(figure.value - reference) / std::abs(reference));
        } else {
            out << ", \"absolute_error\": " << json_number(std::abs(figure.value));
        }
    } else if (!figure.source.empty()) {
        out << ", \"source\": " << json_quoted(figure.source); // a statement without a value
    }
    out << '}';
}

/// What ran: the case, its overrides, the build and how the run ended.
void write_identity(std::ostream& out, const RunSummary& summary) {
    out << "  \"case\": " << json_quoted(summary.case_name) << ",\n"
        << "  \"case_file\": " << json_quoted(summary.case_file) << ",\n"
        << "  \"overrides\": [";
    for (std::size_t i = 0; i < summary.overrides.size(); ++i) {
        out << (i == 0 ? "" : ", ") << json_quoted(summary.overrides[i]);
    }
    out << "],\n"
        << "  \"version\": " << json_quoted(kVersion) << ",\n"
        << "  \"git_hash\": " << json_quoted(kGitHash) << ",\n"
        << "  \"status\": " << json_quoted(summary.status) << ",\n";
    if (!summary.diagnosis.empty()) {
        out << "  \"diagnosis\": " << json_quoted(summary.diagnosis) << ",\n";
    }
}

/// What the run cost: threads, times, steps, points and their rates.
void write_effort(std::ostream& out, const RunSummary& summary) {
    out << "  \"threads\": " << summary.threads << ",\n"
        << "  \"wall_time_s\": " << json_number(summary.wall_time) << ",\n";
    if (summary.cpu_time) {
        out << "  \"cpu_time_s\": " << json_number(*summary.cpu_time) << ",\n";
    }
    out << "  \"simulated_time_s\": " << json_number(summary.simulated_time) << ",\n"
        << "  \"steps\": " << summary.steps << ",\n"
        << "  \"particles\": " << summary.points << ",\n"
        << "  \"material_points\": " << summary.material_points << ",\n"
        << "  \"particle_steps_per_second\": " << json_number(summary.point_steps_per_second())
        << ",\n";
    if (summary.shell_nodes > 0) {
        out << "  \"shell_nodes\": " << summary.shell_nodes << ",\n"
            << "  \"shell_node_steps_per_second\": "
            << json_number(summary.wall_time > 0.0 ? summary.shell_node_steps / summary.wall_time
                                                   : 0.0)
            << ",\n";
    }
}

/// The estimate made before the run, and the run against it.
void write_estimate(std::ostream& out, const RunSummary& summary) {
    if (!summary.estimated_steps || !summary.estimated_wall_time) {
        return;
    }
    const double steps = *summary.estimated_steps;
    const double wall = *summary.estimated_wall_time;
    out << "  \"estimate\": {\"steps\": " << json_number(steps)
        << ", \"wall_time_s\": " << json_number(wall)
        << ", \"steps_ratio\": " << json_number(static_cast<double>(summary.steps) / steps)
        << ", \"wall_time_ratio\": " << json_number(summary.wall_time / wall);
    if (summary.cpu_time) {
        out << ", \"cpu_time_ratio\": " << json_number(*summary.cpu_time / wall);
    }
    if (summary.estimated_factorisations) {
        out << ", \"fem_factorisations\": " << json_number(*summary.estimated_factorisations);
    }
    if (summary.estimated_back_substitutions) {
        out << ", \"fem_back_substitutions\": "
            << json_number(*summary.estimated_back_substitutions);
    }
    out << ", \"calibration\": " << json_quoted(summary.estimate_calibration) << "},\n";
}

/// What was modelled and the hints for the user.
void write_model_and_hints(std::ostream& out, const RunSummary& summary) {
    out << "  \"model\": {";
    for (std::size_t i = 0; i < summary.model.size(); ++i) {
        out << (i == 0 ? "" : ", ") << json_quoted(summary.model[i].item) << ": "
            << json_quoted(summary.model[i].choice);
    }
    out << "},\n  \"hints\": [";
    for (std::size_t i = 0; i < summary.hints.size(); ++i) {
        out << (i == 0 ? "\n    " : ",\n    ") << json_quoted(summary.hints[i]);
    }
    out << (summary.hints.empty() ? "],\n" : "\n  ],\n");
}

} // namespace

void write_run_summary(const RunSummary& summary, const std::string& path) {
    write_file_atomically(path, [&](std::ostream& out) {
        out << "{\n";
        write_identity(out, summary);
        write_effort(out, summary);
        write_estimate(out, summary);
        write_model_and_hints(out, summary);
        if (!summary.phases.empty()) {
            write_phases(out, summary.phases);
        }
        out << "  \"results\": {";
        for (std::size_t i = 0; i < summary.results.size(); ++i) {
            out << (i == 0 ? "\n" : ",\n");
            write_result(out, summary.results[i]);
        }
        out << (summary.results.empty() ? "}\n" : "\n  }\n") << "}\n";
    });
}

} // namespace grainload::io
