#include "coupling/added_mass.hpp"

#include "coupling/window_limits.hpp"

namespace grainload::coupling {

std::vector<fem::ShellAnalysis::NodeSpring>
added_mass_springs(const fem::ShellMesh& mesh, const std::vector<CoupledPart>& parts,
                   double areal_mass, double window, double factor) {
    std::vector<fem::ShellAnalysis::NodeSpring> springs;
    const double stiffness = factor * areal_mass / (window * window); // per area [Pa/m]
    if (!(stiffness > 0.0)) {
        return springs;
    }
    const Eigen::VectorXd area_vectors = coupled_area_vectors(mesh, parts);
    for (Index n = 0; n < mesh.node_count(); ++n) {
        const Vec3 w = area_vectors.segment<3>(6 * n);
        const double area = w.norm();
        if (area > 0.0) {
            // Along the node's normal only: the sand's inertia resists the wall's normal
            // motion; along the wall it slides (friction), which this does not model.
            springs.push_back({n, Mat3(stiffness * w * w.transpose() / area)});
        }
    }
    return springs;
}

} // namespace grainload::coupling
