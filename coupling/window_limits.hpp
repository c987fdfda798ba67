#pragma once
// The coupling windows the staggered exchange can take without oscillating.

#include "coupling/coupled_part.hpp"
#include "fem/shell_model.hpp"
#include "sph/sph_model.hpp"

#include <Eigen/Core>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace grainload::coupling {

/// The windows the staggered exchange can take (docs/theory/coupling.md, "Stability of the
/// exchange"): with relaxation omega it is stable for a loop gain g < 2 / omega - 1.
///  - Dynamic shell: g = rho_s c_s dt / m_eff, the sand's impedance over the window against the
///    shell's effective mass; m_eff = m_w / 3 (the areal mass rho_w t of the lightest coupled
///    part times the modal mass fraction of a plate's first mode, about 1/4 to 1/3; the 1/3 is
///    calibrated on the sand drop: stable at 0.94 of the limit, 9 % energy error at 3.7 times
///    it, docs/validation/coupling.md). A window longer than `dynamic_max` oscillates.
///  - Static shell: g = m_s C / dt^2, the inertia of the sand behind the wall (areal mass m_s =
///    M_sand / A_coupled, the sources' mass to come included) against the shell's compliance C
///    in its most compliant mode (shell_mode_compliance). A window shorter than `static_min`
///    oscillates. With the added mass (coupling/added_mass.hpp, factor beta) the lagged load
///    meets the compliance C / (1 + beta g) instead, a loop gain g / (1 + beta g) < 1 / beta:
///    stable for every window once beta (2 / omega - 1) >= 1.
struct WindowLimits {
    double dynamic_max = std::numeric_limits<double>::infinity(); ///< [s]
    double static_min = 0.0;                                      ///< [s]
    double impedance = 0.0;  ///< largest rho c of the sand [kg/(m^2 s)]
    double shell_mass = 0.0; ///< areal mass of the lightest coupled part [kg/m^2]
    double sand_mass = 0.0;  ///< the sand's areal mass behind the coupled walls [kg/m^2]
    double compliance = 0.0; ///< static: shell_mode_compliance [m/Pa]
};

/// The shell's compliance to the sand's pressure on `parts` in its most compliant mode [m/Pa]:
/// the largest eigenvalue mu of C W, C the current tangent's inverse and W the coupled nodes'
/// area vectors w_i (the sum of a / corners times the outward normal of the elements at node
/// i: a pressure p_i there is the force p_i w_i, and the wall's outward displacement there is
/// u_i . w_i / |w_i|), by power iteration with one factorisation. The staggered exchange's
/// loop gain in the worst mode is m_s mu / dt^2, and a uniform pressure need not excite that
/// mode: an open cylinder ovalises (circumferential wave number n = 2, an inextensional mode
/// held by ring bending alone, mu = R^4 / (D (n^2 - 1)^2); Timoshenko & Gere, Theory of Elastic
/// Stability, sec. 7.4) orders of magnitude more easily than it widens under a uniform
/// pressure (R^2 / (E t)).
double shell_mode_compliance(fem::ShellAnalysis& analysis, const std::vector<CoupledPart>& parts);

/// The coupled nodes' area vectors, 6 entries per node (translations; 0 elsewhere): the sum
/// of a / corners times the outward normal (against the sand's side) of the coupled elements
/// at each node.
Eigen::VectorXd coupled_area_vectors(const fem::ShellMesh& mesh,
                                     const std::vector<CoupledPart>& parts);

/// Estimates the limits for the staggered scheme with relaxation `omega` and added-mass factor
/// `added_mass`; the sand's areal mass counts the mass the sources create up to `end_time`.
/// For a static shell it solves once with the shell's current tangent (the state is left
/// unchanged).
WindowLimits estimate_window_limits(const sph::SphModel& sph, fem::ShellModel& fem,
                                    const std::vector<CoupledPart>& parts, double omega,
                                    double end_time, double added_mass = 0.0);

/// How long a static shell with the added mass (factor `added_mass`) takes to follow a change
/// of the load [s]: each window closes 1 / (1 + beta g) of the gap to its equilibrium, g =
/// m_s C / dt^2, so the gap falls by e over tau = dt (1 + beta g) = dt + beta m_s C / dt (the
/// springs act as a damper of beta m_s / dt per unit area, stiffer for shorter windows).
/// Shortest, 2 sqrt(beta m_s C), at dt = sqrt(beta m_s C). 0 without the added mass.
double added_mass_lag(const WindowLimits& limits, double window, double added_mass);

/// A warning when that lag exceeds a tenth of the run (`end_time`): the wall's figures then
/// follow the load late (docs/theory/coupling.md, "Added mass"); std::nullopt otherwise.
std::optional<std::string> added_mass_lag_warning(const WindowLimits& limits, double window,
                                                  double added_mass, double end_time);

/// A refusal when the staggered window is beyond twice its limit (the estimate is good to a
/// factor of about two), naming the limit and what works instead; std::nullopt otherwise.
std::optional<std::string> window_refusal(const WindowLimits& limits, double window, bool dynamic,
                                          double omega);

/// A warning when the staggered window is beyond its estimated limit (static: within 25 % of it)
/// but within the factor two that window_refusal allows (runs there went either way,
/// docs/validation/coupling.md); std::nullopt otherwise.
std::optional<std::string> window_warning(const WindowLimits& limits, double window, bool dynamic,
                                          double omega);

} // namespace grainload::coupling
