#include "materials/cap_surfaces.hpp"

#include <algorithm>
#include <cmath>

namespace grainload::materials::cap {

double envelope(const Parameters& p, double i1) {
    return p.k + p.theta * i1 - p.gamma * std::exp(-p.beta * i1);
}

double envelope_slope(const Parameters& p, double i1) {
    return p.theta + p.gamma * p.beta * std::exp(-p.beta * i1);
}

double envelope_curvature(const Parameters& p, double i1) {
    return -p.gamma * p.beta * p.beta * std::exp(-p.beta * i1);
}

double cap_position(const Parameters& p, double l) {
    return l + p.R * envelope(p, l);
}

double cap_position_slope(const Parameters& p, double l) {
    return 1.0 + p.R * envelope_slope(p, l);
}

double hardening_decay(const Parameters& p, double x) {
    return std::exp(-p.D * (x - p.X0));
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

double cap_center_for(const Parameters& p, double x, double guess) {
    const double floor = minimum_pressure(p);
    if (cap_position(p, floor) >= x) {
        return floor;
    }
    // X'(L) >= 1 gives a bracket of width |X(guess) - x| on the side where x lies.
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

Root solve_bracketed(const std::function<void(double, double&, double&)>& fn, double lo, double hi,
                     double tolerance, double relative, double guess) {
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
