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

/// The mass the scene's sources create up to `end_time` (mass rate over the part of their
/// active span before it; a span that ends at a phase counts to `end_time`).
double source_mass(const sph::SphModel& sph, double end_time) {
    double mass = 0.0;
    for (const auto& source : sph.sources().sources()) {
        const double start = std::min(source.start, end_time);
        mass += source.mass_rate * std::max(0.0, std::min(source.end, end_time) - start);
    }
    return mass;
}

/// The power iteration of shell_mode_compliance (window_limits.hpp) from a pressure that
/// varies from node to node (a golden-ratio sequence between 0.5 and 1.5), so that every mode
/// is in the start on a symmetric mesh too: f_i = w_i (w_i . u_i) / |w_i|, u <- C f,
/// mu = (f . C f) / (f . u), the Rayleigh quotient of the symmetric N^1/2 C N^1/2 with
/// N_i = w_i w_i^T / |w_i| (Golub & Van Loan, Matrix Computations, 4th ed., sec. 8.2.1).
double largest_eigenvalue(fem::ShellAnalysis& analysis, const Eigen::VectorXd& area_vectors,
                          const std::vector<Index>& nodes) {
    const auto inverse = analysis.tangent_inverse();
    Eigen::VectorXd f = Eigen::VectorXd::Zero(area_vectors.size());
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        const double golden = 0.6180339887498949 * static_cast<double>(k);
        const Index at = 6 * nodes[k];
        f.segment<3>(at) = (0.5 + (golden - std::floor(golden))) * area_vectors.segment<3>(at);
    }
    Eigen::VectorXd u = inverse(f);
    double mu = 0.0;
    // A quotient that moves by less than 1e-4 between passes has settled; 200 passes (one
    // back-substitution each) bound the cost where the two largest modes lie close together.
    // The quotient grows towards the largest eigenvalue, so stopping early errs low by what
    // the last passes still added.
    constexpr int kPasses = 200;
    constexpr double kSettled = 1e-4;
    for (int pass = 0; pass < kPasses; ++pass) {
        f.setZero();
        for (const Index node : nodes) {
            const auto w = area_vectors.segment<3>(6 * node);
            f.segment<3>(6 * node) = w * (w.dot(u.segment<3>(6 * node)) / w.norm());
        }
        const double norm = f.dot(u);
        if (!(norm > 0.0)) {
            return mu;
        }
        const Eigen::VectorXd next = inverse(f);
        const double quotient = f.dot(next) / norm;
        const bool settled = std::abs(quotient - mu) <= kSettled * quotient;
        mu = quotient;
        u = next / next.norm();
        if (settled) {
            break;
        }
    }
    return mu;
}

} // namespace

Eigen::VectorXd coupled_area_vectors(const fem::ShellMesh& mesh,
                                     const std::vector<CoupledPart>& parts) {
    Eigen::VectorXd area_vectors = Eigen::VectorXd::Zero(6 * mesh.node_count());
    for (const CoupledPart& part : parts) {
        for (const Index e : part.elements) {
            const fem::ShellElement& element = mesh.element(e);
            const double a = fem::element_area(mesh, element);
            // The sand pushes against its side's normal (both sides: either side's push, the
            // same compliance for a linear shell).
            const Vec3 push = -normal_sign(part.side) * fem::element_normal(mesh, element);
            const int corners = element.is_triangle() ? 3 : 4;
            for (int k = 0; k < corners; ++k) {
                const Index node = element.nodes[static_cast<std::size_t>(k)];
                area_vectors.segment<3>(6 * node) += (a / corners) * push;
            }
        }
    }
    return area_vectors;
}

double shell_mode_compliance(fem::ShellAnalysis& analysis, const std::vector<CoupledPart>& parts) {
    const fem::ShellMesh& mesh = analysis.mesh();
    const Eigen::VectorXd area_vectors = coupled_area_vectors(mesh, parts);
    // The coupled nodes; one whose pushes cancel (a fold met from both sides, or elements of no
    // area) takes no pressure and is left out, rather than divided by its zero norm below.
    std::vector<Index> nodes;
    for (Index n = 0; n < mesh.node_count(); ++n) {
        if (area_vectors.segment<3>(6 * n).norm() > 0.0) {
            nodes.push_back(n);
        }
    }
    return largest_eigenvalue(analysis, area_vectors, nodes);
}

WindowLimits estimate_window_limits(const sph::SphModel& sph, fem::ShellModel& fem,
                                    const std::vector<CoupledPart>& parts, double omega,
                                    double end_time, double added_mass) {
    WindowLimits limits;
    const sph::SphSolver& solver = *sph.solver();
    const sph::ParticleSet& p = solver.particles();
    double mass = 0.0;
    for (Index i = 0; i < p.size(); ++i) {
        if (p.is_wall(i)) {
            continue;
        }
        const auto& material = *solver.materials()[static_cast<std::size_t>(p.material_id[i])];
        limits.impedance =
            std::max(limits.impedance, material.density() * material.elastic().p_wave_speed());
        mass += p.mass[i];
    }
    // A source fills the silo later: its mass stands behind the walls by the time it has run.
    mass += source_mass(sph, end_time);
    fem::ShellAnalysis& analysis = fem.analysis();
    const fem::ShellMesh& mesh = analysis.mesh();
    double area = 0.0;
    limits.shell_mass = std::numeric_limits<double>::infinity();
    for (const CoupledPart& part : parts) {
        const double density =
            analysis.parts()[static_cast<std::size_t>(mesh.element(part.elements.front()).part)]
                .material->density();
        for (const Index e : part.elements) {
            const fem::ShellElement& element = mesh.element(e);
            const double a = fem::element_area(mesh, element);
            area += a;
            limits.shell_mass = std::min(limits.shell_mass, density * element.thickness);
        }
    }
    const double impedance = std::max(limits.impedance, 1e-300);
    if (fem.dynamic()) {
        limits.dynamic_max = tolerated_gain(omega) * limits.shell_mass / (3.0 * impedance);
        return limits;
    }
    limits.sand_mass = area > 0.0 ? mass / area : 0.0;
    limits.compliance = shell_mode_compliance(analysis, parts);
    // g / (1 + beta g) = T at g = T / (1 - beta T); none when beta T >= 1 (window_limits.hpp).
    const double tolerated = tolerated_gain(omega);
    limits.static_min = std::sqrt(limits.sand_mass * limits.compliance *
                                  std::max(0.0, 1.0 - added_mass * tolerated) / tolerated);
    return limits;
}

