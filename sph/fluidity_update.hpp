#pragma once
// The non-local fluidity of the particles' materials, solved before each stress update.

#include "materials/material.hpp"
#include "sph/fluidity_field.hpp"
#include "sph/particle_set.hpp"
#include "sph/symmetry.hpp"

#include <cmath>
#include <span>
#include <vector>

namespace grainload::sph {

/// Before each stress update, for the materials with a non-local fluidity
/// (materials/nonlocal_fluidity.hpp): each of their particles' local fluidity g_loc and
/// screening 1/xi^2 from the stress at the step's start (mu = sqrt(J2)/p), the field g solved
/// over the neighbours (FluidityField), starting from the fluidity each particle flowed at in
/// the last step, and the excess g - g_loc written into the particle's state for its update.
/// Particles at p <= 0 (no confinement) take no part and get no excess. A restart that restores
/// the states and the neighbour list repeats the solve bit for bit.
class FluidityUpdate {
  public:
    /// Whether any of the materials has a non-local fluidity.
    static bool needed(std::span<const materials::Material* const> materials);
    /// Whether the step from `time` to time + dt solves the field: the first step into each
    /// `interval` of the clock (SphOptions::fluidity_interval; 0: every step). The clock, which a
    /// restart sets back, decides, so that a restarted run solves at the same steps.
    static bool due(double time, double dt, double interval) {
        return !(interval > 0.0) ||
               std::floor((time + dt) / interval) > std::floor(time / interval);
    }

    /// At the step's positions, images attached after the first `count` particles (`images`
    /// names their sources); `list` built over them.
    void apply(ParticleSet& particles, Index count, std::span<const GhostImage> images,
               std::span<const materials::Material* const> materials,
               const particles::NeighbourList& list, const SmoothingKernel& kernel);
    /// The most iterations one solve took, since this process started the run.
    int most_iterations() const { return most_iterations_; }
    /// Iterations per solve, averaged over the solves since this process started the run.
    double mean_iterations() const {
        return solves_ > 0 ? static_cast<double>(iterations_) / static_cast<double>(solves_) : 0.0;
    }
    /// The largest residual a solve left (above the tolerance only where the cap stopped it).
    double worst_residual() const { return worst_residual_; }
    std::size_t bytes() const;

  private:
    void connect(const ParticleSet& particles, Index count, std::span<const GhostImage> images,
                 std::span<const materials::Material* const> materials,
                 const particles::NeighbourList& list);

    FluidityField field_;
    std::vector<char> carries_;
    std::vector<char> active_;
    std::vector<double> volume_;
    std::vector<double> local_;
    std::vector<double> screening_;
    std::vector<double> values_;
    int most_iterations_ = 0;
    double worst_residual_ = 0.0;
    long long solves_ = 0;
    long long iterations_ = 0;
};

} // namespace grainload::sph
