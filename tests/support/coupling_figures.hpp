#pragma once
// Figures read from a coupled run's coupling.csv.

#include "support/case_runner.hpp"
#include "support/csv_rows.hpp"

#include <initializer_list>
#include <string>

namespace grainload::testing {

/// The shell's mean vertical interface load over the coupling windows that end after `after`
/// (s): coupling.csv's shell_impulse_z (applied load times window) summed over those windows,
/// divided by their length, which `time` receives.
inline double mean_shell_load_z(const std::string& out, double after, double& time) {
    constexpr std::size_t kTime = 0, kWindow = 1, kShellImpulseZ = 13; // coupling.csv columns
    double impulse = 0.0;
    time = 0.0;
    for (const auto& row : numeric_csv_rows(out + "/coupling.csv")) {
        if (row[kTime] > after + 1e-9) {
            impulse += row[kShellImpulseZ];
            time += row[kWindow];
        }
    }
    return time > 0.0 ? impulse / time : 0.0;
}

/// The vertical forces of rigid walls `wall_NAME_force_z` in a summary.json text, summed.
inline double walls_force_z(const std::string& summary, std::initializer_list<const char*> walls) {
    double sum = 0.0;
    for (const char* wall : walls) {
        sum += result_value(summary, std::string("wall_") + wall + "_force_z");
    }
    return sum;
}

} // namespace grainload::testing
