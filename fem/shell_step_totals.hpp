#pragma once
// The totals of the shell's load steps that summary.json reports, kept across restarts.

#include "fem/newton_solver.hpp"

#include <istream>
#include <map>
#include <ostream>
#include <string>

namespace grainload::fem {

/// What summary.json reports of the shell's load steps (the last step's load factor, Newton
/// iterations and solver; how many steps each factorisation solved), kept over the whole run:
/// the step log itself lives only in the process that ran the steps, so these totals go into
/// the checkpoint and a restarted run reports the uninterrupted run's figures.
struct ShellStepTotals {
    bool any = false;
    double last_load_factor = 0.0;
    int last_iterations = 0;
    std::string last_solver;
    std::map<std::string, int> steps_by_solver; ///< steps whose last solve went through each

    void add(double load_factor, const StepReport& report);
    void write(std::ostream& out) const;
    /// Throws std::runtime_error on a malformed record (the checkpoint reader names the file).
    void read(std::istream& in);
};

} // namespace grainload::fem
