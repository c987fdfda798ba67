#pragma once
// The generalized cap model (Sandler-DiMaggio-Baladi), integrated fully implicitly.

#include "materials/cap_return.hpp"
#include "materials/material.hpp"

#include <memory>
#include <string>
#include <utility>

namespace grainload::materials {

/// Generalized cap model (Sandler-DiMaggio-Baladi; algorithm after Sandler & Rubin as given
/// by Kojic & Bathe; thesis section 4.6.3; initial cap and centre as LS-DYNA's MAT_025 unless
/// cap_semantics = "lifted_x0"), integrated fully implicitly (backward Euler) with the cap
/// hardening coupled and an analytic consistent tangent in every region.
///
/// The model is written compression positive (I1 = tr sigma > 0 in compression, sqrt(J2) of the
/// deviator) as in its sources; update() converts from the tension-positive convention of
/// io/types.hpp at entry and back at exit. State per point (names as in state_names()):
///   0 cap_position              X [Pa], where the cap meets the I1 axis (MAT_025 PLOT = 2)
///   1 hardening_parameter       kappa [Pa], X = kappa + R F(kappa); the centre is
///                               L = max(kappa, 0) (MAT_025) or kappa (MAT_025 PLOT = 1)
///   2 plastic_volumetric_strain eps_v^p of the hardening law, COMPACTION positive (PLOT = 3)
///   3 equivalent_plastic_strain sqrt(2/3 deps^p : deps^p), accumulated
class GeneralizedCap final : public Material {
  public:
    enum StateIndex : int {
        kCapPosition = 0,
        kHardeningParameter = 1,
        kPlasticVolumetricStrain = 2,
        kEquivalentPlasticStrain = 3,
    };

    /// Throws std::invalid_argument when the parameters admit no elastic region.
    GeneralizedCap(ElasticConstants elastic, cap::Parameters parameters);

    /// Key and message of the first inadmissible parameter; empty key when all are valid.
    static std::pair<std::string, std::string> check(const cap::Parameters& parameters);

    std::string_view model() const override { return "generalized_cap"; }
    int state_size() const override { return 4; }
    std::vector<std::string> state_names() const override;
    void initialise_state(std::span<double> state) const override;
    PlasticRegion update(const Voigt6& strain_increment, Voigt6& stress, std::span<double> state,
                         Matrix6* tangent) const override;
    /// The points' returns through cap::return_map_many: bit for bit as update(). The model is
    /// rate-independent: the time step is not used.
    void update_points(std::span<const Voigt6> strain_increments, double time_step,
                       std::span<Voigt6> stresses, std::span<double* const> states,
                       std::span<PlasticRegion> regions) const override;
    double equivalent_plastic_strain(std::span<const double> state) const override;

    const cap::Parameters& parameters() const { return model_.p; }

  private:
    /// Trial invariants of one point, compression positive.
    struct Trial {
        Voigt6 deviator;
        double i1 = 0.0;
        double q = 0.0;
    };
    /// Written into `t` in place: a Trial returned by value was built on the stack and copied
    /// in 16-byte pieces over its 8-byte stores, which the processor cannot forward.
    void trial(const Voigt6& strain_increment, const Voigt6& stress, Trial& t) const;
    /// Stress and state after the return r from trial t.
    void apply(const Trial& t, const cap::Return& r, Voigt6& stress, double* state) const;

    cap::Model model_;
};

} // namespace grainload::materials
