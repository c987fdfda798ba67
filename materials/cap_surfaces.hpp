#pragma once

#include <functional>
#include <limits>

// Scalar building blocks of the generalized cap model (Sandler-DiMaggio-Baladi), written
// COMPRESSION POSITIVE as in its sources (thesis section 4.6.3; Kojic & Bathe, "Inelastic
// Analysis of Solids and Structures", cap model after Sandler & Rubin). All stresses in Pa.
namespace grainload::materials::cap {

/// Material constants of the cap model, SI (Pa, 1/Pa). See docs/theory/generalized_cap.md.
struct Parameters {
    double k = 0.0;       ///< cohesion-like constant of the envelope [Pa]
    double theta = 0.0;   ///< slope of the envelope in (I1, sqrt(J2)) [-]
    double gamma = 0.0;   ///< amplitude of the exponential term [Pa]
    double beta = 0.0;    ///< B1, decay of the exponential term [1/Pa]
    double D = 0.0;       ///< hardening rate [1/Pa]
    double W = 0.0;       ///< maximum plastic volumetric compaction [-]
    double X0 = 0.0;      ///< initial cap position on the I1 axis [Pa]
    double R = 0.0;       ///< ellipse aspect ratio (X - L) / B; 0 gives a flat cap [-]
    double tension = 0.0; ///< tension cutoff T >= 0: I1 >= -T [Pa]
};

/// Failure envelope F(I1) = k + theta I1 - gamma exp(-B1 I1), thesis (4.6.3.15): the failure
/// surface is sqrt(J2) = F(I1).
double envelope(const Parameters& p, double i1);
double envelope_slope(const Parameters& p, double i1);
double envelope_curvature(const Parameters& p, double i1);

/// Cap position X(L) = L + R F(L), thesis (4.6.3.10) with B = F(L) (4.6.3.35).
double cap_position(const Parameters& p, double l);
double cap_position_slope(const Parameters& p, double l);

/// exp(-D (X - X0)): the hardening law (4.6.3.4) reads eps_v^p = W (1 - hardening_decay(X)).
/// Volumetric plastic strain is always formed as a difference W (decay_n - decay(X)), so that a
/// locked state (decay -> 0) needs no logarithm.
double hardening_decay(const Parameters& p, double x);

/// Lowest admissible I1: the tension cutoff -T or the apex of the envelope (F = 0), whichever
/// is larger; the cap centre L never goes below it.
double minimum_pressure(const Parameters& p);

/// L such that X(L) = x, never below minimum_pressure; Newton on the monotone X(L), (4.6.3.19).
double cap_center_for(const Parameters& p, double x, double guess);

/// Result of a bracketed Newton solve.
struct Root {
    double value = 0.0;
    double slope = 0.0; ///< g'(value), reused by the consistent tangent
};

/// Solve g(u) = 0 for u in [lo, hi] where g(lo) and g(hi) differ in sign (or are zero).
/// `fn` returns g and g'. Newton steps that leave the bracket are replaced by bisection, so
/// the solve cannot diverge; it stops at |step| <= tolerance + relative |u|. Newton starts at
/// `guess` when it lies inside the bracket, else at the end with the smaller |g|.
Root solve_bracketed(const std::function<void(double, double&, double&)>& fn, double lo, double hi,
                     double tolerance, double relative = 0.0,
                     double guess = std::numeric_limits<double>::quiet_NaN());

} // namespace grainload::materials::cap
