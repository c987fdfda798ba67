#include "fem/newmark_integrator.hpp"
#include "fem/shell_mesh_generators.hpp"
#include "materials/linear_elastic.hpp"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <numbers>

namespace grainload::fem {
namespace {

// Free vibration of a simply supported square steel plate released from its first mode
// shape. Kirchhoff plate: omega_11 = pi^2 (2 / a^2) sqrt(D / (rho t)) (Timoshenko & Young,
// "Vibration Problems in Engineering", section 6.7 / Leissa 1969, NASA SP-160, Table 4.20).
// a = 1 m, t = 0.01 m: f_11 = 49.17 Hz. Quarter model (8 x 8) with symmetry, lumped mass,
// trapezoidal rule with dt = T/50, over three periods.
TEST(PlateVibration, FirstFrequencyAndEnergyConservation) {
    const double pi = std::numbers::pi;
    const double a = 1.0, t = 0.01, young = 2.1e11, nu = 0.3, rho = 7850.0;
    const materials::LinearElastic steel(materials::ElasticConstants::from_young(rho, young, nu));
    ShellAnalysis analysis(make_plate(0.5 * a, 0.5 * a, 8, 8, t), steel, Kinematics::linear, 2);
    const ShellMesh& mesh = analysis.mesh();
    analysis.prescribe(mesh.node_set("all"), {0, 1, 5}); // bending only
    analysis.prescribe(mesh.node_set("x0"), {2, 3});     // simple support at x = 0
    analysis.prescribe(mesh.node_set("y0"), {2, 4});     // simple support at y = 0
    analysis.prescribe(mesh.node_set("x1"), {4});        // symmetry at x = a/2
    analysis.prescribe(mesh.node_set("y1"), {3});        // symmetry at y = a/2
    Eigen::VectorXd mode = Eigen::VectorXd::Zero(6 * mesh.node_count());
    const double w0 = 1e-3;
    for (Index n = 0; n < mesh.node_count(); ++n) {
        const double x = mesh.node(n).x(), y = mesh.node(n).y();
        mode(6 * n + 2) = w0 * std::sin(pi * x / a) * std::sin(pi * y / a);
        mode(6 * n + 3) = w0 * pi / a * std::sin(pi * x / a) * std::cos(pi * y / a);
        mode(6 * n + 4) = -w0 * pi / a * std::cos(pi * x / a) * std::sin(pi * y / a);
    }
    for (std::size_t d = 0; d < analysis.prescribed_values().size(); ++d) {
        if (!std::isnan(analysis.prescribed_values()[d])) {
            mode(static_cast<Eigen::Index>(d)) = 0.0;
        }
    }
    analysis.update_state(mode);
    analysis.commit();
    NewmarkIntegrator newmark(analysis);
    newmark.initialise(Eigen::VectorXd::Zero(mode.size()));

    const double d = young * t * t * t / (12.0 * (1.0 - nu * nu));
    const double omega = pi * pi * 2.0 / (a * a) * std::sqrt(d / (rho * t));
    const double period = 2.0 * pi / omega;
    const double dt = period / 50.0;
    const Index centre = mesh.nearest_node(Vec3(0.5 * a, 0.5 * a, 0.0));
    const double energy0 = newmark.strain_energy();
    double previous = analysis.displacement(centre).z();
    std::vector<double> crossings;
    double drift = 0.0;
    NewtonSettings settings;
    for (int s = 1; s <= 150; ++s) {
        ASSERT_TRUE(newmark.step(dt, 0.0, settings).converged);
        const double w = analysis.displacement(centre).z();
        if (previous > 0.0 && w <= 0.0) { // downward zero crossing, linear interpolation
            crossings.push_back(dt * (s - 1 + previous / (previous - w)));
        }
        previous = w;
        const double energy = newmark.kinetic_energy() + newmark.strain_energy();
        drift = std::max(drift, std::abs(energy / energy0 - 1.0));
    }
    ASSERT_GE(crossings.size(), 3u);
    const double measured = (crossings.back() - crossings.front()) / double(crossings.size() - 1);
    std::printf("period %.6f s (f = %.3f Hz), Kirchhoff %.6f s (f = %.3f Hz), error %+.2f %%; "
                "energy drift %.2e\n",
                measured, 1.0 / measured, period, 1.0 / period, 100.0 * (measured / period - 1.0),
                drift);
    // Acceptance of the issue: 2 %. Trapezoidal period elongation (omega dt)^2 / 12 = 0.13 %.
    EXPECT_NEAR(measured, period, 0.02 * period);
    // The trapezoidal rule conserves the energy of a linear system (Bathe FEP section 9.4.4);
    // what remains is the round-off of the Newton tolerance.
    EXPECT_LT(drift, 1e-9); // measured 5e-12
}

} // namespace
} // namespace grainload::fem
