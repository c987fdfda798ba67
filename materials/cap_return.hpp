#pragma once
// The generalized cap's return mapping in the invariant plane.

#include "materials/cap_values.hpp"

#include <span>

// Backward-Euler return mapping of the generalized cap model in the invariant plane
// (I1, sqrt(J2)), compression positive. Every region reduces to one scalar equation g(u) = 0
// (derivations in docs/theory/generalized_cap.md); the deviator is always scaled radially,
// s = rho s_trial, because every flow direction is coaxial with s.
namespace grainload::materials::cap {

Return return_map(const Model& model, double i1_trial, double q_trial, const Hardening& state);

/// return_map of several points, bit for bit; the cap returns iterate together (cap_region.hpp).
void return_map_many(const Model& model, std::span<const double> i1_trial,
                     std::span<const double> q_trial, std::span<const Hardening> states,
                     std::span<Return> returns);

} // namespace grainload::materials::cap
