#pragma once
// The generalized cap's return onto its elliptical cap.

#include "materials/cap_moves.hpp"
#include "materials/cap_values.hpp"

#include <span>

// The return onto the elliptical cap (R > 0), thesis (4.6.3.31)-(4.6.3.37): the unknown a = I1 - L
// and the move dk of the hardening parameter, solved by Newton from a start next to the corner,
// from the trial or from a reduced solve, with a nested bracketed solve as the safe path
// (docs/theory/generalized_cap.md, "Cap return"). Compression positive.
namespace grainload::materials::cap {

/// The cap return of one point whose trial lies outside the elliptical cap (R > 0); `terms` are
/// its state_terms (cap_moves.hpp), which the routing has formed.
Return cap_return(const Model& m, double i1_trial, double q_trial, const Hardening& s,
                  const StateTerms& terms);

/// cap_return for the points listed, bit for bit. The returns that start next to the corner (the
/// compacting points of a granular flow) take their Newton iterations in lockstep, one point's
/// after another's: each iteration is a chain of exponentials and divisions that waits on
/// itself, and the processor runs the next point's chain while one point's waits.
/// terms[k] are point k's state_terms (cap_moves.hpp), which the routing has formed.
void cap_returns(const Model& m, std::span<const double> i1_trial, std::span<const double> q_trial,
                 std::span<const Hardening> states, std::span<const StateTerms> terms,
                 std::span<const int> points, std::span<Return> returns);

} // namespace grainload::materials::cap
