#pragma once
// The generalized cap's surfaces and hardening law as scalar functions.

#include <algorithm>
#include <cmath>
#include <limits>

// Scalar building blocks of the generalized cap model (Sandler-DiMaggio-Baladi), written
// COMPRESSION POSITIVE as in its sources (thesis section 4.6.3; Kojic & Bathe, "Inelastic
// Analysis of Solids and Structures", cap model after Sandler & Rubin; LS-DYNA
// *MAT_GEOLOGIC_CAP_MODEL, MAT_025). All stresses in Pa.
namespace grainload::materials::cap {

/// How X0 and the cap centre are read (docs/theory/generalized_cap.md, "Initial cap").
enum class Semantics {
    /// LS-DYNA MAT_025: X0 is the initial cap intercept, kappa0 solves X(kappa0) = X0 (it may be
    /// negative), the cap centre is L = max(kappa, 0) and eps_v^p starts at 0.
    mat025,
    /// grainload's first cap semantics: the centre never goes below the lowest admissible I1, so an
    /// X0 below X(I1_min) is lifted to it and eps_v^p starts at the law's value there.
    lifted_x0,
};

/// Material constants of the cap model, SI (Pa, 1/Pa). See docs/theory/generalized_cap.md.
struct Parameters {
    double k = 0.0;       ///< cohesion-like constant of the envelope (MAT_025 ALPHA) [Pa]
    double theta = 0.0;   ///< slope of the envelope in (I1, sqrt(J2)) [-]
    double gamma = 0.0;   ///< amplitude of the exponential term [Pa]
    double beta = 0.0;    ///< B1, decay of the exponential term [1/Pa]
    double D = 0.0;       ///< hardening rate [1/Pa]
    double W = 0.0;       ///< maximum plastic volumetric compaction [-]
    double X0 = 0.0;      ///< initial cap intercept with the I1 axis [Pa]
    double R = 0.0;       ///< ellipse aspect ratio (X - L) / B; 0 gives a flat cap [-]
    double tension = 0.0; ///< tension cutoff T >= 0: I1 >= -T (MAT_025 TOFF = -T) [Pa]
    Semantics semantics = Semantics::mat025;
};

/// Failure envelope F(I1) = k + theta I1 - gamma exp(-B1 I1), thesis (4.6.3.15): the failure
/// surface is sqrt(J2) = F(I1).
/// Inline, as the other small pieces below: the returns evaluate them at every iteration.
inline double envelope(const Parameters& p, double i1) {
    // k - gamma exp(-B1 I1) written as (k - gamma) - gamma expm1(-B1 I1): with the usual
    // k = gamma (the apex at the origin) the plain form cancels to round-off of k for small
    // I1 (|F| below about 1e-16 k is lost entirely), this one keeps F's relative accuracy.
    return (p.k - p.gamma) + p.theta * i1 - p.gamma * std::expm1(-p.beta * i1);
}

inline double envelope_slope(const Parameters& p, double i1) {
    return p.theta + p.gamma * p.beta * std::exp(-p.beta * i1);
}

inline double envelope_curvature(const Parameters& p, double i1) {
    return -p.gamma * p.beta * p.beta * std::exp(-p.beta * i1);
}

/// Lowest admissible I1: the tension cutoff -T or the apex of the envelope (F = 0), whichever
/// is larger.
double minimum_pressure(const Parameters& p);

// The hardening state is the parameter kappa of MAT_025 (the thesis' L when the centre is not
// clamped): the cap meets the I1 axis at X(kappa), its centre is L(kappa) and its half-height
// B(kappa) = (X - L) / R.

/// Cap position X(kappa) = kappa + R F(kappa), thesis (4.6.3.10) with B = F(L) (4.6.3.35).
double cap_position(const Parameters& p, double kappa);
double cap_position_slope(const Parameters& p, double kappa);

/// True where the centre is held at L = 0 while kappa < 0 (MAT_025 with R > 0). Inline with the
/// two below: every Newton step of the cap asks.
inline bool centre_clamped(const Parameters& p, double kappa) {
    return p.semantics == Semantics::mat025 && p.R > 0.0 && kappa < 0.0;
}
/// Cap centre L(kappa): max(kappa, 0) for MAT_025 with R > 0, kappa otherwise.
inline double cap_center(const Parameters& p, double kappa) {
    return centre_clamped(p, kappa) ? 0.0 : kappa;
}
inline double cap_center_slope(const Parameters& p, double kappa) {
    return centre_clamped(p, kappa) ? 0.0 : 1.0;
}
/// Half-height B(kappa) = (X - L) / R of the ellipse: F(kappa) where L = kappa.
double half_height(const Parameters& p, double kappa);
double half_height_slope(const Parameters& p, double kappa);

/// exp(-D (X - X0)): the hardening law (4.6.3.4) reads eps_v^p = W (1 - hardening_decay(X)).
/// Volumetric plastic strain is always formed as a difference W (decay_n - decay(X)), so that a
/// locked state (decay -> 0) needs no logarithm.
inline double hardening_decay(const Parameters& p, double x) {
    return std::exp(-p.D * (x - p.X0));
}

/// kappa such that X(kappa) = x, searched from `guess` but not below `floor` (the caller knows
/// the root lies above it); Newton on the monotone X(kappa), (4.6.3.19).
double hardening_for(const Parameters& p, double x, double guess, double floor);

/// Smallest kappa the cap may contract to: I1_min when the centre is kappa; for MAT_025 with
/// R > 0 the kappa where X = max(0, apex), below which the ellipse (X - L >= 0) would vanish.
double lowest_hardening(const Parameters& p, double i1_min);

/// Smallest X0 the semantics accept: the cap of the lowest hardening state.
double lowest_cap_position(const Parameters& p, double i1_min);

/// The corner where the envelope meets the cap's top, or its flat continuation at height B to
/// the left of a clamped centre (docs "Initial cap"): I1 = kappa where L = kappa; for a clamped
/// centre the c with F(c) = B(kappa), not below i1_min (there the top meets the cutoff).
struct CornerPoint {
    double i1 = 0.0;
    double slope = 1.0; ///< dc/dkappa, 0 where the corner sits on the cutoff
};
CornerPoint corner_point(const Parameters& p, double kappa, double i1_min);
/// kappa whose corner lies at i1 (the inverse of corner_point above i1_min), not below
/// kappa_min.
double hardening_for_corner(const Parameters& p, double i1, double kappa_min);

/// Result of a bracketed Newton solve.
struct Root {
    double value = 0.0;
    double slope = 0.0; ///< g'(value), reused by the consistent tangent
};

/// Solve g(u) = 0 for u in [lo, hi] where g(lo) and g(hi) differ in sign (or are zero).
/// `fn` returns g and g'. Newton steps that leave the bracket are replaced by bisection, so
/// the solve cannot diverge; it stops at |step| <= tolerance + relative |u|. Newton starts at
/// `guess` when it lies inside the bracket, else at the end with the smaller |g|.
/// A template (in the header) so that each caller's residual is inlined into the iteration.
template <class Fn>
Root solve_bracketed(const Fn& fn, double lo, double hi, double tolerance, double relative = 0.0,
                     double guess = std::numeric_limits<double>::quiet_NaN()) {
    double g_lo = 0.0;
    double g_hi = 0.0;
    double slope_lo = 0.0;
    double slope_hi = 0.0;
    fn(lo, g_lo, slope_lo);
    if (g_lo == 0.0) {
        return {lo, slope_lo};
    }
    fn(hi, g_hi, slope_hi);
    if (g_hi == 0.0) {
        return {hi, slope_hi};
    }
    const bool rising = g_lo < 0.0;
    const bool lo_closer = std::abs(g_lo) < std::abs(g_hi);
    double u = lo_closer ? lo : hi;
    double g = lo_closer ? g_lo : g_hi;
    double slope = lo_closer ? slope_lo : slope_hi;
    if (guess > std::min(lo, hi) && guess < std::max(lo, hi)) {
        u = guess;
        fn(u, g, slope);
    }
    for (int iteration = 0; iteration < 200 && g != 0.0; ++iteration) {
        ((g < 0.0) == rising ? lo : hi) = u;
        double next = u - g / slope;
        const bool inside = next > std::min(lo, hi) && next < std::max(lo, hi);
        if (!(slope != 0.0) || !inside) {
            next = 0.5 * (lo + hi);
        }
        const double step = next - u;
        u = next;
        fn(u, g, slope);
        const double limit = tolerance + relative * std::abs(u);
        if (std::abs(step) <= limit || std::abs(hi - lo) <= limit) {
            break;
        }
    }
    return {u, slope};
}

} // namespace grainload::materials::cap
