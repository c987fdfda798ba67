#include "materials/cap_return.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace grainload::materials::cap {
namespace {

// Relative tolerance of the scalar solves; far below the 1e-8 step-independence and 1e-5
// tangent checks, and a few ulps above round-off of the residuals.
constexpr double kTolerance = 1e-14;
// What round-off leaves of a Newton step on the cap, relative to the trial's distance from the
// cap centre (a few ulps); and how often a step that leaves the admissible box is halved.
constexpr double kRoundOff = 1e-15;
constexpr int kMaxStepCuts = 60;
// How close the reduced cap solve brings its start for the Newton polish (relative to the
// corner's shift): Newton converges quadratically from there in 2-3 steps.
constexpr double kStartTolerance = 1e-8;
// Newton's a carries the round-off of the volumetric balance, about 1e-16 (I1_tr - L_n). An
// a below this fraction of I1_tr - L_n (a return next to the corner) is left to the nested
// solve, which treats a as exact: rho = 3a / (3a + G R^2 dv) must not inherit that round-off.
constexpr double kResolvedGap = 1e-6;

double tolerance_for(const Model& m, double i1_trial, double q_trial, const Hardening& s) {
    return kTolerance * (std::abs(i1_trial) + q_trial + std::abs(s.l) + std::abs(m.p.k) + 1.0);
}

/// The cap moved from the state (L_n, X_n) by dL: its shift dX, the plastic volumetric strain
/// dv of the hardening law (4.6.3.4) and d(dv)/d(dL) (4.6.3.5), all written as increments
/// (expm1) so that moves far below the ulp of L stay resolved and a locked state
/// (exp(-D (X_n - X0)) = 0) gives dv = 0 without a logarithm.
struct CapMove {
    double dx = 0.0;
    double dv = 0.0;
    double rate = 0.0;
};

CapMove move_cap(const Parameters& p, const Hardening& s, double dl) {
    const double decay_n = hardening_decay(p, s.x);
    // F(L_n + dL) - F(L_n) = theta dL - gamma (exp(-B1 (L_n + dL)) - exp(-B1 L_n)); expm1 keeps
    // small moves exact, the plain difference avoids inf * 0 for large contractions.
    const double shifted = p.gamma * std::exp(-p.beta * s.l);
    const double arg = -p.beta * dl;
    const double exp_change =
        arg < 1.0 ? shifted * std::expm1(arg) : p.gamma * std::exp(-p.beta * (s.l + dl)) - shifted;
    CapMove c;
    c.dx = dl + p.R * (p.theta * dl - exp_change);
    // exp(-D (X_n + dX - X0)) in one exponent: finite even when decay_n has underflowed.
    const double decay = std::exp(-p.D * (s.x + c.dx - p.X0));
    c.dv = decay_n > 0.0 ? -p.W * decay_n * std::expm1(-p.D * c.dx) : -p.W * decay;
    c.rate = p.W * p.D * decay * cap_position_slope(p, s.l + dl);
    return c;
}

/// A locked point has exhausted its compaction (eps_v^p = W, exp(-D (X - X0)) = 0): its cap
/// sits at infinity and only dilatancy can bring it back.
bool locked(const Parameters& p, const Hardening& s) {
    return !(hardening_decay(p, s.x) > 0.0);
}

Return finish(PlasticRegion region, double i1, double rho, const Hardening& after, double dv) {
    Return r;
    r.region = region;
    r.i1 = i1;
    r.rho = rho;
    r.hardening = after;
    r.hardening_strain = dv;
    return r;
}

/// Hardening after a dilatant flow (volumetric plastic strain dv < 0): the cap contracts by
/// inverting (4.6.3.4), thesis (4.6.3.8), but never past the stress point i1; returns the new
/// state and the plastic volumetric strain the hardening law records.
std::pair<Hardening, double> contract_cap(const Parameters& p, const Hardening& s, double dv,
                                          double i1) {
    const double decay_n = hardening_decay(p, s.x);
    const double decay = decay_n - dv / p.W;
    if (!(decay > 0.0)) {
        return {s, 0.0}; // locked (decay_n == 0) and no flow: the cap stays where it is
    }
    const double x = p.X0 - std::log(decay) / p.D;
    if (x <= cap_position(p, i1)) {
        const double x_min = cap_position(p, i1);
        return {{x_min, i1}, p.W * (decay_n - hardening_decay(p, x_min))};
    }
    return {{x, cap_center_for(p, x, s.l)}, dv};
}

/// Tension cutoff / apex: I1 = I1_min, with sqrt(J2) limited to F(I1_min) (the corner of the
/// cutoff plane and the envelope; the apex itself when F(I1_min) = 0).
Return tension_return(const Model& m, double i1_trial, double q_trial, const Hardening& s) {
    const double f_min = envelope(m.p, m.i1_min);
    const bool sheared = q_trial > f_min;
    const double flow = (i1_trial - m.i1_min) / (3.0 * m.bulk);
    const auto [after, dv] = contract_cap(m.p, s, std::min(flow, 0.0), m.i1_min);
    Return r = finish(PlasticRegion::apex, m.i1_min, sheared ? f_min / q_trial : 1.0, after, dv);
    r.di1_di1 = 0.0;
    r.drho_dq = sheared ? -f_min / (q_trial * q_trial) : 0.0;
    return r;
}

/// Shift dL of the cap centre that puts the stress at the corner, I1 = L: with L = L_n + dL the
/// volumetric balance (4.6.3.43) reads g(dL) = (I1_tr - L_n) - dL - 3K dv(dL) = 0, decreasing
/// in dL. Infeasible when that point lies below I1_min.
struct CornerShift {
    bool feasible = false;
    double dl = 0.0;
    double slope = -1.0; ///< g'(dL)
};

CornerShift corner_shift(const Model& m, double i1_trial, const Hardening& s) {
    const double a_trial = i1_trial - s.l;
    const auto fn = [&](double dl, double& g, double& dg) {
        const CapMove c = move_cap(m.p, s, dl);
        g = a_trial - dl - 3.0 * m.bulk * c.dv;
        dg = -1.0 - 3.0 * m.bulk * c.rate;
    };
    const double floor = m.i1_min - s.l;
    const double lo = std::max(std::min(a_trial, 0.0), floor);
    double hi = std::max(std::max(a_trial, 0.0), floor);
    double g = 0.0;
    double dg = 0.0;
    fn(lo, g, dg);
    if (g < 0.0) {
        return {};
    }
    fn(hi, g, dg);
    if (g > 0.0) {
        hi += 3.0 * m.bulk * m.p.W; // dilatancy from a locked cap: 3K |dv| <= 3K W
    }
    // dL may be far below the ulp of L: the tolerance scales with the bracket, not with L.
    const Root root = solve_bracketed(fn, lo, hi, kTolerance * (hi - lo));
    return {true, root.value, root.slope};
}

/// Corner: the stress sits where the cap meets the envelope, I1 = L and sqrt(J2) = F(L)
/// (the thesis writes J2 = B there, an erratum).
Return corner_return(const Model& m, double i1_trial, double q_trial, const Hardening& s) {
    const CornerShift shift = corner_shift(m, i1_trial, s);
    if (!shift.feasible) {
        return tension_return(m, i1_trial, q_trial, s); // the corner lies below I1_min
    }
    const CapMove c = move_cap(m.p, s, shift.dl);
    const double l = s.l + shift.dl;
    const double f = envelope(m.p, l);
    Return r =
        finish(PlasticRegion::corner, l, q_trial > 0.0 ? f / q_trial : 1.0, {s.x + c.dx, l}, c.dv);
    r.di1_di1 = -1.0 / shift.slope;
    if (q_trial > 0.0) {
        r.drho_di1 = envelope_slope(m.p, l) * r.di1_di1 / q_trial;
        r.drho_dq = -f / (q_trial * q_trial);
    }
    return r;
}

/// Failure surface f1 = sqrt(J2) - F(I1) = 0 with associated flow, (4.6.3.24)-(4.6.3.30).
/// Unknown u = I1: dilatancy gives I1 = I1_tr + 9 K dlambda F'(I1) and sqrt(J2) =
/// sqrt(J2_tr) - G dlambda; eliminating dlambda (without dividing by F', which may be 0):
/// g(u) = F'(u) (q_tr - F(u)) - G (u - I1_tr) / (9 K).
Return failure_return(const Model& m, double i1_trial, double q_trial, const Hardening& s) {
    const Parameters& p = m.p;
    const double ratio = m.shear / (9.0 * m.bulk);
    const auto fn = [&](double u, double& g, double& dg) {
        const double slope = envelope_slope(p, u);
        const double excess = q_trial - envelope(p, u);
        g = slope * excess - ratio * (u - i1_trial);
        dg = envelope_curvature(p, u) * excess - slope * slope - ratio;
    };
    // F(I1_tr) < 0 with q_tr = 0 happens only by round-off at the apex.
    if (!(q_trial > 0.0)) {
        return tension_return(m, i1_trial, q_trial, s);
    }
    // The root must lie above I1_min (else the cutoff takes over), so the bracket starts at
    // max(I1_tr, I1_min): this also keeps exp(-B1 I1) finite for far-tensile trials.
    const double lo = std::max(i1_trial, m.i1_min);
    double g_lo = 0.0;
    double dg_lo = 0.0;
    fn(lo, g_lo, dg_lo);
    if (g_lo < 0.0) {
        return tension_return(m, i1_trial, q_trial, s);
    }
    const double hi = lo + envelope_slope(p, lo) * (q_trial - envelope(p, lo)) / ratio;
    const Root root = solve_bracketed(fn, lo, hi, tolerance_for(m, i1_trial, q_trial, s));
    const double i1 = root.value;
    const auto [after, dv] = contract_cap(p, s, (i1_trial - i1) / (3.0 * m.bulk), i1);
    if (after.l <= i1) {
        return corner_return(m, i1_trial, q_trial, s); // the cap would pass the stress point
    }
    const double slope = envelope_slope(p, i1);
    const double f = envelope(p, i1);
    Return r = finish(PlasticRegion::failure_surface, i1, f / q_trial, after, dv);
    r.di1_di1 = -ratio / root.slope;
    r.di1_dq = -slope / root.slope;
    r.drho_di1 = slope * r.di1_di1 / q_trial;
    r.drho_dq = slope * r.di1_dq / q_trial - f / (q_trial * q_trial);
    return r;
}

/// Cap residual in the unknowns a = I1 - L >= 0 and L, with its partial derivatives.
struct CapResidual {
    double g, g_a, g_l, g_q;
    double rho, rho_a, rho_l;
};

/// Elliptical cap fc = (I1 - L)^2 + R^2 (J2 - B^2), thesis (4.6.3.9), with associated flow
/// (4.6.3.31)-(4.6.3.33): dv = 6 dlambda a and s = s_tr / (1 + 2 G R^2 dlambda), hence
/// rho = 3a / (3a + G R^2 dv). fc is divided by (a + R B) > 0 so that the residual stays
/// linear-like as R -> 0: g = a - R B + R^2 rho^2 q_tr^2 / (a + R B); R = 0 gives g = a.
CapResidual cap_residual(const Model& m, double q_trial, double a, double l, const CapMove& c) {
    const Parameters& p = m.p;
    const double soft = m.shear * p.R * p.R;
    const double den = 3.0 * a + soft * c.dv;
    CapResidual r{};
    r.rho = 1.0;
    if (den > 0.0) {
        r.rho = 3.0 * a / den;
        r.rho_a = 3.0 * soft * c.dv / (den * den);
        r.rho_l = -3.0 * a * soft * c.rate / (den * den);
    }
    const double b = envelope(p, l);
    const double b_l = envelope_slope(p, l);
    const double sum = a + p.R * b;
    const double rq2 = p.R * p.R * q_trial * q_trial;
    const double tail = sum > 0.0 ? rq2 * r.rho * r.rho / sum : 0.0;
    const double tail_rho = sum > 0.0 ? 2.0 * rq2 * r.rho / sum : 0.0;
    const double tail_sum = sum > 0.0 ? -tail / sum : 0.0;
    r.g = a - p.R * b + tail;
    r.g_a = 1.0 + tail_rho * r.rho_a + tail_sum;
    r.g_l = -p.R * b_l + tail_rho * r.rho_l + tail_sum * p.R * b_l;
    r.g_q = sum > 0.0 ? 2.0 * p.R * p.R * q_trial * r.rho * r.rho / sum : 0.0;
    return r;
}

/// R = 0: the cap is the plane I1 = X = L (4.6.3.3); below the envelope the deviator is
/// untouched, above it the solution is the corner's.
Return flat_cap(Return corner, double q_trial, const Parameters& p) {
    if (q_trial <= envelope(p, corner.i1)) {
        corner.region = PlasticRegion::cap;
        corner.rho = 1.0;
        corner.drho_di1 = 0.0;
        corner.drho_dq = 0.0;
    }
    return corner;
}

/// Newton on both cap equations at once, r1 = (I1_tr - L_n) - dL - 3K dv(dL) - a and
/// r2 = g(a, L_n + dL), from the start (a, dL) passed in. A step that would leave the
/// admissible box 0 <= a, dL <= I1_tr - L_n (dv >= 0 bounds dL) is halved until it stays
/// inside: the first step from the trial overshoots to a < 0 whenever the hardening is stiff
/// (3K dv'(0) >> 1, e.g. every compressed point of the thesis sand with X0 = 0). Returns false
/// when no step inside the box is found or the iteration does not converge.
/// Converged: |da| below kTolerance a or the residual's round-off, about 1e-15 (I1_tr - L_n).
bool cap_newton(const Model& m, double q_trial, const Hardening& s, double a_trial, double& a,
                double& dl) {
    for (int iteration = 0; iteration < 25; ++iteration) {
        const CapMove c = move_cap(m.p, s, dl);
        const CapResidual r = cap_residual(m, q_trial, a, s.l + dl, c);
        const double r1 = a_trial - dl - 3.0 * m.bulk * c.dv - a;
        const double j12 = -1.0 - 3.0 * m.bulk * c.rate; // dr1/da = -1
        const double det = -r.g_l - j12 * r.g_a;
        if (!(det != 0.0)) {
            return false;
        }
        double da = (r1 * r.g_l - j12 * r.g) / det;
        double ddl = (-r.g - r.g_a * r1) / det;
        for (int cuts = 0;
             !(a - da >= 0.0 && a - da <= a_trial && dl - ddl >= 0.0 && dl - ddl <= a_trial);
             ++cuts) {
            if (cuts == kMaxStepCuts) {
                return false;
            }
            da *= 0.5;
            ddl *= 0.5;
        }
        a -= da;
        dl -= ddl;
        if (std::abs(da) <= kTolerance * a + kRoundOff * a_trial &&
            std::abs(ddl) <= kTolerance * a_trial) {
            return true;
        }
    }
    return false;
}

/// A start for cap_newton where the one from the trial fails. The volumetric balance gives a
/// explicitly, a(dL) = (I1_tr - L_n) - dL - 3K dv(dL), so the cap condition reduces to
/// h(dL) = g(a(dL), L_n + dL) on [0, dL_corner]: h(0) > 0 (the trial is outside the cap) and
/// h(dL_corner) = -R B <= 0 (a = 0, rho = 0). For a trial far above the envelope,
/// R^2 q_tr^2 > (a + R B)^2 makes g decrease with a and h rise from dL = 0, so Newton from
/// the trial heads out of the box (the thesis sand at full stiffness: 94 % of its cap
/// returns). The bracketed solve on h does not care; it only has to get near the root, from
/// where cap_newton converges in a few steps to the coupled equations' tolerance. Returns false
/// when the corner lies below I1_min.
bool cap_reduced_start(const Model& m, double q_trial, const Hardening& s, double a_trial,
                       const CornerShift& corner, double& a, double& dl) {
    if (!corner.feasible || !(corner.dl > 0.0)) {
        return false;
    }
    const auto reduced = [&](double dl_try, double& h, double& dh) {
        const CapMove c = move_cap(m.p, s, dl_try);
        const double slope = -1.0 - 3.0 * m.bulk * c.rate; // da/dL
        const CapResidual r = cap_residual(
            m, q_trial, std::max(a_trial - dl_try - 3.0 * m.bulk * c.dv, 0.0), s.l + dl_try, c);
        h = r.g;
        dh = r.g_a * slope + r.g_l;
    };
    dl = solve_bracketed(reduced, 0.0, corner.dl, kStartTolerance * corner.dl).value;
    a = std::max(a_trial - dl - 3.0 * m.bulk * move_cap(m.p, s, dl).dv, 0.0);
    return true;
}

/// Cap return with the unknown a = I1 - L in [0, I1_tr - L_n]; for each a the move dL of the
/// centre solves the volumetric balance (I1_tr - L_n) - dL - 3K dv(dL) = a, (4.6.3.35)-
/// (4.6.3.37). Solving for a rather than L resolves returns that end next to the corner
/// (a ~ R^2, tiny for small R) and trials within round-off of I1_tr = L_n. cap_newton is tried
/// from the trial, then from cap_reduced_start; the nested, bracketed solve is the safe path
/// left when both fail.
Return cap_return(const Model& m, double i1_trial, double q_trial, const Hardening& s) {
    const Parameters& p = m.p;
    if (p.R == 0.0) {
        return flat_cap(corner_return(m, i1_trial, q_trial, s), q_trial, p);
    }
    const double a_trial = i1_trial - s.l;
    double a = a_trial;
    double dl = 0.0;
    bool converged = cap_newton(m, q_trial, s, a_trial, a, dl);
    std::optional<CornerShift> corner; // solved once, for the reduced start and the nested solve
    if (!converged) {
        corner = corner_shift(m, i1_trial, s);
        converged = cap_reduced_start(m, q_trial, s, a_trial, *corner, a, dl) &&
                    cap_newton(m, q_trial, s, a_trial, a, dl);
    }
    if (!(converged && a >= kResolvedGap * a_trial)) {
        if (!corner) {
            corner = corner_shift(m, i1_trial, s);
        }
        const double dl_max = corner->dl; // a = 0 bounds dL
        const double tolerance = kTolerance * dl_max;
        double last_dl = std::numeric_limits<double>::quiet_NaN(); // warm start
        const auto centre = [&](double a_try) {
            const auto balance = [&](double dl_try, double& g, double& dg) {
                const CapMove c = move_cap(p, s, dl_try);
                g = a_trial - dl_try - 3.0 * m.bulk * c.dv - a_try;
                dg = -1.0 - 3.0 * m.bulk * c.rate;
            };
            last_dl = solve_bracketed(balance, 0.0, dl_max, tolerance, 0.0, last_dl).value;
            return last_dl;
        };
        const auto fn = [&](double a_try, double& g, double& dg) {
            const double dl_try = centre(a_try);
            const CapMove c = move_cap(p, s, dl_try);
            const CapResidual r = cap_residual(m, q_trial, a_try, s.l + dl_try, c);
            g = r.g;
            dg = r.g_a - r.g_l / (1.0 + 3.0 * m.bulk * c.rate);
        };
        a = solve_bracketed(fn, 0.0, a_trial, 0.0, kTolerance).value;
        dl = centre(a);
    }
    const CapMove c = move_cap(p, s, dl);
    const double l = s.l + dl;
    const CapResidual res = cap_residual(m, q_trial, a, l, c);
    Return r = finish(PlasticRegion::cap, l + a, res.rho, {s.x + c.dx, l}, c.dv);
    // Implicit differentiation of g(a, L(a, I1_tr), q_tr) = 0 with dL = (dI1_tr - da) slope.
    const double slope = 1.0 / (1.0 + 3.0 * m.bulk * c.rate);
    const double g_a = res.g_a - res.g_l * slope;
    const double a_i1 = -res.g_l * slope / g_a;
    const double a_q = -res.g_q / g_a;
    const double l_i1 = slope * (1.0 - a_i1);
    const double l_q = -slope * a_q;
    r.di1_di1 = l_i1 + a_i1;
    r.di1_dq = l_q + a_q;
    r.drho_di1 = res.rho_a * a_i1 + res.rho_l * l_i1;
    r.drho_dq = res.rho_a * a_q + res.rho_l * l_q;
    return r;
}

bool in_tension_region(const Model& m, double i1_trial, double q_trial) {
    if (i1_trial >= m.i1_min) {
        return false;
    }
    // Below I1_min the return goes to the cutoff unless the trial lies inside the failure
    // surface's normal cone at (I1_min, F(I1_min)): I1 = I1_min - 9K F' (q - F) / G.
    const double f_min = envelope(m.p, m.i1_min);
    const double excess = q_trial - f_min;
    return excess <= 0.0 ||
           i1_trial <= m.i1_min - 9.0 * m.bulk * envelope_slope(m.p, m.i1_min) * excess / m.shear;
}

} // namespace

Return return_map(const Model& m, double i1_trial, double q_trial, const Hardening& state) {
    if (in_tension_region(m, i1_trial, q_trial)) {
        return tension_return(m, i1_trial, q_trial, state);
    }
    if (i1_trial > state.l) {
        const double b = envelope(m.p, state.l);
        const double a = i1_trial - state.l;
        const double fc = a * a + m.p.R * m.p.R * (q_trial * q_trial - b * b);
        // A locked cap follows the stress elastically (dv = 0); above the envelope only the
        // failure surface can flow.
        if (fc > 0.0 && locked(m.p, state) && q_trial > envelope(m.p, i1_trial)) {
            return failure_return(m, i1_trial, q_trial, state);
        }
        if (fc > 0.0) {
            return cap_return(m, i1_trial, q_trial, state);
        }
    } else if (q_trial > envelope(m.p, i1_trial)) {
        return failure_return(m, i1_trial, q_trial, state);
    }
    Return r;
    r.i1 = i1_trial;
    r.hardening = state;
    return r;
}

} // namespace grainload::materials::cap
