#pragma once
// Grains rained into a DEM scene through a box: a scene part, as the SPH sources are.

#include "dem/dem_case_reader.hpp"
#include "dem/plane_wall.hpp"
#include "dem/sphere_set.hpp"
#include "particles/phase_sequence.hpp"
#include "particles/scene_part.hpp"

#include <optional>
#include <random>
#include <utility>
#include <vector>

namespace grainload::dem {

/// The [[dem.source]] tables: each makes grains of its body appear in its box, `rate` per
/// second from its start to its end (and `count` in all), as the DEM study filled its silo by
/// letting balls fall in from above (Lazarevic, Dvornik & Fresl 2002). The grains due in a step
/// (the rate's running sum) are drawn as the body's initial grains are: a radius uniform in
/// [radius_min, radius_max], a centre uniform where the sphere lies inside the box (a clump's
/// orientation uniform first, and the centre where all of it lies inside); a draw that
/// overlaps a sphere of the scene, one placed this step, or a wall's face is drawn again (the
/// radius kept), up to 100 times; then the box counts as full for this step and the grain stays
/// due. A source that has waited for room says so once in the log. The draws follow a 64-bit
/// Mersenne twister seeded by `seed`; its state travels in the checkpoint.
class GrainSources : public particles::ScenePart {
  public:
    GrainSources(std::vector<SourceSettings> sources, const std::vector<BodySettings>& bodies,
                 std::vector<double> body_density, const SphereSet& spheres,
                 const std::vector<PlaneWall>& walls);

    std::string_view name() const override { return "dem.source"; }
    bool empty() const { return sources_.empty(); }
    /// The mass the sources have made enter [kg], for the mass audit.
    double created_mass() const;
    /// Sources whose start or end names a phase take its start (+infinity while unknown).
    void apply_phase_starts(const particles::PhaseSequence& phases);

    void collect_arrivals(const particles::ParticleView& particles, double t, double dt,
                          std::vector<particles::Arrival>& arrivals) override;
    void append_results(std::vector<io::ResultFigure>& results) const override;
    void take_events(std::vector<std::string>& events) override;
    void write_checkpoint(std::ostream& out) const override;
    void read_checkpoint(std::istream& in) override;

  private:
    struct Source {
        SourceSettings settings;
        std::mt19937_64 generator;
        double due = 0.0;
        Index created = 0;
        double created_mass = 0.0;
        bool waited = false;
    };
    /// One grain of source s at a free place, or none after the draws ran out.
    std::optional<particles::Arrival> draw(Source& source);
    /// The spheres of the scene a grain in the box of `source` could touch, into near_.
    void find_near(const SourceSettings& source);
    /// Whether a sphere at `centre` of `radius` touches no sphere near the box, no sphere of a
    /// grain placed this step (placed_) and no wall.
    bool free(const Vec3& centre, double radius) const;
    /// The spheres of `arrival` (turned by its orientation) join placed_.
    void add_placed(const particles::Arrival& arrival);

    std::vector<Source> sources_;
    const std::vector<BodySettings>& bodies_;
    std::vector<double> body_density_;
    const SphereSet& spheres_;
    const std::vector<PlaneWall>& walls_;
    std::vector<std::string> events_;
    std::vector<Index> near_;
    /// The centres and radii of the spheres of the grains placed in this step, each computed
    /// once as its grain is placed.
    std::vector<std::pair<Vec3, double>> placed_;
};

} // namespace grainload::dem
