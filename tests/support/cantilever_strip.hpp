#pragma once
// The shell tests' cantilever strip, clamped at one end and loaded at the other.

#include "fem/shell_analysis.hpp"

#include <Eigen/Core>

namespace grainload::testing {

/// The shell tests' cantilever: a strip made by make_plate along x, clamped at x = 0 (node set
/// "x0"), loaded at its tip (node set "x1") by `total` on DOF `dof` of each node's six (2: a
/// force along z, 4: a moment about y), split equally over the tip's nodes, and solved.
inline bool load_clamped_strip(fem::ShellAnalysis& analysis, int dof, double total) {
    const fem::ShellMesh& mesh = analysis.mesh();
    analysis.prescribe(mesh.node_set("x0"), {0, 1, 2, 3, 4, 5});
    Eigen::VectorXd forces = Eigen::VectorXd::Zero(6 * mesh.node_count());
    const auto& tip = mesh.node_set("x1");
    for (const Index n : tip) {
        forces(6 * n + dof) = total / static_cast<double>(tip.size());
    }
    analysis.set_additional_forces(forces);
    return analysis.equilibrate(fem::NewtonSettings{}).converged;
}

} // namespace grainload::testing
