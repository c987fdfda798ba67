#include "materials/cap_return.hpp"

#include "materials/cap_moves.hpp"
#include "materials/cap_region.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace grainload::materials::cap {
namespace {

double tolerance_for(const Model& m, double i1_trial, double q_trial, const Hardening& s) {
    return kTolerance * (std::abs(i1_trial) + q_trial + std::abs(s.kappa) + std::abs(m.p.k) + 1.0);
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
    const CapMove c = CapMoves(m.p, s)(shift.dk);
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

/// Which return a trial takes (thesis 4.6.3, "Algorithm"; docs/theory/generalized_cap.md).
enum class Route { elastic, tension, failure, cap, flat_top };

/// `terms` receives the state's terms (cap_moves.hpp) where the route is the cap's.
Route route(const Model& m, double i1_trial, double q_trial, const Hardening& state,
            StateTerms& terms) {
    if (in_tension_region(m, i1_trial, q_trial, state)) {
        return Route::tension;
    }
    const double l = cap_center(m.p, state.kappa);
    if (i1_trial > l) {
        // half_height(p, kappa) from the envelope the cap's moves also start from.
        terms.envelope = envelope(m.p, state.kappa);
        const double b = centre_clamped(m.p, state.kappa)
                             ? std::max(0.0, state.kappa / m.p.R + terms.envelope)
                             : terms.envelope;
        const double a = i1_trial - l;
        const double fc = a * a + m.p.R * m.p.R * (q_trial * q_trial - b * b);
        if (!(fc > 0.0)) {
            return Route::elastic;
        }
        // A locked cap (exp(-D (X - X0)) = 0: eps_v^p = W) follows the stress elastically
        // (dv = 0); above the envelope only the failure surface can flow.
        terms.decay = hardening_decay(m.p, state.x);
        return !(terms.decay > 0.0) && q_trial > envelope(m.p, i1_trial) ? Route::failure
                                                                         : Route::cap;
    }
    if (centre_clamped(m.p, state.kappa) && q_trial > half_height(m.p, state.kappa) &&
        i1_trial >= corner_point(m.p, state.kappa, m.i1_min).i1) {
        return Route::flat_top;
    }
    return q_trial > envelope(m.p, i1_trial) ? Route::failure : Route::elastic;
}

/// The elastic step's "return" written in place: the trial itself, the state unchanged. A
/// Return built on the stack and copied was stored in pieces of 4 and 8 bytes and read back
/// in 16-byte ones the processor cannot forward, a third of the routing's time.
void elastic(double i1_trial, const Hardening& state, Return& out) {
    out = Return{};
    out.i1 = i1_trial;
    out.hardening = state;
}

/// The return of the route taken; `terms` as route() left them.
Return along(Route route, const Model& m, double i1_trial, double q_trial, const Hardening& state,
             const StateTerms& terms) {
    switch (route) {
    case Route::tension:
        return tension_return(m, i1_trial, q_trial, state);
    case Route::failure:
        return failure_return(m, i1_trial, q_trial, state);
    case Route::cap:
        return m.p.R == 0.0 ? flat_cap(corner_return(m, i1_trial, q_trial, state), q_trial, m.p)
                            : cap_return(m, i1_trial, q_trial, state, terms);
    case Route::flat_top:
        return flat_top_return(m, i1_trial, q_trial, state);
    case Route::elastic:
        break;
    }
    Return r;
    elastic(i1_trial, state, r);
    return r;
}

} // namespace

Return return_map(const Model& m, double i1_trial, double q_trial, const Hardening& state) {
    StateTerms terms;
    const Route r = route(m, i1_trial, q_trial, state, terms);
    return along(r, m, i1_trial, q_trial, state, terms);
}

void return_map_many(const Model& m, std::span<const double> i1_trial,
                     std::span<const double> q_trial, std::span<const Hardening> states,
                     std::span<Return> returns) {
    thread_local std::vector<int> caps; // kept between calls, as GeneralizedCap's buffers
    thread_local std::vector<StateTerms> terms;
    caps.clear();
    terms.resize(returns.size());
    for (std::size_t k = 0; k < returns.size(); ++k) {
        const Route r = route(m, i1_trial[k], q_trial[k], states[k], terms[k]);
        if (r == Route::cap && m.p.R > 0.0) {
            caps.push_back(static_cast<int>(k));
        } else if (r == Route::elastic) {
            elastic(i1_trial[k], states[k], returns[k]);
        } else {
            returns[k] = along(r, m, i1_trial[k], q_trial[k], states[k], terms[k]);
        }
    }
    cap_returns(m, i1_trial, q_trial, states, terms, caps, returns);
}

} // namespace grainload::materials::cap