double added_mass_lag(const WindowLimits& limits, double window, double added_mass) {
    if (!(added_mass > 0.0) || !(window > 0.0)) {
        return 0.0;
    }
    return window + added_mass * limits.sand_mass * limits.compliance / window;
}

std::optional<std::string> added_mass_lag_warning(const WindowLimits& limits, double window,
                                                  double added_mass, double end_time) {
    // A change of the load at the run's start is followed to e^-10 by its end when the lag is a
    // tenth of the run. The strip (docs/validation/coupling.md, "The added mass"), 0.12 s over
    // 1 s, ended within 0.01 % of its deflection without the springs; the 1 mm polycarbonate
    // silo lagged by 0.8-13 s over 2.7 s.
    constexpr double kShareOfTheRun = 0.1;
    const double lag = added_mass_lag(limits, window, added_mass);
    if (!(lag > kShareOfTheRun * end_time)) {
        return std::nullopt;
    }
    const double best = std::sqrt(added_mass * limits.sand_mass * limits.compliance);
    std::ostringstream why;
    why << "with added_mass = " << added_mass << " the static shell follows a change of the "
        << "sand's load within about " << lag << " s (window + added_mass m_s C / window), "
        << "more than a tenth of the run (" << end_time << " s): the wall's deflection, stresses "
        << "and the pressures that depend on them lag the load; the lag is shortest, " << 2.0 * best
        << " s, at a window of " << best << " s, and shorter with a smaller "
        << "added_mass (at least 1 / (2 / relaxation - 1) for stability)";
    return why.str();
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
            << "); use a window of at least that, a smaller relaxation, the sand's inertia on "
               "the shell (added_mass = 4: it ran a strip and a silo wall at 0.2 to 1 times "
               "this limit, docs/validation/coupling.md), or iterate each window "
               "(max_iterations > 1)";
        return why.str();
    }
    return std::nullopt;
}

namespace {

/// `x` to two significant digits, rounded towards zero (down) or away from it (up): a setting
/// printed for the user stays on the safe side of the value it stands for.
double two_digits(double x, bool up) {
    const double unit = std::pow(10.0, std::floor(std::log10(x)) - 1.0);
    return (up ? std::ceil(x / unit) : std::floor(x / unit)) * unit;
}

} // namespace

std::optional<std::string> window_warning(const WindowLimits& limits, double window, bool dynamic,
                                          double omega) {
    // Static windows of 1.02-1.20 times static_min oscillated and 1.08 times it ran stable
    // (docs/validation/coupling.md): the estimate is the boundary to about 20 %, so a window
    // within 25 % of it is warned about.
    constexpr double kStaticMargin = 1.25;
    const bool beyond =
        dynamic ? window > limits.dynamic_max : window < kStaticMargin * limits.static_min;
    if (!beyond) {
        return std::nullopt;
    }
    const double limit = dynamic ? limits.dynamic_max : limits.static_min;
    // The loop gain the relaxation that clears the window tolerates (estimate_window_limits):
    // the dynamic limit grows as T = 2 / omega - 1; the static one squared is m_s C / T - beta
    // m_s C, which the margin puts at (window / 1.25)^2.
    const double gain = tolerated_gain(omega);
    double wanted = gain * window / limits.dynamic_max;
    if (!dynamic) {
        const double mc = limits.sand_mass * limits.compliance;
        const double beta_mc = (mc - limit * limit * gain) / gain;
        const double margin = window / kStaticMargin;
        wanted = mc / (margin * margin + beta_mc);
    }
    std::ostringstream why;
    why.precision(3);
    why << "the coupling window " << window << " s is " << window / limit << " times the "
        << (dynamic ? "longest" : "shortest")
        << " stable staggered window the coupling estimates for this "
        << (dynamic ? "dynamic" : "static") << " shell (" << limit << " s at relaxation " << omega
        << "), "
        << (dynamic ? "beyond it, where runs have gone either way"
                    : "within the estimate's 25 % uncertainty: windows up to 1.2 times it have "
                      "oscillated")
        << ". The run goes ahead, and should the exchange oscillate the interface energy "
        << "watchdog stops it with exit 3; to clear it set window = \""
        << two_digits(dynamic ? limit : kStaticMargin * limit, !dynamic) << " s\" or "
        << (dynamic ? "shorter" : "longer")
        << ", relaxation = " << two_digits(2.0 / (1.0 + wanted), false) << " or less, "
        << (dynamic ? "or " : "added_mass = 4 or ") << "max_iterations = 2";
    return why.str();
}

} // namespace grainload::coupling
