#pragma once
// How the coupling solves each window: its length, sub-cycles, iterations and watchdog.

#include "coupling/interface_accelerator.hpp"

namespace grainload::coupling {

/// How each window is solved (docs/theory/coupling.md). The case file's defaults are declared
/// with its keys (coupling_case_reader.hpp, kCouplingKeys); the values here are the same, which
/// coupling_case_reader.cpp asserts at compile time.
struct CouplingSettings {
    double window = 0.0;     ///< FEM step: the coupling window [s]
    int max_subcycles = 0;   ///< SPH steps a window may take; 0: no limit
    int max_iterations = 1;  ///< 1: staggered with a one-window lag; > 1: fixed-point iteration
    double relaxation = 0.5; ///< omega of the iteration's load update
    Accelerator accelerator = Accelerator::aitken; ///< the iterated window's update
    double iteration_tolerance = 1e-3; ///< ||F(k+1) - F(k)|| / ||F(k+1)|| that ends the iteration
    /// Run stopped (exit 3) when |interface energy error| exceeds this fraction of the interface
    /// work (with an absolute floor, coupling_monitor.hpp).
    double energy_error_limit = 0.05;
    /// beta of the added-mass springs on a static shell (coupling/added_mass.hpp); 0: none.
    double added_mass = 0.0;
};

} // namespace grainload::coupling
