#pragma once
// The perfectly plastic Mohr-Coulomb material in 3D: the hexagonal cone itself, corners and apex
// returned exactly.

#include "materials/drucker_prager_return.hpp"
#include "materials/material.hpp"
#include "materials/mohr_coulomb_return.hpp"

#include <memory>

namespace grainload::materials {

/// Perfectly plastic Mohr-Coulomb material with non-associated flow (yield and potential of
/// MohrCoulombSurface). Unlike the Drucker-Prager cones, which agree with the hexagon on one
/// meridian or in plane strain only (materials/cone_fit.hpp), it has the Mohr-Coulomb strength
/// on every Lode angle: triaxial compression, extension and plane strain at once. The corners
/// are not rounded: the return map is the exact multi-surface one in principal stresses
/// (materials/mohr_coulomb_return.hpp), with the stress rebuilt on the trial's principal
/// directions, and its consistent tangent is the derivative of that isotropic function.
///
/// A trial inside the inscribed Drucker-Prager cone (materials/cone_fit.hpp, `inner`) lies
/// inside the hexagon: it is taken as elastic without the spectral decomposition.
///
/// State per point as DruckerPrager: the accumulated equivalent plastic strain
/// sum sqrt(2/3) ||dev d eps_p|| and the plastic volumetric strain.
class MohrCoulomb final : public Material {
  public:
    struct Parameters {
        double friction_angle = 0.0;  ///< phi, rad, 0 < phi < pi/2
        double cohesion = 0.0;        ///< c, Pa
        double dilatancy_angle = 0.0; ///< psi, rad, 0 <= psi <= phi
    };

    MohrCoulomb(ElasticConstants elastic, Parameters parameters);

    std::string_view model() const override { return "mohr_coulomb"; }
    int state_size() const override { return 2; }
    std::vector<std::string> state_names() const override;
    PlasticRegion update(const Voigt6& strain_increment, Voigt6& stress, std::span<double> state,
                         Matrix6* tangent) const override;
    double equivalent_plastic_strain(std::span<const double> state) const override;

    const Parameters& parameters() const { return parameters_; }
    const MohrCoulombSurface& surface() const { return surface_; }
    /// f of the hexagon at a stress (its principal values sorted first).
    double yield_function(const Voigt6& stress) const;

  private:
    Parameters parameters_;
    MohrCoulombSurface surface_;
    DruckerPragerCone inscribed_;
};

} // namespace grainload::materials
