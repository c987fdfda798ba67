#include "io/run_summary.hpp"

#include "io/atomic_file.hpp"
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

std::string quoted(const std::string& text) {
    std::ostringstream out;
    out << '"';
    for (char c : text) {
        switch (c) {
        case '"':
            out << "\\\"";
            break;
        case '\\':
            out << "\\\\";
            break;
        case '\n':
            out << "\\n";
            break;
        case '\t':
            out << "\\t";
            break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                out << "\\u" << std::hex << std::setw(4) << std::setfill('0') << int(c) << std::dec;
            } else {
                out << c;
            }
        }
    }
    out << '"';
    return out.str();
}

// JSON has no NaN or infinity; a diverged figure is written as null.
std::string number(double value) {
    if (!std::isfinite(value)) {
        return "null";
    }
    std::ostringstream out;
    out << std::setprecision(12) << value;
    return out.str();
}

// A phase's times to 17 digits, which read back as the same double: a run restated with fixed
// times in place of a condition (remove_at, a history's points) then takes the same steps.
std::string exact(double value) {
    if (!std::isfinite(value)) {
        return "null";
    }
    std::ostringstream out;
    out << std::setprecision(17) << value;
    return out.str();
}

void write_phases(std::ostream& out, const std::vector<PhaseRecord>& phases) {
    out << "  \"phases\": [";
    for (std::size_t i = 0; i < phases.size(); ++i) {
        const PhaseRecord& phase = phases[i];
        out << (i == 0 ? "\n    " : ",\n    ") << "{\"name\": " << quoted(phase.name)
            << ", \"start\": " << exact(phase.start) << ", \"end\": " << exact(phase.end)
            << ", \"ended_by\": "
            << (phase.ended_by.empty() ? std::string("null") : quoted(phase.ended_by)) << '}';
    }
    out << (phases.empty() ? "],\n" : "\n  ],\n");
}

void write_result(std::ostream& out, const ResultFigure& figure) {
    out << "    " << quoted(figure.name) << ": {\"value\": " << number(figure.value)
        << ", \"unit\": " << quoted(figure.unit);
    if (figure.reference) {
        const double reference = *figure.reference;
        out << ", \"reference\": " << number(reference)
            << ", \"source\": " << quoted(figure.source);
        if (reference != 0.0) {
            out << ", \"relative_error\": "
                << number(std::abs(figure.value - reference) / std::abs(reference));
        } else {
            out << ", \"absolute_error\": " << number(std::abs(figure.value));
        }
    } else if (!figure.source.empty()) {
        out << ", \"source\": " << quoted(figure.source); // a statement without a value
    }
    out << '}';
}

} // namespace

void write_run_summary(const RunSummary& summary, const std::string& path) {
    write_file_atomically(path, [&](std::ostream& out) {
        out << "{\n"
            << "  \"case\": " << quoted(summary.case_name) << ",\n"
            << "  \"case_file\": " << quoted(summary.case_file) << ",\n"
            << "  \"overrides\": [";
        for (std::size_t i = 0; i < summary.overrides.size(); ++i) {
            out << (i == 0 ? "" : ", ") << quoted(summary.overrides[i]);
        }
        out << "],\n"
            << "  \"version\": " << quoted(kVersion) << ",\n"
            << "  \"git_hash\": " << quoted(kGitHash) << ",\n"
            << "  \"status\": " << quoted(summary.status) << ",\n";
        if (!summary.diagnosis.empty()) {
            out << "  \"diagnosis\": " << quoted(summary.diagnosis) << ",\n";
        }
        out << "  \"threads\": " << summary.threads << ",\n"
            << "  \"wall_time_s\": " << number(summary.wall_time) << ",\n"
            << "  \"simulated_time_s\": " << number(summary.simulated_time) << ",\n"
            << "  \"steps\": " << summary.steps << ",\n"
            << "  \"particles\": " << summary.points << ",\n"
            << "  \"material_points\": " << summary.material_points << ",\n"
            << "  \"particle_steps_per_second\": " << number(summary.point_steps_per_second())
            << ",\n";
        if (summary.estimated_steps && summary.estimated_wall_time) {
            const double steps = *summary.estimated_steps;
            const double wall = *summary.estimated_wall_time;
            out << "  \"estimate\": {\"steps\": " << number(steps)
                << ", \"wall_time_s\": " << number(wall)
                << ", \"steps_ratio\": " << number(static_cast<double>(summary.steps) / steps)
                << ", \"wall_time_ratio\": " << number(summary.wall_time / wall) << "},\n";
        }
        out << "  \"model\": {";
        for (std::size_t i = 0; i < summary.model.size(); ++i) {
            out << (i == 0 ? "" : ", ") << quoted(summary.model[i].item) << ": "
                << quoted(summary.model[i].choice);
        }
        out << "},\n  \"hints\": [";
        for (std::size_t i = 0; i < summary.hints.size(); ++i) {
            out << (i == 0 ? "\n    " : ",\n    ") << quoted(summary.hints[i]);
        }
        out << (summary.hints.empty() ? "],\n" : "\n  ],\n");
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
