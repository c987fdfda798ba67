#include "materials/cap_surfaces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grainload::materials::cap {

double cap_position(const Parameters& p, double kappa) {
    return kappa + p.R * envelope(p, kappa);
}

double cap_position_slope(const Parameters& p, double kappa) {
    return 1.0 + p.R * envelope_slope(p, kappa);
}

double half_height(const Parameters& p, double kappa) {
    // (X - L) / R with L = 0: kappa / R + F(kappa), 0 at the lowest cap (X = 0) up to
    // round-off, which must not turn the deviator round; with L = kappa: F(kappa) exactly.
    return centre_clamped(p, kappa) ? std::max(0.0, kappa / p.R + envelope(p, kappa))
                                    : envelope(p, kappa);
}

double half_height_slope(const Parameters& p, double kappa) {
    return centre_clamped(p, kappa) ? 1.0 / p.R + envelope_slope(p, kappa)
                                    : envelope_slope(p, kappa);
}

double minimum_pressure(const Parameters& p) {
    const double cutoff = -p.tension;
    if (envelope(p, cutoff) >= 0.0) {
        return cutoff;
    }
    // F is increasing; expand until F > 0 (the constructor guarantees F(+inf) > 0), then
    // solve F = 0 for the apex.
    double hi = std::max(0.0, cutoff) + std::max(p.k, 1.0);
    while (envelope(p, hi) <= 0.0) {
        hi = 2.0 * hi;
    }
    const auto fn = [&p](double u, double& g, double& dg) {
        g = envelope(p, u);
        dg = envelope_slope(p, u);
    };
    return solve_bracketed(fn, cutoff, hi, 1e-15 * (std::abs(hi) + std::abs(cutoff))).value;
}

double hardening_for(const Parameters& p, double x, double guess, double floor) {
    // X'(kappa) >= 1 gives a bracket of width |X(guess) - x| on the side where x lies.
    const double start = std::max(guess, floor);
    const double gap = x - cap_position(p, start);
    const double lo = gap > 0.0 ? start : std::max(floor, start + gap);
    const double hi = gap > 0.0 ? start + gap : start;
    const auto fn = [&p, x](double u, double& g, double& dg) {
        g = cap_position(p, u) - x;
        dg = cap_position_slope(p, u);
    };
    const double scale = std::abs(lo) + std::abs(hi) + std::abs(x) + p.k;
    return solve_bracketed(fn, lo, hi, 1e-15 * scale).value;
}

namespace {

/// MAT_025 with R > 0 and F(0) >= 0: the centre is clamped at 0 for kappa < 0 and the cap may
/// contract until X = 0 (kappa < 0). Otherwise the centre is kappa >= I1_min throughout.
bool clamping_possible(const Parameters& p) {
    return p.semantics == Semantics::mat025 && p.R > 0.0 && envelope(p, 0.0) >= 0.0;
}

} // namespace

double lowest_hardening(const Parameters& p, double i1_min) {
    return clamping_possible(p) ? hardening_for(p, 0.0, 0.0, -std::numeric_limits<double>::max())
                                : i1_min;
}

double lowest_cap_position(const Parameters& p, double i1_min) {
    return clamping_possible(p) ? 0.0 : cap_position(p, i1_min);
}

CornerPoint corner_point(const Parameters& p, double kappa, double i1_min) {
    if (!centre_clamped(p, kappa)) {
        return {kappa, 1.0};
    }
    const double b = half_height(p, kappa);
    if (envelope(p, i1_min) >= b) {
        return {i1_min, 0.0}; // the flat top meets the cutoff before the envelope
    }
    // F(i1_min) < B < F(kappa): F(c) = B has its root in [i1_min, kappa].
    const auto fn = [&p, b](double u, double& g, double& dg) {
        g = envelope(p, u) - b;
        dg = envelope_slope(p, u);
    };
    const double scale = std::abs(i1_min) + std::abs(kappa) + p.k;
    const Root root = solve_bracketed(fn, i1_min, kappa, 1e-15 * scale);
    return {root.value, half_height_slope(p, kappa) / root.slope};
}

double hardening_for_corner(const Parameters& p, double i1, double kappa_min) {
    if (!clamping_possible(p) || i1 >= 0.0) {
        return std::max(i1, kappa_min);
    }
    // B(kappa) = F(i1) on [kappa_min, 0]: B(kappa_min) = X(kappa_min) / R = 0 <= F(i1) and
    // B(0) = F(0) > F(i1); B is increasing.
    const double target = envelope(p, i1);
    if (half_height(p, kappa_min) >= target) {
        return kappa_min;
    }
    const auto fn = [&p, target](double u, double& g, double& dg) {
        g = half_height(p, u) - target;
        dg = half_height_slope(p, u);
    };
    const double scale = std::abs(kappa_min) + std::abs(i1) + p.k;
    return solve_bracketed(fn, kappa_min, 0.0, 1e-15 * scale).value;
}

} // namespace grainload::materials::cap
