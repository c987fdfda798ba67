#include "fem/newmark_integrator.hpp"
#include "fem/shell_mesh_generators.hpp"
#include "materials/linear_elastic.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <memory>
#include <numbers>

namespace grainload::fem {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kA = 1.0, kT = 0.01, kYoung = 2.1e11, kNu = 0.3, kRho = 7850.0;
const materials::LinearElastic kSteel(materials::ElasticConstants::from_young(kRho, kYoung, kNu));

/// Kirchhoff first frequency omega_11 = pi^2 (2 / a^2) sqrt(D / (rho t)) (Timoshenko & Young,
/// "Vibration Problems in Engineering", section 6.7 / Leissa 1969, NASA SP-160, Table 4.20).
double first_omega() {
    const double d = kYoung * kT * kT * kT / (12.0 * (1.0 - kNu * kNu));
    return kPi * kPi * 2.0 / (kA * kA) * std::sqrt(d / (kRho * kT));
}

/// Quarter model (8 x 8) of the simply supported square plate, bending DOFs only, displaced
/// into its first mode shape (amplitude 1 mm) and committed.
std::unique_ptr<ShellAnalysis> plate_in_first_mode(int elements = 8) {
    auto analysis = std::make_unique<ShellAnalysis>(
        make_plate(0.5 * kA, 0.5 * kA, elements, elements, kT), kSteel, Kinematics::linear, 2);
    const ShellMesh& mesh = analysis->mesh();
    analysis->prescribe(mesh.node_set("all"), {0, 1, 5}); // bending only
    analysis->prescribe(mesh.node_set("x0"), {2, 3});     // simple support at x = 0
    analysis->prescribe(mesh.node_set("y0"), {2, 4});     // simple support at y = 0
    analysis->prescribe(mesh.node_set("x1"), {4});        // symmetry at x = a/2
    analysis->prescribe(mesh.node_set("y1"), {3});        // symmetry at y = a/2
    Eigen::VectorXd mode = Eigen::VectorXd::Zero(6 * mesh.node_count());
    const double w0 = 1e-3;
    for (Index n = 0; n < mesh.node_count(); ++n) {
        const double x = mesh.node(n).x(), y = mesh.node(n).y();
        mode(6 * n + 2) = w0 * std::sin(kPi * x / kA) * std::sin(kPi * y / kA);
        mode(6 * n + 3) = w0 * kPi / kA * std::sin(kPi * x / kA) * std::cos(kPi * y / kA);
        mode(6 * n + 4) = -w0 * kPi / kA * std::cos(kPi * x / kA) * std::sin(kPi * y / kA);
    }
    for (std::size_t d = 0; d < analysis->equation_numbers().size(); ++d) {
        if (analysis->equation_numbers()[d] < 0) {
            mode(static_cast<Eigen::Index>(d)) = 0.0;
        }
    }
    analysis->update_state(mode);
    analysis->commit();
    return analysis;
}

/// Period of the centre deflection from its downward zero crossings over `steps` steps.
double measured_period(ShellAnalysis& analysis, NewmarkIntegrator& integrator, double dt,
                       int steps) {
    const Index centre = analysis.mesh().nearest_node(Vec3(0.5 * kA, 0.5 * kA, 0.0));
    double previous = analysis.displacement(centre).z();
    std::vector<double> crossings;
    for (int s = 1; s <= steps; ++s) {
        EXPECT_TRUE(integrator.step(dt, 0.0, NewtonSettings{}).converged);
        const double w = analysis.displacement(centre).z();
        if (previous > 0.0 && w <= 0.0) { // linear interpolation
            crossings.push_back(dt * (s - 1 + previous / (previous - w)));
        }
        previous = w;
    }
    EXPECT_GE(crossings.size(), 3u);
    return (crossings.back() - crossings.front()) / double(crossings.size() - 1);
}

// Free vibration of a simply supported square steel plate released from its first mode
// shape: a = 1 m, t = 0.01 m, f_11 = 49.17 Hz. Lumped mass, trapezoidal rule with dt = T/50,
// over three periods.
TEST(PlateVibration, FirstFrequencyAndEnergyConservation) {
    auto owner = plate_in_first_mode();
    ShellAnalysis& analysis = *owner;
    const ShellMesh& mesh = analysis.mesh();
    NewmarkIntegrator newmark(analysis);
    newmark.initialise(Eigen::VectorXd::Zero(6 * mesh.node_count()));
    const double period = 2.0 * kPi / first_omega();
    const double dt = period / 50.0;
    const Index centre = mesh.nearest_node(Vec3(0.5 * kA, 0.5 * kA, 0.0));
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
    // Acceptance bound: 2 %. Trapezoidal period elongation (omega dt)^2 / 12 = 0.13 %.
    EXPECT_NEAR(measured, period, 0.02 * period);
    // The trapezoidal rule conserves the energy of a linear system (Bathe FEP section 9.4.4);
    // what remains is the round-off of the Newton tolerance.
    EXPECT_LT(drift, 1e-9); // measured 5e-12
}

// HHT-alpha with alpha = 0 is the trapezoidal rule: the same states step by step.
TEST(PlateVibration, HhtWithAlphaZeroIsTrapezoidal) {
    auto a = plate_in_first_mode();
    auto b = plate_in_first_mode();
    NewmarkIntegrator trapezoidal(*a);
    NewmarkIntegrator hht = NewmarkIntegrator::hht(*b, 0.0);
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(a->dofs().size());
    trapezoidal.initialise(zero);
    hht.initialise(zero);
    const double dt = 2.0 * kPi / first_omega() / 20.0;
    for (int s = 0; s < 20; ++s) {
        ASSERT_TRUE(trapezoidal.step(dt, 0.0, NewtonSettings{}).converged);
        ASSERT_TRUE(hht.step(dt, 0.0, NewtonSettings{}).converged);
    }
    EXPECT_LT((a->dofs() - b->dofs()).norm(), 1e-12 * a->dofs().norm());
}

/// Spectral radius of the HHT-alpha amplification matrix of the undamped oscillator at
/// Omega = omega dt (Hilber, Hughes & Taylor 1977, eqs. 9-11): A x(n+1) = B x(n) for
/// x = (u, dt v, dt^2 a).
double hht_spectral_radius(double alpha, double omega_dt) {
    const double beta = 0.25 * (1.0 - alpha) * (1.0 - alpha), gamma = 0.5 - alpha;
    const double w2 = omega_dt * omega_dt;
    Eigen::Matrix3d a, b;
    a << (1.0 + alpha) * w2, 0.0, 1.0, 1.0, 0.0, -beta, 0.0, 1.0, -gamma;
    b << alpha * w2, 0.0, 0.0, 1.0, 1.0, 0.5 - beta, 0.0, 1.0, 1.0 - gamma;
    return (a.inverse() * b).eigenvalues().cwiseAbs().maxCoeff();
}

/// Decay rate per step of the centre deflection after `steps` steps of `dt`: the least-squares
/// fit of u(n+1) = p u(n) + q u(n-1) over the late steps (the principal root pair rho e^(+-i
/// phi) has q = -rho^2; the spurious root and the higher modes have died out by then).
double measured_radius(ShellAnalysis& analysis, NewmarkIntegrator& integrator, double dt,
                       int steps) {
    const Index centre = analysis.mesh().nearest_node(Vec3(0.5 * kA, 0.5 * kA, 0.0));
    std::vector<double> u;
    for (int s = 0; s < steps; ++s) {
        EXPECT_TRUE(integrator.step(dt, 0.0, NewtonSettings{}).converged);
        u.push_back(analysis.displacement(centre).z());
    }
    Eigen::MatrixXd lhs(steps - 12, 2);
    Eigen::VectorXd rhs(steps - 12);
    for (int n = 11; n < steps - 1; ++n) {
        lhs.row(n - 11) << u[n], u[n - 1];
        rhs(n - 11) = u[n + 1];
    }
    const Eigen::Vector2d pq = lhs.colPivHouseholderQr().solve(rhs);
    return std::sqrt(std::max(-pq(1), 0.0));
}

// alpha = -0.1 damps a mode with omega dt = 10 (a "high" frequency for the step) at the
// analytic spectral radius, while the trapezoidal rule keeps its amplitude (rho = 1).
TEST(PlateVibration, HhtDampsHighFrequencyAtAnalyticSpectralRadius) {
    const double omega_dt = 10.0;
    const double dt = omega_dt / first_omega();
    for (const double alpha : {0.0, -0.1}) {
        auto analysis = plate_in_first_mode();
        NewmarkIntegrator hht = NewmarkIntegrator::hht(*analysis, alpha);
        hht.initialise(Eigen::VectorXd::Zero(analysis->dofs().size()));
        const double measured = measured_radius(*analysis, hht, dt, 40);
        const double analytic = hht_spectral_radius(alpha, omega_dt);
        std::printf("alpha = %+.2f, omega dt = %.0f: spectral radius measured %.5f, analytic "
                    "%.5f (rho_inf = %.5f)\n",
                    alpha, omega_dt, measured, analytic, (1.0 + alpha) / (1.0 - alpha));
        EXPECT_NEAR(measured, analytic, 0.01 * analytic);
    }
}

// Second-order accuracy is kept on the resolved mode: alpha = -0.1 at dt = T/50 gives the
// first frequency within the acceptance bound of 2 % and loses little amplitude per period.
TEST(PlateVibration, HhtKeepsFirstFrequency) {
    auto analysis = plate_in_first_mode();
    NewmarkIntegrator hht = NewmarkIntegrator::hht(*analysis, -0.1);
    hht.initialise(Eigen::VectorXd::Zero(analysis->dofs().size()));
    const double period = 2.0 * kPi / first_omega();
    const double measured = measured_period(*analysis, hht, period / 50.0, 150);
    std::printf("HHT alpha = -0.1, dt = T/50: period %.6f s, Kirchhoff %.6f s, error %+.2f %%\n",
                measured, period, 100.0 * (measured / period - 1.0));
    EXPECT_NEAR(measured, period, 0.02 * period);
}

// Lumped and consistent mass both give the first frequency within 2 % at 8 x 8; refining
// 4 x 4 -> 8 x 8 shows consistent mass converging from above (Rayleigh-Ritz upper bound) and
// lumped mass from below. The step T/60 keeps the trapezoidal period elongation
// ((omega dt)^2 / 12 = 0.09 %) below the differences compared.
TEST(PlateVibration, LumpedAndConsistentMassFirstFrequency) {
    const double period = 2.0 * kPi / first_omega();
    for (const MassMatrix mass : {MassMatrix::lumped, MassMatrix::consistent}) {
        std::vector<double> errors;
        for (const int n : {4, 8}) {
            auto analysis = plate_in_first_mode(n);
            NewmarkIntegrator newmark(*analysis, 0.25, 0.5, 0.0, mass);
            newmark.initialise(Eigen::VectorXd::Zero(analysis->dofs().size()));
            const double measured = measured_period(*analysis, newmark, period / 60.0, 200);
            errors.push_back(period / measured - 1.0); // frequency error
            std::printf(
                "%s mass, %d x %d quarter: f = %.3f Hz, Kirchhoff %.3f Hz, error %+.2f %%\n",
                mass == MassMatrix::lumped ? "lumped" : "consistent", n, n, 1.0 / measured,
                1.0 / period, 100.0 * errors.back());
        }
        EXPECT_LT(std::abs(errors.back()), 0.02);
        if (mass == MassMatrix::consistent) {
            EXPECT_GT(errors[0], errors[1]); // from above
            EXPECT_GT(errors[1], 0.0);
        } else {
            EXPECT_LT(errors[0], errors[1]); // from below
            EXPECT_LT(errors[1], 0.0);
        }
    }
}

} // namespace
} // namespace grainload::fem
