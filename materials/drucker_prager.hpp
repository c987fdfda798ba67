#pragma once
// The perfectly plastic Drucker-Prager material: non-associated flow and a tension cutoff.

#include "materials/drucker_prager_return.hpp"
#include "materials/material.hpp"

#include <memory>

namespace grainload::materials {

/// Perfectly plastic Drucker-Prager model with non-associated flow and a tension cutoff.
///
/// Yield:     f = sqrt(J2) + alpha I1 - k <= 0     (thesis 4.6.3.1 with tension-positive I1:
///                                                 the thesis's theta is alpha)
/// Potential: g = sqrt(J2) + alpha_flow I1          (alpha_flow from the dilatancy angle)
/// Cutoff:    f_t = I1 - T <= 0, associated flow    (thesis section 4.6.3, line I1 = T)
///
/// The invariant is sqrt(J2) = ||s|| / sqrt(2); constants fitted against ||s|| differ by sqrt 2.
/// The return map is closed form (the model is perfectly plastic, so each region's equation is
/// linear) with three regions: the cone, the cutoff plane, and their intersection circle, which
/// is the apex itself when T is at the apex (the default); materials/drucker_prager_return.hpp
/// holds it. Derivation and consistent tangents in docs/theory/materials.md.
///
/// State per point: equivalent plastic strain sqrt(2/3)||e_p||, plastic volumetric strain.
class DruckerPrager final : public Material {
  public:
    using Parameters = DruckerPragerCone;

    /// A cutoff above the apex k/alpha is clamped to it; infinity with alpha > 0 means the apex.
    DruckerPrager(ElasticConstants elastic, Parameters parameters);

    std::string_view model() const override { return "drucker_prager"; }
    int state_size() const override { return 2; }
    std::vector<std::string> state_names() const override;
    PlasticRegion update(const Voigt6& strain_increment, Voigt6& stress, std::span<double> state,
                         Matrix6* tangent) const override;
    double equivalent_plastic_strain(std::span<const double> state) const override;

    const Parameters& parameters() const { return parameters_; }
    /// f = sqrt(J2) + alpha I1 - k at a stress.
    double yield_function(const Voigt6& stress) const;

  private:
    Parameters parameters_;
};

} // namespace grainload::materials
