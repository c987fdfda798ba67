#pragma once
// The perfectly plastic Drucker-Prager material: non-associated flow and a tension cutoff.

#include "io/key_spec.hpp"
#include "materials/drucker_prager_return.hpp"
#include "materials/material.hpp"

#include <array>
#include <memory>

namespace grainload::materials {

/// The keys of a [[material]] with model = "drucker_prager" besides density and the elastic
/// pair: one of two forms, the Mohr-Coulomb angles with a cone fit, or the cone's own constants.
inline constexpr std::array<io::KeySpec, 8> kDruckerPragerKeys{{
    {"friction_angle", "angle", "required in form 1", "φ, 0 ≤ φ < 90°"},
    {"cohesion", "pressure", "required in form 1", "c ≥ 0"},
    {"dilatancy_angle", "angle", "required in form 1", "ψ, 0 ≤ ψ ≤ φ; ψ = φ is associated"},
    {"cone_fit", "string", "required in form 1",
     "`plane_strain`, `compression`, `extension` or `inner`: which Mohr-Coulomb angle the cone "
     "reproduces"},
    {"dp_k", "pressure", "required in form 2", "k of thesis 4.6.3.1"},
    {"dp_theta", "number", "required in form 2", "θ of thesis 4.6.3.1"},
    {"dp_theta_flow", "number", "`dp_theta`", "θ of the plastic potential, 0 ≤ θ_flow ≤ θ"},
    {"tension_cutoff", "pressure", "the apex k/α",
     "T: the limit on I1 = σ_xx + σ_yy + σ_zz (not on the mean stress)"},
}};

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
    /// Keys, one of two forms plus the elastic keys:
    ///  - friction_angle, cohesion, dilatancy_angle, cone_fit = plane_strain|compression|
    ///    extension|inner;
    ///  - dp_k (pressure), dp_theta (number), optional dp_theta_flow (default dp_theta).
    /// Optional tension_cutoff (pressure, the limit on I1; default the apex).
    static std::unique_ptr<DruckerPrager> from_case(const io::CaseTable& table);

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
