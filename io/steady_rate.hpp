#pragma once
// The steady discharge rate: the slope of a line through the 20-80 % part of a discharge curve.

#include <optional>
#include <span>

namespace grainload::io {

/// Share of the final discharged mass where the steady part of a discharge curve M(t) starts
/// and ends: the start-up transient (the orifice opening, the flow accelerating) lies below
/// 20 % and the run-down (the last material sliding off the slopes, the rate falling to zero)
/// above 80 % of what left by the end. docs/theory/sph.md, "Sinks", says why.
inline constexpr double kSteadyLowerFraction = 0.2;
inline constexpr double kSteadyUpperFraction = 0.8;

/// The slope of a least-squares line M = a + W t through the samples (t_k, M_k) of a
/// cumulative discharge curve whose M_k lies within [lower, upper] times the last sample's M
/// (the mass discharged by the end of the run), with the window it used.
struct SteadyRate {
    double rate = 0.0;  ///< W, mass per time
    double start = 0.0; ///< first and last time in the window
    double end = 0.0;
    int samples = 0;
};

/// std::nullopt when fewer than 3 samples fall in the window (nothing or too little left, or too
/// few output instants to tell a line), or the times in it do not differ.
std::optional<SteadyRate> steady_rate(std::span<const double> time, std::span<const double> mass,
                                      double lower = kSteadyLowerFraction,
                                      double upper = kSteadyUpperFraction);

} // namespace grainload::io
