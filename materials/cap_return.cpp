#include "materials/cap_return.hpp"

#include "materials/cap_moves.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>

namespace grainload::materials::cap {
namespace {

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
// corner_start's estimate of a is used below this fraction of I1_tr - L_n: there the trial's
// start would cost at least log2(10) ~ 3 halved steps.
constexpr double kNearCorner = 0.1;

double tolerance_for(const Model& m, double i1_trial, double q_trial, const Hardening& s) {
    return kTolerance * (std::abs(i1_trial) + q_trial + std::abs(s.kappa) + std::abs(m.p.k) + 1.0);
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

/// Tension cutoff / apex: I1 = I1_min, with sqrt(J2) limited to F(I1_min) (the corner of the
/// cutoff plane and the envelope; the apex itself when F(I1_min) = 0), or to the half-height B
/// of a cap whose clamped centre puts its flat top below F(I1_min). The cutoff's flow is
/// volumetric: it alone sets the new kappa, whose B then limits sqrt(J2) explicitly.
Return tension_return(const Model& m, double i1_trial, double q_trial, const Hardening& s) {
    const double f_min = envelope(m.p, m.i1_min);
    const double flow = (i1_trial - m.i1_min) / (3.0 * m.bulk);
    const Contraction c = contract_cap(m, s, std::min(flow, 0.0), m.kappa_min);
    const double b = half_height(m.p, c.after.kappa);
    const double limit = std::min(f_min, b);
    const bool sheared = q_trial > limit;
    Return r =
        finish(PlasticRegion::apex, m.i1_min, sheared ? limit / q_trial : 1.0, c.after, c.dv);
    r.di1_di1 = 0.0;
    r.drho_dq = sheared ? -limit / (q_trial * q_trial) : 0.0;
    if (sheared && b < f_min && flow < 0.0 && !c.floored) {
        // rho = B(kappa(I1_tr)) / q_tr: dkappa/dI1_tr = 1 / (3K W D exp(-D (X - X0)) X'(kappa)).
        const double decay = hardening_decay(m.p, c.after.x);
        const double dkappa =
            1.0 / (3.0 * m.bulk * m.p.W * m.p.D * decay * cap_position_slope(m.p, c.after.kappa));
        r.drho_di1 = half_height_slope(m.p, c.after.kappa) * dkappa / q_trial;
    }
    return r;
}

/// Corner: the stress sits where the cap meets the envelope, I1 = L and sqrt(J2) = F(L)
/// (the thesis writes J2 = B there, an erratum).
Return corner_return(const Model& m, double i1_trial, double q_trial, const Hardening& s) {
    const Shift shift = shift_to(m, i1_trial, s, Target::corner);
    if (!shift.feasible) {
        return tension_return(m, i1_trial, q_trial, s); // the corner lies below I1_min
    }
    const CapMove c = move_cap(m.p, s, shift.dk);
    const double corner_n = corner_point(m.p, s.kappa, m.i1_min).i1;
    const Change d = corner_change(m, s, corner_n, shift.dk);
    const double i1 = corner_n + d.d;
    const double f = envelope(m.p, i1);
    Return r = finish(PlasticRegion::corner, i1, q_trial > 0.0 ? f / q_trial : 1.0,
                      {s.x + c.dx, s.kappa + shift.dk}, c.dv);
    r.di1_di1 = -d.slope / shift.slope;
    if (q_trial > 0.0) {
        r.drho_di1 = envelope_slope(m.p, i1) * r.di1_di1 / q_trial;
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
    const double floor = hardening_for_corner(p, i1, m.kappa_min);
    const Contraction c = contract_cap(m, s, (i1_trial - i1) / (3.0 * m.bulk), floor);
    if (c.floored || c.after.kappa <= floor) {
        return corner_return(m, i1_trial, q_trial, s); // the cap would pass the stress point
    }
    const double slope = envelope_slope(p, i1);
    const double f = envelope(p, i1);
    Return r = finish(PlasticRegion::failure_surface, i1, f / q_trial, c.after, c.dv);
    r.di1_di1 = -ratio / root.slope;
    r.di1_dq = -slope / root.slope;
    r.drho_di1 = slope * r.di1_di1 / q_trial;
    r.drho_dq = slope * r.di1_dq / q_trial - f / (q_trial * q_trial);
    return r;
}

/// Cap residual in the unknowns a = I1 - L >= 0 and kappa, with its partial derivatives.
struct CapResidual {
    double g, g_a, g_k, g_q;
    double rho, rho_a, rho_k;
};

/// Elliptical cap fc = (I1 - L)^2 + R^2 (J2 - B^2), thesis (4.6.3.9), with associated flow
/// (4.6.3.31)-(4.6.3.33): dv = 6 dlambda a and s = s_tr / (1 + 2 G R^2 dlambda), hence
/// rho = 3a / (3a + G R^2 dv). fc is divided by (a + R B) > 0 so that the residual stays
/// linear-like as R -> 0: g = a - R B + R^2 rho^2 q_tr^2 / (a + R B); R = 0 gives g = a.
/// B = B(kappa) is the half-height (X - L) / R, F(kappa) unless the centre is clamped.
CapResidual cap_residual(const Model& m, double q_trial, double a, double kappa, const CapMove& c) {
    const Parameters& p = m.p;
    const double soft = m.shear * p.R * p.R;
    const double den = 3.0 * a + soft * c.dv;
    CapResidual r{};
    r.rho = 1.0;
    if (den > 0.0) {
        r.rho = 3.0 * a / den;
        r.rho_a = 3.0 * soft * c.dv / (den * den);
        r.rho_k = -3.0 * a * soft * c.rate / (den * den);
    }
    const double b = half_height(p, kappa);
    const double b_k = half_height_slope(p, kappa);
    const double sum = a + p.R * b;
    const double rq2 = p.R * p.R * q_trial * q_trial;
    const double tail = sum > 0.0 ? rq2 * r.rho * r.rho / sum : 0.0;
    const double tail_rho = sum > 0.0 ? 2.0 * rq2 * r.rho / sum : 0.0;
    const double tail_sum = sum > 0.0 ? -tail / sum : 0.0;
    r.g = a - p.R * b + tail;
    r.g_a = 1.0 + tail_rho * r.rho_a + tail_sum;
    r.g_k = -p.R * b_k + tail_rho * r.rho_k + tail_sum * p.R * b_k;
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

/// What the cap solves share: the trial's distance from the centre and the box for kappa.
struct CapBox {
    double a_trial = 0.0; ///< I1_tr - L_n
    double dk_max = 0.0;  ///< a >= 0 bounds the move: L(kappa) <= I1_tr
};

/// Newton on both cap equations at once, r1 = (I1_tr - L_n) - dL(dk) - 3K dv(dk) - a and
/// r2 = g(a, kappa_n + dk), from the start (a, dk) passed in. A step that would leave the
/// admissible box 0 <= a <= I1_tr - L_n, 0 <= dk <= dk_max is halved until it stays inside:
/// the first step from the trial overshoots to a < 0 whenever the hardening is stiff
/// (3K dv'(0) >> 1, e.g. every compressed point of the thesis sand with X0 = 0). Returns false
/// when no step inside the box is found or the iteration does not converge.
/// Converged: |da| below kTolerance a or the residual's round-off, about 1e-15 (I1_tr - L_n).
bool cap_newton(const Model& m, double q_trial, const Hardening& s, const CapBox& box, double& a,
                double& dk) {
    const double a_trial = box.a_trial;
    for (int iteration = 0; iteration < 25; ++iteration) {
        const CapMove c = move_cap(m.p, s, dk);
        const Change d = centre_change(m.p, s, dk);
        const CapResidual r = cap_residual(m, q_trial, a, s.kappa + dk, c);
        const double r1 = a_trial - d.d - 3.0 * m.bulk * c.dv - a;
        const double j12 = -d.slope - 3.0 * m.bulk * c.rate; // dr1/da = -1
        const double det = -r.g_k - j12 * r.g_a;
        if (!(det != 0.0)) {
            return false;
        }
        double da = (r1 * r.g_k - j12 * r.g) / det;
        double ddk = (-r.g - r.g_a * r1) / det;
        for (int cuts = 0;
             !(a - da >= 0.0 && a - da <= a_trial && dk - ddk >= 0.0 && dk - ddk <= box.dk_max);
             ++cuts) {
            if (cuts == kMaxStepCuts) {
                return false;
            }
            da *= 0.5;
            ddk *= 0.5;
        }
        a -= da;
        dk -= ddk;
        if (std::abs(da) <= kTolerance * a + kRoundOff * a_trial &&
            std::abs(ddk) <= kTolerance * box.dk_max) {
            return true;
        }
    }
    return false;
}

/// A start for cap_newton next to the corner, where the returns of a stiff hardening law
/// (3K dv' >> 1) end: dk from the volumetric balance linearised at the trial with a = 0, and a
/// from the cap condition g = 0 at that dk in the limit 3a << G R^2 dv, where rho = 3a / (G R^2
/// dv): a^2 (1 + (3 q_tr / (G R dv))^2) = R^2 B^2. From the trial instead, Newton's first steps
/// leave the box (a < 0) and are halved about log2((I1_tr - L_n) / a) times before it converges
/// (8-15 iterations against 3-5 from here for the compacting granular block of
/// bench/sph_throughput). Returns false where the estimate is not next to the corner (a above
/// kNearCorner of the trial's), where the trial is as good a start.
bool corner_start(const Model& m, double q_trial, const Hardening& s, const CapBox& box, double& a,
                  double& dk) {
    const double rate =
        centre_change(m.p, s, 0.0).slope + 3.0 * m.bulk * move_cap(m.p, s, 0.0).rate;
    const double dk_start = box.a_trial / rate;
    if (!(dk_start > 0.0 && dk_start <= box.dk_max)) {
        return false;
    }
    const double ratio = 3.0 * q_trial / (m.shear * m.p.R * move_cap(m.p, s, dk_start).dv);
    const double a_start =
        m.p.R * half_height(m.p, s.kappa + dk_start) / std::sqrt(1.0 + ratio * ratio);
    if (!(a_start > 0.0 && a_start < kNearCorner * box.a_trial)) {
        return false;
    }
    a = a_start;
    dk = dk_start;
    return true;
}

/// a(dk) = (I1_tr - L_n) - dL(dk) - 3K dv(dk): the volumetric balance solved for a.
double balance_gap(const Model& m, const Hardening& s, double a_trial, double dk) {
    return a_trial - centre_change(m.p, s, dk).d - 3.0 * m.bulk * move_cap(m.p, s, dk).dv;
}

/// A start for cap_newton where the one from the trial fails. The volumetric balance gives a
/// explicitly, a(dk), so the cap condition reduces to h(dk) = g(a(dk), kappa_n + dk) on
/// [0, dk_centre]: h(0) > 0 (the trial is outside the cap) and h(dk_centre) = -R B <= 0 (a = 0,
/// rho = 0). For a trial far above the envelope, R^2 q_tr^2 > (a + R B)^2 makes g decrease with
/// a and h rise from dk = 0, so Newton from the trial heads out of the box (the thesis sand at
/// full stiffness: 94 % of its cap returns). The bracketed solve on h does not care; it only
/// has to get near the root, from where cap_newton converges in a few steps to the coupled
/// equations' tolerance. Returns false when the centre shift is infeasible.
bool cap_reduced_start(const Model& m, double q_trial, const Hardening& s, double a_trial,
                       const Shift& centre, double& a, double& dk) {
    if (!centre.feasible || !(centre.dk > 0.0)) {
        return false;
    }
    const auto reduced = [&](double dk_try, double& h, double& dh) {
        const CapMove c = move_cap(m.p, s, dk_try);
        const Change d = centre_change(m.p, s, dk_try);
        const double slope = -d.slope - 3.0 * m.bulk * c.rate; // da/dkappa
        const CapResidual r = cap_residual(
            m, q_trial, std::max(a_trial - d.d - 3.0 * m.bulk * c.dv, 0.0), s.kappa + dk_try, c);
        h = r.g;
        dh = r.g_a * slope + r.g_k;
    };
    dk = solve_bracketed(reduced, 0.0, centre.dk, kStartTolerance * centre.dk).value;
    a = std::max(balance_gap(m, s, a_trial, dk), 0.0);
    return true;
}

/// The nested, bracketed cap solve (the safe path): the unknown a in [0, I1_tr - L_n]; for each
/// a the move dk solves the volumetric balance a(dk) = a on [0, dk_centre]. Returns (a, dk).
std::pair<double, double> cap_nested(const Model& m, double q_trial, const Hardening& s,
                                     double a_trial, const Shift& centre) {
    const double dk_max = centre.dk; // a = 0 bounds dk
    const double tolerance = kTolerance * dk_max;
    double last_dk = std::numeric_limits<double>::quiet_NaN(); // warm start
    const auto move_for = [&](double a_try) {
        const auto balance = [&](double dk_try, double& g, double& dg) {
            const CapMove c = move_cap(m.p, s, dk_try);
            const Change d = centre_change(m.p, s, dk_try);
            g = a_trial - d.d - 3.0 * m.bulk * c.dv - a_try;
            dg = -d.slope - 3.0 * m.bulk * c.rate;
        };
        last_dk = solve_bracketed(balance, 0.0, dk_max, tolerance, 0.0, last_dk).value;
        return last_dk;
    };
    const auto fn = [&](double a_try, double& g, double& dg) {
        const double dk_try = move_for(a_try);
        const CapMove c = move_cap(m.p, s, dk_try);
        const Change d = centre_change(m.p, s, dk_try);
        const CapResidual r = cap_residual(m, q_trial, a_try, s.kappa + dk_try, c);
        g = r.g;
        dg = r.g_a - r.g_k / (d.slope + 3.0 * m.bulk * c.rate);
    };
    const double a = solve_bracketed(fn, 0.0, a_trial, 0.0, kTolerance).value;
    return {a, move_for(a)};
}

/// Cap return with the unknown a = I1 - L in [0, I1_tr - L_n]; for each a the move dk of kappa
/// solves the volumetric balance (I1_tr - L_n) - dL(dk) - 3K dv(dk) = a, (4.6.3.35)-(4.6.3.37).
/// Solving for a rather than L resolves returns that end next to the corner (a ~ R^2, tiny for
/// small R) and trials within round-off of I1_tr = L_n. cap_newton is tried from corner_start
/// where that applies, then from the trial, then from cap_reduced_start; the nested, bracketed
/// solve is the safe path left when all fail.
Return cap_return(const Model& m, double i1_trial, double q_trial, const Hardening& s) {
    const Parameters& p = m.p;
    if (p.R == 0.0) {
        return flat_cap(corner_return(m, i1_trial, q_trial, s), q_trial, p);
    }
    const double l_n = cap_center(p, s.kappa);
    // L(kappa) <= I1_tr bounds kappa by I1_tr, i.e. dk <= a_trial + (L_n - kappa_n).
    const CapBox box{i1_trial - l_n, i1_trial - l_n + (l_n - s.kappa)};
    double a = box.a_trial;
    double dk = 0.0;
    bool converged =
        corner_start(m, q_trial, s, box, a, dk) && cap_newton(m, q_trial, s, box, a, dk);
    if (!converged) {
        a = box.a_trial;
        dk = 0.0;
        converged = cap_newton(m, q_trial, s, box, a, dk);
    }
    std::optional<Shift> centre; // solved once, for the reduced start and the nested solve
    if (!converged) {
        centre = shift_to(m, i1_trial, s, Target::centre);
        converged = cap_reduced_start(m, q_trial, s, box.a_trial, *centre, a, dk) &&
                    cap_newton(m, q_trial, s, box, a, dk);
    }
    if (!(converged && a >= kResolvedGap * box.a_trial)) {
        if (!centre) {
            centre = shift_to(m, i1_trial, s, Target::centre);
        }
        std::tie(a, dk) = cap_nested(m, q_trial, s, box.a_trial, *centre);
    }
    const CapMove c = move_cap(p, s, dk);
    const Change d = centre_change(p, s, dk);
    const double kappa = s.kappa + dk;
    const CapResidual res = cap_residual(m, q_trial, a, kappa, c);
    Return r = finish(PlasticRegion::cap, l_n + d.d + a, res.rho, {s.x + c.dx, kappa}, c.dv);
    // Implicit differentiation of g(a, kappa(a, I1_tr), q_tr) = 0 with
    // dkappa = (dI1_tr - da) / (L' + 3K dv').
    const double slope = 1.0 / (d.slope + 3.0 * m.bulk * c.rate);
    const double g_a = res.g_a - res.g_k * slope;
    const double a_i1 = -res.g_k * slope / g_a;
    const double a_q = -res.g_q / g_a;
    const double k_i1 = slope * (1.0 - a_i1);
    const double k_q = -slope * a_q;
    r.di1_di1 = d.slope * k_i1 + a_i1;
    r.di1_dq = d.slope * k_q + a_q;
    r.drho_di1 = res.rho_a * a_i1 + res.rho_k * k_i1;
    r.drho_dq = res.rho_a * a_q + res.rho_k * k_q;
    return r;
}

/// Flat top of a cap whose centre is clamped at L = 0 (MAT_025, kappa < 0): between the corner
/// c(kappa) and L the elastic domain is bounded by sqrt(J2) = B(kappa), the ellipse's top value
/// (docs "Initial cap": the reading of MAT_025's Tmises that keeps the domain convex). The
/// normal is deviatoric: no volumetric flow, kappa unchanged, the deviator scaled to B.
Return flat_top_return(const Model& m, double i1_trial, double q_trial, const Hardening& s) {
    const double b = half_height(m.p, s.kappa);
    Return r = finish(PlasticRegion::failure_surface, i1_trial, b / q_trial, s, 0.0);
    r.drho_dq = -b / (q_trial * q_trial);
    return r;
}

bool in_tension_region(const Model& m, double i1_trial, double q_trial, const Hardening& s) {
    if (i1_trial >= m.i1_min) {
        return false;
    }
    // A clamped cap's flat top below F(I1_min) meets the cutoff itself: that corner's normal
    // cone holds every trial below I1_min.
    const double f_min = envelope(m.p, m.i1_min);
    if (centre_clamped(m.p, s.kappa) && half_height(m.p, s.kappa) < f_min) {
        return true;
    }
    // Below I1_min the return goes to the cutoff unless the trial lies inside the failure
    // surface's normal cone at (I1_min, F(I1_min)): I1 = I1_min - 9K F' (q - F) / G.
    const double excess = q_trial - f_min;
    return excess <= 0.0 ||
           i1_trial <= m.i1_min - 9.0 * m.bulk * envelope_slope(m.p, m.i1_min) * excess / m.shear;
}

} // namespace

Return return_map(const Model& m, double i1_trial, double q_trial, const Hardening& state) {
    if (in_tension_region(m, i1_trial, q_trial, state)) {
        return tension_return(m, i1_trial, q_trial, state);
    }
    const double l = cap_center(m.p, state.kappa);
    if (i1_trial > l) {
        const double b = half_height(m.p, state.kappa);
        const double a = i1_trial - l;
        const double fc = a * a + m.p.R * m.p.R * (q_trial * q_trial - b * b);
        // A locked cap follows the stress elastically (dv = 0); above the envelope only the
        // failure surface can flow.
        if (fc > 0.0 && locked(m.p, state) && q_trial > envelope(m.p, i1_trial)) {
            return failure_return(m, i1_trial, q_trial, state);
        }
        if (fc > 0.0) {
            return cap_return(m, i1_trial, q_trial, state);
        }
    } else if (centre_clamped(m.p, state.kappa) && q_trial > half_height(m.p, state.kappa) &&
               i1_trial >= corner_point(m.p, state.kappa, m.i1_min).i1) {
        return flat_top_return(m, i1_trial, q_trial, state);
    } else if (q_trial > envelope(m.p, i1_trial)) {
        return failure_return(m, i1_trial, q_trial, state);
    }
    Return r;
    r.i1 = i1_trial;
    r.hardening = state;
    return r;
}

} // namespace grainload::materials::cap
