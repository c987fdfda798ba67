#include "coupling/window_limits.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>

namespace grainload::coupling {

namespace {

/// The loop gain the relaxed update tolerates: |1 - omega (1 + g)| < 1.
double tolerated_gain(double omega) {
    return 2.0 / omega - 1.0;
}

} // namespace

WindowLimits estimate_window_limits(const sph::SphModel& sph, fem::ShellModel& fem,
                                    const std::vector<CoupledPart>& parts, double omega) {
    WindowLimits limits;
    const sph::SphSolver& solver = *sph.solver();
    const sph::ParticleSet& p = solver.particles();
    double mass = 0.0;
    double volume = 0.0;
    for (Index i = 0; i < p.size(); ++i) {
        if (p.is_wall(i)) {
            continue;
        }
        const auto& material = *solver.materials()[static_cast<std::size_t>(p.material_id[i])];
        limits.impedance =
            std::max(limits.impedance, material.density() * material.elastic().p_wave_speed());
        mass += p.mass[i];
        volume += p.mass[i] / p.density[i];
    }
    fem::ShellAnalysis& analysis = fem.analysis();
    const fem::ShellMesh& mesh = analysis.mesh();
    double area = 0.0;
    limits.shell_mass = std::numeric_limits<double>::infinity();
    Eigen::VectorXd unit_pressure = Eigen::VectorXd::Zero(analysis.dofs().size());
    std::vector<Vec3> outward(static_cast<std::size_t>(mesh.node_count()), Vec3::Zero());
    for (const CoupledPart& part : parts) {
        const double density =
            analysis.parts()[static_cast<std::size_t>(mesh.element(part.elements.front()).part)]
                .material->density();
        for (const Index e : part.elements) {
            const fem::ShellElement& element = mesh.element(e);
            const double a = fem::element_area(mesh, element);
            area += a;
            limits.shell_mass = std::min(limits.shell_mass, density * element.thickness);
            // The sand pushes against its side's normal.
            // (both sides: either side's push, the same compliance for a linear shell)
            const Vec3 push = -normal_sign(part.side) * fem::element_normal(mesh, element);
            const int corners = element.is_triangle() ? 3 : 4;
            for (int k = 0; k < corners; ++k) {
                const Index node = element.nodes[static_cast<std::size_t>(k)];
                unit_pressure.segment<3>(6 * node) += (a / corners) * push;
                outward[static_cast<std::size_t>(node)] = push;
            }
        }
    }
    const double impedance = std::max(limits.impedance, 1e-300);
    if (fem.dynamic()) {
        limits.dynamic_max = tolerated_gain(omega) * limits.shell_mass / (3.0 * impedance);
        return limits;
    }
    limits.sand_mass = area > 0.0 ? mass / volume * (volume / area) : 0.0;
    const Eigen::VectorXd response = analysis.tangent_response(unit_pressure);
    for (Index n = 0; n < mesh.node_count(); ++n) {
        limits.compliance =
            std::max(limits.compliance,
                     response.segment<3>(6 * n).dot(outward[static_cast<std::size_t>(n)]));
    }
    limits.static_min = std::sqrt(limits.sand_mass * limits.compliance / tolerated_gain(omega));
    return limits;
}

std::optional<std::string> window_refusal(const WindowLimits& limits, double window, bool dynamic,
                                          double omega) {
    std::ostringstream why;
    if (dynamic && window > 2.0 * limits.dynamic_max) {
        why << "the coupling window " << window << " s is longer than the staggered exchange can "
            << "take with a dynamic shell: about " << limits.dynamic_max
            << " s (the sand's impedance rho c = " << limits.impedance
            << " kg/(m^2 s) against the lightest coupled part's " << limits.shell_mass
            << " kg/m^2, relaxation " << omega
            << "); use a window of at most that, or iterate each window (max_iterations > 1)";
        return why.str();
    }
    if (!dynamic && window < 0.5 * limits.static_min) {
        why << "the coupling window " << window << " s is shorter than the staggered exchange "
            << "can take with a static shell: about " << limits.static_min
            << " s (the sand's areal mass " << limits.sand_mass
            << " kg/m^2 against the shell's compliance " << limits.compliance
            << " m/Pa, relaxation " << omega
            << "); use a window of at least that, a smaller relaxation, or iterate each window "
               "(max_iterations > 1)";
        return why.str();
    }
    return std::nullopt;
}

} // namespace grainload::coupling
