#include "materials/cap_region.hpp"

#include "materials/cap_moves.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

namespace grainload::materials::cap {
namespace {

// What round-off leaves of a Newton step on the cap, relative to the trial's distance from the
// cap centre (a few ulps); and how often a step that leaves the admissible box is halved.
constexpr double kRoundOff = 1e-15;
constexpr int kMaxStepCuts = 60;
constexpr int kMaxNewtonIterations = 25;
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
// A Newton step predicted below this fraction of the convergence test's bounds (kTolerance a and
// kTolerance dk_max, 1e-14 relative) is not taken: 1e-2 of them is 1e-16 relative, the
// unknowns' round-off, so the iterate without it is the converged one to within an ulp or two,
// and a compacting return takes three Newton steps instead of four (the fourth confirmed).
// Measured with the test disabled after each prediction (bench/material_update's paths and
// bench/sph_throughput's granular block, 13.7 million predictions): the step not taken was at
// most 0.2 of the bounds when the step before it was below 1e-2 relative (1e12 of the bounds'
// units), but up to 44 times them after steps of 1e-1 relative, where the rate is not yet
// quadratic; a step before within 1e-3 relative is required.
constexpr double kNegligibleStep = 1e-2;
constexpr double kQuadraticBasin = 1e-3 / kTolerance;

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
CapResidual cap_residual(const Model& m, double q_trial, double a, const CapMove& c) {
    const Parameters& p = m.p;
    const double soft = m.shear * p.R * p.R;
    const double den = 3.0 * a + soft * c.dv;
    CapResidual r{};
    r.rho = 1.0;
    // Reciprocals taken once: a Newton iteration evaluates this residual, and its divisions,
    // waiting on one another, were most of its time.
    if (den > 0.0) {
        const double inverse = 1.0 / den;
        const double inverse_squared = 3.0 * soft * inverse * inverse;
        r.rho = 3.0 * a * inverse;
        r.rho_a = inverse_squared * c.dv;
        r.rho_k = -inverse_squared * a * c.rate;
    }
    const double b = c.b;
    const double b_k = c.b_slope;
    const double sum = a + p.R * b;
    const double inverse_sum = sum > 0.0 ? 1.0 / sum : 0.0;
    const double rq2 = p.R * p.R * q_trial * q_trial;
    const double tail_rho = 2.0 * rq2 * r.rho * inverse_sum;
    const double tail = 0.5 * tail_rho * r.rho;
    const double tail_sum = -tail * inverse_sum;
    r.g = a - p.R * b + tail;
    r.g_a = 1.0 + tail_rho * r.rho_a + tail_sum;
    r.g_k = -p.R * b_k + tail_rho * r.rho_k + tail_sum * p.R * b_k;
    r.g_q = 2.0 * p.R * p.R * q_trial * r.rho * r.rho * inverse_sum;
    return r;
}

/// What the cap solves share: the trial's distance from the centre and the box for kappa.
struct CapBox {
    double a_trial = 0.0; ///< I1_tr - L_n
    double dk_max = 0.0;  ///< a >= 0 bounds the move: L(kappa) <= I1_tr
};

/// L(kappa) <= I1_tr bounds kappa by I1_tr, i.e. dk <= a_trial + (L_n - kappa_n).
CapBox cap_box(double i1_trial, double l_n, const Hardening& s) {
    return {i1_trial - l_n, i1_trial - l_n + (l_n - s.kappa)};
}

/// An iterate of the cap solves with its moved cap, c = moves(dk): evaluated once where the
/// iterate is set, read by the Newton step from it and by the return when it is the solution.
struct Iterate {
    double a = 0.0;
    double dk = 0.0;
    CapMove c;
    /// The last Newton step that led here, in units of the convergence test's bounds; infinite
    /// at a start and after a halved step, where it predicts nothing.
    double step = std::numeric_limits<double>::infinity();
};

Iterate iterate_at(const CapMoves& moves, double a, double dk) {
    return {a, dk, moves(dk)};
}

/// Where a Newton iteration on the cap leaves the unknowns.
enum class Step { more, converged, failed };

/// The next Newton step's size from the last two, e_{k+1} = C e_k^2 with C = e_k / e_{k-1}^2
/// (quadratic convergence, both in the same units); infinite unless both are known, contract,
/// and the one before is inside kQuadraticBasin.
double predicted_step(double before, double last) {
    return last < before && before <= kQuadraticBasin ? last * (last / before) * (last / before)
                                                      : std::numeric_limits<double>::infinity();
}

/// One iteration of Newton on both cap equations at once, r1 = (I1_tr - L_n) - dL(dk) - 3K
/// dv(dk) - a and r2 = g(a, kappa_n + dk). A step that would leave the admissible box 0 <= a <=
/// I1_tr - L_n, 0 <= dk <= dk_max is halved until it stays inside: the first step from the trial
/// overshoots to a < 0 whenever the hardening is stiff (3K dv'(0) >> 1, e.g. every compressed
/// point of the thesis sand with X0 = 0). Fails when no step inside the box is found.
/// Converged: |da| below kTolerance a or the residual's round-off, about 1e-15 (I1_tr - L_n).
Step newton_step(const Model& m, double q_trial, const Hardening& s, const CapMoves& moves,
                 const CapBox& box, Iterate& x) {
    const double a_trial = box.a_trial;
    double a = x.a;
    double dk = x.dk;
    const CapMove& c = x.c;
    const Change d = centre_change(m.p, s, dk);
    const CapResidual r = cap_residual(m, q_trial, a, c);
    const double r1 = a_trial - d.d - 3.0 * m.bulk * c.dv - a;
    const double j12 = -d.slope - 3.0 * m.bulk * c.rate; // dr1/da = -1
    const double det = -r.g_k - j12 * r.g_a;
    if (!(det != 0.0)) {
        return Step::failed;
    }
    const double inverse = 1.0 / det;
    double da = (r1 * r.g_k - j12 * r.g) * inverse;
    double ddk = (-r.g - r.g_a * r1) * inverse;
    int cuts = 0;
    for (; !(a - da >= 0.0 && a - da <= a_trial && dk - ddk >= 0.0 && dk - ddk <= box.dk_max);
         ++cuts) {
        if (cuts == kMaxStepCuts) {
            return Step::failed;
        }
        da *= 0.5;
        ddk *= 0.5;
    }
    a -= da;
    dk -= ddk;
    const double last = x.step;
    x = iterate_at(moves, a, dk);
    const double step = std::max(std::abs(da) / (kTolerance * a + kRoundOff * a_trial),
                                 std::abs(ddk) / (kTolerance * box.dk_max));
    if (cuts == 0) {
        x.step = step;
    }
    // Converged when this step was within the bounds, or when the quadratic rate of the last two
    // full steps predicts that the next one would move the iterate by round-off only.
    return step <= 1.0 || (cuts == 0 && predicted_step(last, step) <= kNegligibleStep)
               ? Step::converged
               : Step::more;
}

/// Newton on the cap equations from the start (a, dk) passed in, newton_step after
/// newton_step; false when a step fails or kMaxNewtonIterations do not converge.
bool cap_newton(const Model& m, double q_trial, const Hardening& s, const CapMoves& moves,
                const CapBox& box, Iterate& x) {
    for (int iteration = 0; iteration < kMaxNewtonIterations; ++iteration) {
        const Step step = newton_step(m, q_trial, s, moves, box, x);
        if (step != Step::more) {
            return step == Step::converged;
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
bool corner_start(const Model& m, double q_trial, const Hardening& s, const CapMoves& moves,
                  const CapBox& box, Iterate& x) {
    const double rate = centre_change(m.p, s, 0.0).slope + 3.0 * m.bulk * moves.start_rate();
    const double dk_start = box.a_trial / rate;
    if (!(dk_start > 0.0 && dk_start <= box.dk_max)) {
        return false;
    }
    const CapMove c = moves(dk_start);
    const double ratio = 3.0 * q_trial / (m.shear * m.p.R * c.dv);
    const double a_start = m.p.R * c.b / std::sqrt(1.0 + ratio * ratio);
    if (!(a_start > 0.0 && a_start < kNearCorner * box.a_trial)) {
        return false;
    }
    x = {a_start, dk_start, c};
    return true;
}

/// a(dk) = (I1_tr - L_n) - dL(dk) - 3K dv(dk): the volumetric balance solved for a.
double balance_gap(const Model& m, const Hardening& s, const CapMoves& moves, double a_trial,
                   double dk) {
    return a_trial - centre_change(m.p, s, dk).d - 3.0 * m.bulk * moves(dk).dv;
}

/// A start for cap_newton where the one from the trial fails. The volumetric balance gives a
/// explicitly, a(dk), so the cap condition reduces to h(dk) = g(a(dk), kappa_n + dk) on
/// [0, dk_centre]: h(0) > 0 (the trial is outside the cap) and h(dk_centre) = -R B <= 0 (a = 0,
/// rho = 0). For a trial far above the envelope, R^2 q_tr^2 > (a + R B)^2 makes g decrease with
/// a and h rise from dk = 0, so Newton from the trial heads out of the box (the thesis sand at
/// full stiffness: 94 % of its cap returns). The bracketed solve on h does not care; it only
/// has to get near the root, from where cap_newton converges in a few steps to the coupled
/// equations' tolerance. Returns false when the centre shift is infeasible.
bool cap_reduced_start(const Model& m, double q_trial, const Hardening& s, const CapMoves& moves,
                       double a_trial, const Shift& centre, double& a, double& dk) {
    if (!centre.feasible || !(centre.dk > 0.0)) {
        return false;
    }
    const auto reduced = [&](double dk_try, double& h, double& dh) {
        const CapMove c = moves(dk_try);
        const Change d = centre_change(m.p, s, dk_try);
        const double slope = -d.slope - 3.0 * m.bulk * c.rate; // da/dkappa
        const CapResidual r =
            cap_residual(m, q_trial, std::max(a_trial - d.d - 3.0 * m.bulk * c.dv, 0.0), c);
        h = r.g;
        dh = r.g_a * slope + r.g_k;
    };
    dk = solve_bracketed(reduced, 0.0, centre.dk, kStartTolerance * centre.dk).value;
    a = std::max(balance_gap(m, s, moves, a_trial, dk), 0.0);
    return true;
}

/// The nested, bracketed cap solve (the safe path): the unknown a in [0, I1_tr - L_n]; for each
/// a the move dk solves the volumetric balance a(dk) = a on [0, dk_centre]. Returns (a, dk).
std::pair<double, double> cap_nested(const Model& m, double q_trial, const Hardening& s,
                                     const CapMoves& moves, double a_trial, const Shift& centre) {
    const double dk_max = centre.dk; // a = 0 bounds dk
    const double tolerance = kTolerance * dk_max;
    double last_dk = std::numeric_limits<double>::quiet_NaN(); // warm start
    const auto move_for = [&](double a_try) {
        const auto balance = [&](double dk_try, double& g, double& dg) {
            const CapMove c = moves(dk_try);
            const Change d = centre_change(m.p, s, dk_try);
            g = a_trial - d.d - 3.0 * m.bulk * c.dv - a_try;
            dg = -d.slope - 3.0 * m.bulk * c.rate;
        };
        last_dk = solve_bracketed(balance, 0.0, dk_max, tolerance, 0.0, last_dk).value;
        return last_dk;
    };
    const auto fn = [&](double a_try, double& g, double& dg) {
        const double dk_try = move_for(a_try);
        const CapMove c = moves(dk_try);
        const Change d = centre_change(m.p, s, dk_try);
        const CapResidual r = cap_residual(m, q_trial, a_try, c);
        g = r.g;
        dg = r.g_a - r.g_k / (d.slope + 3.0 * m.bulk * c.rate);
    };
    const double a = solve_bracketed(fn, 0.0, a_trial, 0.0, kTolerance).value;
    return {a, move_for(a)};
}

/// The return at the converged iterate: stress invariants, hardening and the Jacobian of
/// (I1, rho) for the consistent tangent. Written into `r` in place (a Return passed back by
/// value was copied from the stack over stores the processor could not forward).
void cap_finish(const Model& m, double q_trial, const Hardening& s, double l_n, const Iterate& x,
                Return& r) {
    const double a = x.a;
    const double dk = x.dk;
    const CapMove& c = x.c;
    const Change d = centre_change(m.p, s, dk);
    const CapResidual res = cap_residual(m, q_trial, a, c);
    r = finish(PlasticRegion::cap, l_n + d.d + a, res.rho, {s.x + c.dx, s.kappa + dk}, c.dv);
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
}

} // namespace

/// Cap return with the unknown a = I1 - L in [0, I1_tr - L_n]; for each a the move dk of kappa
/// solves the volumetric balance (I1_tr - L_n) - dL(dk) - 3K dv(dk) = a, (4.6.3.35)-(4.6.3.37).
/// Solving for a rather than L resolves returns that end next to the corner (a ~ R^2, tiny for
/// small R) and trials within round-off of I1_tr = L_n. cap_newton is tried from corner_start
/// where that applies, then from the trial, then from cap_reduced_start; the nested, bracketed
/// solve is the safe path left when all fail.
Return cap_return(const Model& m, double i1_trial, double q_trial, const Hardening& s,
                  const StateTerms& terms) {
    const double l_n = cap_center(m.p, s.kappa);
    const CapBox box = cap_box(i1_trial, l_n, s);
    const CapMoves moves(m.p, s, terms);
    Iterate x;
    bool converged =
        corner_start(m, q_trial, s, moves, box, x) && cap_newton(m, q_trial, s, moves, box, x);
    if (!converged) {
        x = iterate_at(moves, box.a_trial, 0.0);
        converged = cap_newton(m, q_trial, s, moves, box, x);
    }
    std::optional<Shift> centre; // solved once, for the reduced start and the nested solve
    double a = 0.0;
    double dk = 0.0;
    if (!converged) {
        centre = shift_to(m, i1_trial, s, Target::centre);
        if (cap_reduced_start(m, q_trial, s, moves, box.a_trial, *centre, a, dk)) {
            x = iterate_at(moves, a, dk);
            converged = cap_newton(m, q_trial, s, moves, box, x);
        }
    }
    if (!(converged && x.a >= kResolvedGap * box.a_trial)) {
        if (!centre) {
            centre = shift_to(m, i1_trial, s, Target::centre);
        }
        std::tie(a, dk) = cap_nested(m, q_trial, s, moves, box.a_trial, *centre);
        x = iterate_at(moves, a, dk);
    }
    Return r;
    cap_finish(m, q_trial, s, l_n, x, r);
    return r;
}

void cap_returns(const Model& m, std::span<const double> i1_trial, std::span<const double> q_trial,
                 std::span<const Hardening> states, std::span<const StateTerms> terms,
                 std::span<const int> points, std::span<Return> returns) {
    // Each lane is built where it lies (members initialised in place, the start written into
    // it): lanes assembled on the stack and copied were read back over stores the processor
    // could not forward.
    struct Lane {
        Lane(const Model& m, int k, double i1_trial, const Hardening& s, const StateTerms& terms)
            : point(k), l_n(cap_center(m.p, s.kappa)), box(cap_box(i1_trial, l_n, s)),
              moves(m.p, s, terms) {}
        int point;
        double l_n;
        CapBox box;
        CapMoves moves;
        Iterate x;
        Step step = Step::more;
    };
    thread_local std::vector<Lane> lanes; // kept between calls, as GeneralizedCap's buffers
    lanes.clear();
    for (const int k : points) {
        Lane& l = lanes.emplace_back(m, k, i1_trial[k], states[k], terms[k]);
        if (!corner_start(m, q_trial[k], states[k], l.moves, l.box, l.x)) {
            lanes.pop_back();
            returns[k] = cap_return(m, i1_trial[k], q_trial[k], states[k], terms[k]);
        }
    }
    bool iterating = !lanes.empty();
    for (int iteration = 0; iteration < kMaxNewtonIterations && iterating; ++iteration) {
        iterating = false;
        for (Lane& l : lanes) {
            if (l.step == Step::more) {
                l.step = newton_step(m, q_trial[l.point], states[l.point], l.moves, l.box, l.x);
                iterating = iterating || l.step == Step::more;
            }
        }
    }
    for (const Lane& l : lanes) {
        const int k = l.point;
        // What cap_return would do after the same iterations; the others take its whole chain,
        // which repeats these iterations and goes on to the next start.
        if (l.step == Step::converged && l.x.a >= kResolvedGap * l.box.a_trial) {
            cap_finish(m, q_trial[k], states[k], l.l_n, l.x, returns[k]);
        } else {
            returns[k] = cap_return(m, i1_trial[k], q_trial[k], states[k], terms[k]);
        }
    }
}

} // namespace grainload::materials::cap
