#pragma once
// Von Mises elasto-plasticity with mixed linear isotropic/kinematic hardening.

#include "materials/material.hpp"

#include <memory>

namespace grainload::materials {

/// Von Mises elasto-plasticity with mixed linear isotropic/kinematic hardening (thesis
/// section 4.6.2; Kojic & Bathe, "Inelastic Analysis of Solids and Structures", ch. 4).
///
/// Yield function f = sqrt(3/2) ||s - xi|| - sigma_y (4.6.2.5, 4.6.2.16) with back stress xi and
/// sigma_y = sigma_0 + beta E_p eps_p (4.6.2.17), E_p = E E_T / (E - E_T) (4.6.2.1). beta = 1 is
/// purely isotropic, beta = 0 purely kinematic hardening. The return is the exact radial return
/// (4.6.2.28-4.6.2.30); the tangent is the consistent one (docs/theory/materials.md).
///
/// State per point: back stress (6, stress-like Voigt), equivalent plastic strain (1).
class VonMises final : public Material {
  public:
    VonMises(ElasticConstants elastic, double yield_stress, double tangent_modulus, double beta);

    std::string_view model() const override { return "von_mises"; }
    int state_size() const override { return 7; }
    std::vector<std::string> state_names() const override;
    PlasticRegion update(const Voigt6& strain_increment, Voigt6& stress, std::span<double> state,
                         Matrix6* tangent) const override;
    double equivalent_plastic_strain(std::span<const double> state) const override;

    double yield_stress() const { return yield_stress_; }
    double plastic_modulus() const { return plastic_modulus_; }
    double beta() const { return beta_; }
    /// Current yield stress sigma_0 + beta E_p eps_p of a point with this state.
    double current_yield_stress(std::span<const double> state) const;

  private:
    Matrix6 plastic_tangent(const Voigt6& unit_normal, double trial_equivalent,
                            double multiplier) const;

    double yield_stress_;
    double plastic_modulus_;
    double beta_;
};

} // namespace grainload::materials
