#pragma once
// Moves of the generalized cap's hardening parameter shared by its returns.

#include "materials/cap_values.hpp"

#include <algorithm>
#include <cmath>

// Moves of the cap's hardening parameter kappa shared by the returns of cap_return.cpp: the
// shift of X and the plastic volumetric strain of the hardening law for a move dk, the moves of
// the centre L(kappa) and of the corner c(kappa), the contraction after dilatant flow, and the
// move that puts the stress at the corner or at the centre. Compression positive.
namespace grainload::materials::cap {

// Relative tolerance of the scalar solves; far below the 1e-8 step-independence and 1e-5
// tangent checks, and a few ulps above round-off of the residuals.
inline constexpr double kTolerance = 1e-14;

/// The cap moved from the state (kappa_n, X_n) by dk: its shift dX, the plastic volumetric
/// strain dv of the hardening law (4.6.3.4) and d(dv)/d(dk) (4.6.3.5), all written as increments
/// (expm1) so that moves far below the ulp of kappa stay resolved and a locked state
/// (exp(-D (X_n - X0)) = 0) gives dv = 0 without a logarithm; and the half-height B and
/// dB/dkappa at kappa_n + dk, which share the move's exponential.
struct CapMove {
    double dx = 0.0;
    double dv = 0.0;
    double rate = 0.0;
    double b = 0.0;
    double b_slope = 0.0;
};

/// The state's exponential terms: exp(-D (X_n - X0)) and F(kappa_n). The return's routing
/// needs them too (the half-height and whether the cap is locked), and hands them on.
struct StateTerms {
    double decay = 0.0;
    double envelope = 0.0;
};
StateTerms state_terms(const Parameters& p, const Hardening& s);

/// The moves of one state's cap. exp(-D (X_n - X0)), exp(-B1 kappa_n) and expm1(-B1 kappa_n)
/// are formed once, and every exponential at the moved cap is written through them: a move
/// costs two expm1 (of -B1 dk and of -D dX) where forming each term afresh took eight, which
/// was half of a cap return's time. States whose exponentials leave the normal range, and
/// contractions by more than 1/B1, take the direct form.
class CapMoves {
  public:
    CapMoves(const Parameters& p, const Hardening& s, const StateTerms& terms);
    CapMoves(const Parameters& p, const Hardening& s) : CapMoves(p, s, state_terms(p, s)) {}
    CapMove operator()(double dk) const;
    /// d(dv)/d(dk) at dk = 0, as operator()(0.0) gives it, without its exponentials.
    double start_rate() const;

  private:
    CapMove direct(double dk) const;

    const Parameters& p_;
    Hardening s_;
    double decay_n_;    ///< exp(-D (X_n - X0))
    double shifted_;    ///< gamma exp(-B1 kappa_n)
    double curved_;     ///< gamma B1 exp(-B1 kappa_n)
    double envelope_n_; ///< k - gamma + theta kappa_n - gamma expm1(-B1 kappa_n) = F(kappa_n)
    bool fast_;
};

// Inline: the Newton steps of the cap call it once each, and the call's spills cost about as
// much as its arithmetic.
inline CapMove CapMoves::operator()(double dk) const {
    const double arg = -p_.beta * dk;
    if (!fast_ || !(arg < 1.0)) {
        return direct(dk);
    }
    // With m = expm1(-B1 dk): exp(-B1 kappa) = exp(-B1 kappa_n) (1 + m), so F(kappa) - F(kappa_n)
    // = theta dk - gamma exp(-B1 kappa_n) m, the term the shift dX already holds.
    const double m = std::expm1(arg);
    const double change = p_.theta * dk - shifted_ * m;
    CapMove c;
    c.dx = dk + p_.R * change;
    const double dm = std::expm1(-p_.D * c.dx);
    const double decay = decay_n_ + decay_n_ * dm; // exp(-D (X_n + dX - X0))
    const double f = envelope_n_ + change;
    const double f_slope = p_.theta + (curved_ + curved_ * m);
    c.dv = -p_.W * decay_n_ * dm;
    c.rate = p_.W * p_.D * decay * (1.0 + p_.R * f_slope);
    const double kappa = s_.kappa + dk;
    const bool clamped = centre_clamped(p_, kappa);
    c.b = clamped ? std::max(0.0, kappa / p_.R + f) : f;
    c.b_slope = clamped ? 1.0 / p_.R + f_slope : f_slope;
    return c;
}

/// Change of the cap centre L(kappa) = max(kappa, 0) (MAT_025) or kappa when kappa moves by dk,
/// and dL/dkappa at the end. Where the centre is kappa on both ends the change is dk itself,
/// so moves far below the ulp of L stay resolved.
struct Change {
    double d = 0.0;
    double slope = 1.0;
};
inline Change centre_change(const Parameters& p, const Hardening& s, double dk) {
    const double kappa = s.kappa + dk;
    if (!centre_clamped(p, s.kappa) && !centre_clamped(p, kappa)) {
        return {dk, 1.0};
    }
    return {cap_center(p, kappa) - cap_center(p, s.kappa), cap_center_slope(p, kappa)};
}
/// Change of the corner I1, c(kappa), when kappa moves by dk (dk itself where c = kappa).
Change corner_change(const Model& m, const Hardening& s, double corner_n, double dk);

/// Hardening after a dilatant flow (volumetric plastic strain dv < 0): the cap contracts by
/// inverting (4.6.3.4), thesis (4.6.3.8), but kappa not below `floor` (the hardening whose corner
/// is the stress point, or the lowest one); the new state, the plastic volumetric strain the
/// hardening law records and whether the floor stopped it.
struct Contraction {
    Hardening after;
    double dv = 0.0;
    bool floored = false;
};
Contraction contract_cap(const Model& m, const Hardening& s, double dv, double floor);

/// Shift dk of kappa that puts the stress at I1 = P(kappa), where P is the corner c(kappa)
/// (failure-surface side) or the centre L(kappa) (a = 0, the end of the cap's bracket); both
/// are kappa where the centre is not clamped. The volumetric balance (4.6.3.43) reads
/// g(dk) = (I1_tr - P_n) - dP(dk) - 3K dv(dk) = 0, decreasing in dk. Infeasible when that point
/// lies below I1_min.
struct Shift {
    bool feasible = false;
    double dk = 0.0;
    double slope = -1.0; ///< g'(dk)
};
enum class Target { corner, centre };
Shift shift_to(const Model& m, double i1_trial, const Hardening& s, Target target);

} // namespace grainload::materials::cap
