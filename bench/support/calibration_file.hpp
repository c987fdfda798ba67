#pragma once
// The throughput calibration's figures and the file `grainload check` reads them from.

#include "support/output_calibration.hpp"
#include "support/shell_calibration.hpp"

#include <string>

namespace grainload::bench {

/// Seconds per SPH step of one thread: per neighbour-list entry between body particles and
/// between a body and a wall particle (contact), per body particle and per wall particle
/// (app/resources/calibration.hpp).
struct SphCosts {
    double entry = 0.0;
    double contact_entry = 0.0;
    double body = 0.0;
    double wall = 0.0;
    /// A block's step with the kernel-gradient correction on, and in the total Lagrangian
    /// formulation (linear elastic, correction on), over the same block's step without
    double corrected_factor = 1.0;
    double total_lagrangian_factor = 1.0;
};

/// Everything `bench/sph_throughput --calibrate` measured, and how busy the machine was.
struct CalibrationFile {
    SphCosts two_d;
    SphCosts three_d;
    ShellCosts shell;
    FrameCosts output;
    StepCosts steps;
    DemCosts dem;
    int threads = 1;
    double speedup = 1.0;
    double load_before = 0.0; ///< other processes' use of the machine before it measured [cores]
    double others_load = 0.0; ///< and while it measured
    bool quiet = false;
};

/// Writes `c` as the JSON file app/resources/calibration.hpp reads (atomically), dated now.
void write_calibration(const std::string& path, const CalibrationFile& c);

} // namespace grainload::bench
