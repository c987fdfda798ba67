#pragma once
// The constitutive model shared by SPH and FEM: a strain-driven update with consistent tangent.

#include "materials/elastic_constants.hpp"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace grainload::materials {

struct NonlocalFluidity;

/// Which part of the yield surface the last update ended on; written per point for output.
enum class PlasticRegion : int {
    elastic = 0,
    failure_surface = 1, ///< von Mises / Drucker-Prager cone / cap-model failure envelope
    cap = 2,
    corner = 3, ///< failure surface meets cap
    apex = 4,   ///< cone apex or tension cutoff
};

/// A constitutive model shared by SPH and FEM. Parameters live in the object; the per-point
/// state lives in plain arrays owned by the caller (state_size() doubles per point).
///
/// The one entry point is a strain-driven update: given the stress at the start of the step
/// (already rotated by the caller's objective rate), a strain increment (engineering shear)
/// and the point's state, return the new stress, update the state and, on request, give the
/// consistent (algorithmic) tangent d(stress_new)/d(strain_increment).
class Material {
  public:
    explicit Material(ElasticConstants elastic) : elastic_(elastic) {}
    virtual ~Material() = default;

    virtual std::string_view model() const = 0;

    virtual int state_size() const { return 0; }
    /// Names of the state entries, for output and the material-point driver.
    virtual std::vector<std::string> state_names() const { return {}; }
    /// Initial state of one point (e.g. the cap position X0); default all zeros.
    virtual void initialise_state(std::span<double> state) const;

    virtual PlasticRegion update(const Voigt6& strain_increment, Voigt6& stress,
                                 std::span<double> state, Matrix6* tangent) const = 0;

    /// update() over a step of `time_step` seconds. A rate-dependent model reads its strain rate
    /// as strain_increment / time_step (materials/mu_i_material.hpp), and its update() is the
    /// quasi-static limit (zero rate); a rate-independent model ignores the time: the default
    /// is update().
    virtual PlasticRegion update_over(const Voigt6& strain_increment, double time_step,
                                      Voigt6& stress, std::span<double> state,
                                      Matrix6* tangent) const;

    /// update_over() without tangents for several points of one time step (states[k] holds
    /// point k's state_size() doubles), each exactly as update_over() gives it. The default
    /// takes them one after another; a model whose return iterates may interleave the points'
    /// iterations.
    virtual void update_points(std::span<const Voigt6> strain_increments, double time_step,
                               std::span<Voigt6> stresses, std::span<double* const> states,
                               std::span<PlasticRegion> regions) const;

    /// Equivalent plastic strain carried in `state`, for output.
    virtual double equivalent_plastic_strain(std::span<const double> state) const;

    /// A state entry the frames show per particle beside the stress and the plastic strain.
    struct StateField {
        std::string name;
        int index = 0; ///< into the point's state
    };
    /// The state entries worth a frame array (the mu(I) material's inertial number); none by
    /// default.
    virtual std::vector<StateField> frame_state() const { return {}; }
    /// The non-local fluidity whose field a particle method solves before each update
    /// (materials/nonlocal_fluidity.hpp); none by default.
    virtual const NonlocalFluidity* nonlocal_fluidity() const { return nullptr; }

    const ElasticConstants& elastic() const { return elastic_; }
    double density() const { return elastic_.density; }

  protected:
    ElasticConstants elastic_;
};

} // namespace grainload::materials
