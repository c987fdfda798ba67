#pragma once
// Standard shell benchmarks (MacNeal & Harder 1985) with their published displacements.

#include "fem/shell_analysis.hpp"

#include <memory>
#include <string>

namespace grainload::fem {

/// A standard shell benchmark (MacNeal & Harder 1985; Belytschko et al. 1985), built on a
/// quarter/octant model with its symmetry conditions, and the DOF whose value is published.
struct ShellBenchmark {
    std::unique_ptr<materials::Material> material; ///< declared first: outlives `analysis`
    std::unique_ptr<ShellAnalysis> analysis;
    Index monitor_node = -1;
    int monitor_dof = 0;
    double reference = 0.0; ///< published magnitude of the monitored displacement [m]
    std::string name;
    std::string source;

    double monitored_value() const {
        return std::abs(analysis->displacement(monitor_node)(monitor_dof));
    }
};

/// Scordelis-Lo roof under self-weight, quarter model with n x n elements: R = 25, L = 50,
/// t = 0.25, 80 deg arc, E = 4.32e8, nu = 0, q = 90 per unit area; reference 0.3024 (vertical
/// displacement at mid-span of the free edge).
ShellBenchmark scordelis_lo_roof(int n);

/// Pinched cylinder with rigid end diaphragms, octant model with n x n elements: R = 300,
/// L = 600, t = 3, E = 3e6, nu = 0.3, P = 1; reference 1.8248e-5 under the load.
ShellBenchmark pinched_cylinder(int n);

/// Pinched hemisphere with an 18 deg hole, quarter model with n x n elements: R = 10, t = 0.04,
/// E = 6.825e7, nu = 0.3, alternating radial loads of 2 (1 on each half-load point of the
/// quarter); reference 0.094 radial displacement under the load.
ShellBenchmark pinched_hemisphere(int n);

} // namespace grainload::fem
