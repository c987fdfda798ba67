#pragma once
// The elasto-viscoplastic mu(I) material: a Drucker-Prager return on the cone of mu(I).

#include "materials/drucker_prager_return.hpp"
#include "materials/material.hpp"
#include "materials/mu_i_law.hpp"
#include "materials/nonlocal_fluidity.hpp"

#include <memory>

namespace grainload::materials {

/// Elasto-viscoplastic mu(I) material (Jop, Forterre & Pouliquen 2006): the Drucker-Prager
/// return of drucker_prager_return.hpp on the cone sqrt(J2) = mu p, whose friction
/// mu = mu(I) is evaluated with the step's strain rate and trial pressure:
///
///     alpha = mu(I) / 3,  k = 0,  alpha_flow = 0 (isochoric flow),  cutoff at the apex I1 = 0,
///
/// the cone of Jop et al.'s |tau| = mu(I) P, which in plane strain is the plane_strain cone
/// fit of a cohesionless, non-dilatant Mohr-Coulomb material with sin(phi) = mu. At rest (zero
/// shear rate) I = 0 and mu = mu_s exactly, so the update is, bit for bit, that of the
/// DruckerPrager material {mu_s / 3, 0, 0}: same elastic predictor, same return, no creep. The
/// tangent is the cone's at the step's mu (it leaves out d mu / d eps). Equations, the cone in
/// 3D and in plane strain, and the known limits of the law in docs/theory/mu_i.md.
///
/// State per point as DruckerPrager (equivalent plastic strain, plastic volumetric strain), then
/// the inertial number of the last step: I where the trial stress reached the static cone, 0
/// where the step stayed inside it (elastic whatever its rate), NaN where p <= 0 (undefined).
/// The frames show it (`inertial_number`): where the flow is quasi-static (I < 1e-3), dense
/// (1e-3 to 0.1) or collisional (I > 0.1; GDR MiDi 2004).
///
/// With a non-local amplitude A the flow is that of the non-local granular fluidity instead
/// (materials/nonlocal_fluidity.hpp): the deviatoric stress relaxes at the plastic rate
/// gamma_dot^p = g mu of the point's fluidity, two more state entries carry the fluidity and
/// its non-local excess, and the frames show the fluidity too. At rest (g = 0 at every point)
/// it is the same Drucker-Prager solid.
class MuIMaterial final : public Material {
  public:
    /// nonlocal_amplitude 0: the local law.
    MuIMaterial(ElasticConstants elastic, MuILaw law, double nonlocal_amplitude = 0.0);

    /// The cone of a friction coefficient mu: {mu / 3, 0, 0, 0}.
    static DruckerPragerCone cone(double mu);

    std::string_view model() const override { return "mu_i"; }
    int state_size() const override { return fluidity_.amplitude > 0.0 ? 5 : 3; }
    std::vector<std::string> state_names() const override;
    /// The quasi-static limit: update_over() with an infinite time step, I = 0, mu = mu_s.
    PlasticRegion update(const Voigt6& strain_increment, Voigt6& stress, std::span<double> state,
                         Matrix6* tangent) const override;
    PlasticRegion update_over(const Voigt6& strain_increment, double time_step, Voigt6& stress,
                              std::span<double> state, Matrix6* tangent) const override;
    double equivalent_plastic_strain(std::span<const double> state) const override;
    std::vector<StateField> frame_state() const override;

    const MuILaw& law() const { return law_; }
    const NonlocalFluidity* nonlocal_fluidity() const override {
        return fluidity_.amplitude > 0.0 ? &fluidity_ : nullptr;
    }

  private:
    MuILaw law_;
    NonlocalFluidity fluidity_;
};

} // namespace grainload::materials
