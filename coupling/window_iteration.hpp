#pragma once
// The passes of an iterated coupling window, for the SPH and the DEM couplings alike.

#include "coupling/coupling_monitor.hpp"
#include "coupling/coupling_settings.hpp"
#include "coupling/interface_accelerator.hpp"

#include <Eigen/Core>
#include <chrono>

namespace grainload::coupling {

/// The fixed-point iteration of one window on its interface load F (max_iterations > 1;
/// docs/theory/coupling.md): `pass(applied, k, produced)` runs pass k from the window's start
/// (the model restores its start state for k > 1) under the load `applied`, sets `produced` to
/// the load the particles made and returns the pass's record. The passes stop when that load
/// changes by at most iteration_tolerance against its input, or at max_iterations; every input
/// after the first is the accelerator's (Aitken or IQN-ILS from the relaxation factor). Returns
/// the last pass's record with its pass count, its load change and the wall time of every pass;
/// `produced` holds its load.
template <class Pass>
WindowRecord iterate_passes(const CouplingSettings& settings, const Eigen::VectorXd& load,
                            Pass pass, Eigen::VectorXd& produced) {
    using Clock = std::chrono::steady_clock;
    Eigen::VectorXd applied = load;
    InterfaceAccelerator accelerator(settings.accelerator, settings.relaxation);
    WindowRecord spent; // the wall times of the passes before, which the window costs too
    for (int k = 1;; ++k) {
        WindowRecord record = pass(applied, k, produced);
        record.sand_seconds += spent.sand_seconds;
        record.fem_seconds += spent.fem_seconds;
        record.map_seconds += spent.map_seconds;
        const auto start = Clock::now();
        record.iterations = k;
        record.load_change = relative_change(produced, applied);
        const bool done =
            record.load_change <= settings.iteration_tolerance || k >= settings.max_iterations;
        if (!done) {
            applied = accelerator.next(applied, produced);
        }
        record.map_seconds += std::chrono::duration<double>(Clock::now() - start).count();
        if (done) {
            return record;
        }
        spent = record;
    }
}

} // namespace grainload::coupling
