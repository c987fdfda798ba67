#pragma once
// Sources: particles entering the scene through box regions at a mass rate.

#include "io/region.hpp"
#include "particles/phase_sequence.hpp"
#include "particles/scene_part.hpp"
#include "sph/particle_set.hpp"

#include <array>
#include <limits>
#include <string>
#include <vector>

namespace grainload::sph {

/// Particles entering the scene through box regions at a mass rate (the way silos are filled).
/// Each source owns a lattice at the body's spacing inside its box; a step owes it
/// mass_rate * (the part of the step inside [start, end)), and whole particles are created
/// from what is owed at lattice sites no particle is near (closer than kMinimumGap spacings),
/// taking the sites round-robin so the stream covers the box evenly. A scene part in terms of
/// positions and masses only: the model turns its arrivals into particles. (The sites of a
/// shaped source come from the SPH lattice, which keeps it in sph/.)
class SourceSet final : public particles::ScenePart {
  public:
    struct Source {
        std::string name;
        io::Region region;
        int body = 0;
        int material = 0;
        double particle_mass = 0.0;
        double mass_rate = 0.0;
        double start = 0.0;
        double end = std::numeric_limits<double>::infinity();
        Vec3 velocity = Vec3::Zero();
        /// start or end = "phase:NAME": that phase, whose start they are (+infinity while it
        /// is not known); -1: a time.
        int start_phase = -1;
        int end_phase = -1;
        std::vector<Vec3> sites;
        // State (checkpointed):
        double owed = 0.0;
        double created = 0.0;
        std::size_t cursor = 0;
    };
    /// A lattice site is free when no particle lies closer than this many spacings: lattice
    /// neighbours one spacing apart (the body generator's own packing) must both be allowed,
    /// anything nearer would overlap a particle already there.
    static constexpr double kMinimumGap = 0.99;

    SourceSet() = default;
    /// Set the start and end that name phases to those phases' starts as now known.
    void apply_phase_starts(const particles::PhaseSequence& phases);
    /// Sources of bodies at `spacing` (sph/source_case_reader.hpp reads them from a case).
    SourceSet(std::vector<Source> sources, double spacing, int dimension = 3)
        : sources_(std::move(sources)), spacing_(spacing), dimension_(dimension) {}

    bool empty() const { return sources_.empty(); }
    const std::vector<Source>& sources() const { return sources_; }
    /// The lattice of a box at `spacing`: site centres half a spacing in from the faces.
    static std::vector<Vec3> lattice(const io::Region& box, double spacing, int dimension);
    /// The particles to create over the step [t, t + dt], given the particles there now; books
    /// their mass as created.
    std::vector<particles::Arrival> collect(const particles::ParticleView& particles, double t,
                                            double dt);
    /// Total mass created so far (kg, in plane strain kg/m).
    double created() const;

    /// For checkpoints: owed mass, created mass and cursor of each source.
    std::vector<double> state() const;
    void set_state(const std::vector<double>& state);

    std::string_view name() const override { return "sph.source"; }
    /// collect()'s arrivals, appended.
    void collect_arrivals(const particles::ParticleView& particles, double t, double dt,
                          std::vector<particles::Arrival>& arrivals) override;
    void write_checkpoint(std::ostream& out) const override;
    void read_checkpoint(std::istream& in) override;

  private:
    void collect_one(Source& source, const particles::ParticleView& particles,
                     std::vector<particles::Arrival>& arrivals) const;

    std::vector<Source> sources_;
    double spacing_ = 0.0;
    int dimension_ = 3;
};

} // namespace grainload::sph
