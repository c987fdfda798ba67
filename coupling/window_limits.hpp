#pragma once

#include "coupling/coupled_model.hpp"

#include <limits>
#include <string>

namespace grainload::coupling {

/// The windows the staggered exchange can take (docs/theory/coupling.md, "Stability of the
/// exchange"): with relaxation omega it is stable for a loop gain g < 2 / omega - 1.
///  - Dynamic shell: g = rho_s c_s dt / m_eff, the sand's impedance over the window against the
///    shell's effective mass; m_eff = m_w / 3 (the areal mass rho_w t of the lightest coupled
///    part times the modal mass fraction of a plate's first mode, about 1/4 to 1/3; the 1/3 is
///    calibrated on the sand drop: stable at 0.94 of the limit, 9 % energy error at 3.7 times
///    it, docs/validation/coupling.md). A window longer than `dynamic_max` oscillates.
///  - Static shell: g = m_s C / dt^2, the inertia of the sand behind the wall (areal mass m_s =
///    rho_s V_sand / A_coupled) against the shell's compliance C (its largest displacement
///    towards the outside under a unit pressure from the sand side). A window shorter than
///    `static_min` oscillates.
struct WindowLimits {
    double dynamic_max = std::numeric_limits<double>::infinity(); ///< [s]
    double static_min = 0.0;                                      ///< [s]
    double impedance = 0.0;  ///< largest rho c of the sand [kg/(m^2 s)]
    double shell_mass = 0.0; ///< areal mass of the lightest coupled part [kg/m^2]
    double sand_mass = 0.0;  ///< the sand's areal mass behind the coupled walls [kg/m^2]
    double compliance = 0.0; ///< static: largest outward displacement per pascal [m/Pa]
};

/// Estimates the limits for the staggered scheme with relaxation `omega`. For a static shell it
/// solves once with the shell's current tangent (the state is left unchanged).
WindowLimits estimate_window_limits(const sph::SphModel& sph, fem::ShellModel& fem,
                                    const std::vector<CoupledPart>& parts, double omega);

/// A refusal when the staggered window is beyond twice its limit (the estimate is good to a
/// factor of about two), naming the limit and what works instead; std::nullopt otherwise.
std::optional<std::string> window_refusal(const WindowLimits& limits, double window, bool dynamic,
                                          double omega);

} // namespace grainload::coupling
