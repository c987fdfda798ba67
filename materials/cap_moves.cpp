#include "materials/cap_moves.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grainload::materials::cap {

StateTerms state_terms(const Parameters& p, const Hardening& s) {
    return {hardening_decay(p, s.x), envelope(p, s.kappa)};
}

CapMoves::CapMoves(const Parameters& p, const Hardening& s, const StateTerms& terms)
    : p_(p), s_(s), decay_n_(terms.decay), shifted_(p.gamma * std::exp(-p.beta * s.kappa)),
      curved_(p.beta * shifted_), envelope_n_(terms.envelope),
      fast_(decay_n_ >= std::numeric_limits<double>::min() && std::isfinite(curved_)) {}

double CapMoves::start_rate() const {
    // operator()(0.0): m = expm1(-0) = -0, so dX = 0, the decay is decay_n and F' = theta + the
    // curvature term; the same products in the same order.
    return fast_ ? p_.W * p_.D * decay_n_ * (1.0 + p_.R * (p_.theta + curved_)) : direct(0.0).rate;
}

CapMove CapMoves::direct(double dk) const {
    // F(k_n + dk) - F(k_n) = theta dk - gamma (exp(-B1 (k_n + dk)) - exp(-B1 k_n)); expm1 keeps
    // small moves exact, the plain difference avoids inf * 0 for large contractions.
    const double arg = -p_.beta * dk;
    const double exp_change = arg < 1.0
                                  ? shifted_ * std::expm1(arg)
                                  : p_.gamma * std::exp(-p_.beta * (s_.kappa + dk)) - shifted_;
    CapMove c;
    c.dx = dk + p_.R * (p_.theta * dk - exp_change);
    // exp(-D (X_n + dX - X0)) in one exponent: finite even when decay_n has underflowed.
    const double decay = std::exp(-p_.D * (s_.x + c.dx - p_.X0));
    c.dv = decay_n_ > 0.0 ? -p_.W * decay_n_ * std::expm1(-p_.D * c.dx) : -p_.W * decay;
    c.rate = p_.W * p_.D * decay * cap_position_slope(p_, s_.kappa + dk);
    c.b = half_height(p_, s_.kappa + dk);
    c.b_slope = half_height_slope(p_, s_.kappa + dk);
    return c;
}

Change corner_change(const Model& m, const Hardening& s, double corner_n, double dk) {
    const double kappa = s.kappa + dk;
    if (!centre_clamped(m.p, s.kappa) && !centre_clamped(m.p, kappa)) {
        return {dk, 1.0};
    }
    const CornerPoint c = corner_point(m.p, kappa, m.i1_min);
    return {c.i1 - corner_n, c.slope};
}

Contraction contract_cap(const Model& m, const Hardening& s, double dv, double floor) {
    const Parameters& p = m.p;
    const double decay_n = hardening_decay(p, s.x);
    const double decay = decay_n - dv / p.W;
    if (!(decay > 0.0)) {
        return {s, 0.0, false}; // locked (decay_n == 0) and no flow: the cap stays where it is
    }
    const double x = p.X0 - std::log(decay) / p.D;
    const double x_min = cap_position(p, floor);
    if (x <= x_min) {
        return {{x_min, floor}, p.W * (decay_n - hardening_decay(p, x_min)), true};
    }
    return {{x, hardening_for(p, x, s.kappa, m.kappa_min)}, dv, false};
}

Shift shift_to(const Model& m, double i1_trial, const Hardening& s, Target target) {
    const bool corner = target == Target::corner;
    const double p_n = corner ? corner_point(m.p, s.kappa, m.i1_min).i1 : cap_center(m.p, s.kappa);
    const double a_trial = i1_trial - p_n;
    const CapMoves moves(m.p, s);
    const auto fn = [&](double dk, double& g, double& dg) {
        const CapMove c = moves(dk);
        const Change d = corner ? corner_change(m, s, p_n, dk) : centre_change(m.p, s, dk);
        g = a_trial - d.d - 3.0 * m.bulk * c.dv;
        dg = -d.slope - 3.0 * m.bulk * c.rate;
    };
    const double floor =
        (corner ? hardening_for_corner(m.p, m.i1_min, m.kappa_min) : m.kappa_min) - s.kappa;
    double lo = std::max(std::min(a_trial, 0.0), floor);
    double hi = std::max(std::max(a_trial, 0.0), floor);
    double g = 0.0;
    double dg = 0.0;
    fn(lo, g, dg);
    // Where P moves slower than kappa (clamped centre) the root may lie beyond a_trial.
    for (int i = 0; i < 200 && g < 0.0 && lo > floor; ++i) {
        lo = std::max(floor, lo - (hi - lo));
        fn(lo, g, dg);
    }
    if (g < 0.0) {
        return {};
    }
    fn(hi, g, dg);
    if (g > 0.0) {
        hi += 3.0 * m.bulk * m.p.W; // dilatancy from a locked cap: 3K |dv| <= 3K W
        fn(hi, g, dg);
    }
    for (int i = 0; i < 200 && g > 0.0; ++i) {
        hi += hi - lo;
        fn(hi, g, dg);
    }
    // dk may be far below the ulp of kappa: the tolerance scales with the bracket, not kappa.
    const Root root = solve_bracketed(fn, lo, hi, kTolerance * (hi - lo));
    return {true, root.value, root.slope};
}

} // namespace grainload::materials::cap
