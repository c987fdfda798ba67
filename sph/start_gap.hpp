#pragma once
// Bodies and sources that start within the contact potential's reach of a wall: refused or warned.

#include "particles/cell_list.hpp"
#include "sph/kernels.hpp"
#include "sph/particle_set.hpp"
#include "sph/scene_places.hpp"
#include "sph/source.hpp"
#include "sph/sph_options.hpp"
#include "sph/wall.hpp"

#include <limits>
#include <string>
#include <vector>

namespace grainload::sph {

/// What one wall's particles hold of a group of points at t = 0.
struct WallShare {
    /// Energy of the contact potential over the pairs of the points with the wall's particles,
    /// thesis eq. (5.3.12) integrated (sph::contact_energy): J, in plane strain J/m.
    double energy = 0.0;
    /// The smallest distance from a point to one of the wall's particles [m] (infinity: none
    /// within the kernel support).
    double gap = std::numeric_limits<double>::infinity();
    /// The repulsion of the wall on the points, summed: the way the contact throws them [N].
    Vec3 force = Vec3::Zero();
};

/// What the contact potential holds at t = 0 of a group of points (a body's particles, or the
/// sites a source fills) against the walls that act on them.
struct StartContact {
    std::vector<WallShare> walls; ///< one per wall of the scene, in its order
    double energy = 0.0;          ///< over all walls
    /// The wall that stores the most (-1: none stores anything).
    int main_wall() const;
};

/// The wall particles of a scene in a grid of cells as wide as the kernel support, for the
/// contact of points that are not in the particle set yet (a source's sites) or are.
class WallParticleIndex {
  public:
    WallParticleIndex(const ParticleSet& particles, const std::vector<Wall>& walls,
                      double support_radius, int dimension);

    /// The contact of `points` of volume `volume` each (m^3, in plane strain m^2), of body
    /// `body`, with the walls that act on it (Wall::bodies); `only_wall` >= 0 limits it to
    /// that wall. `spacing` is the reference distance dp of W(dp).
    StartContact contact(const std::vector<Vec3>& points, double volume, int body,
                         const SmoothingKernel& kernel, const ContactPotential& potential,
                         double spacing, int only_wall = -1) const;

  private:
    const std::vector<Wall>* walls_;
    std::vector<Vec3> position_;
    std::vector<double> volume_;
    std::vector<int> wall_;
    particles::CellList cells_;
};

/// A start is judged by E0 / (M g s): the energy the contact potential stores at t = 0 (E0)
/// over the weight of the material times one spacing, its potential energy over one spacing.
/// The push can give the material no more kinetic energy than E0 (a body's measured peak:
/// 0.21-0.45 E0, docs/validation/stability.md, "Start gap"). Below this ratio the push gives
/// less than half of M g s, the scale of the fall onto the potential that every start at the
/// force-free gap 2h makes (measured: 0.05-0.39 M g s of kinetic energy): no warning.
constexpr double kStartPushWarning = 1.0;

/// Above this ratio a body's start is refused. Measured on a block of sand in a bin (plane strain
/// and 3D; beside a floor and a side wall; contact stiffness E and 10 E; walls at the spacing
/// and at half of it): bodies died (exit 3, thrown out of the scene) from 179 M g s up (beside
/// the side wall; the other series from 243 to 498) and survived up to 135-368; those that
/// survived above 100 had been thrown with 32-111 M g s of kinetic energy.
constexpr double kStartPushRefusal = 100.0;

/// The same for the sites a source fills, E0 of all its sites against the weight of the
/// particles that fill them. A source refills the sites its particles leave, and each refill is
/// pushed again: its runs died (exit 3) from 32 M g s up and survived up to 19.
constexpr double kSourcePushRefusal = 20.0;

/// Bodies and sources that start within the contact potential's reach of a wall (nearer than
/// 2h to its particles, outside them: check_wall_overlaps refuses those inside). Per body, the
/// energy the potential stores at t = 0 against its weight times one spacing: above
/// kStartPushRefusal (a source: kSourcePushRefusal) the scene is refused at the body's shape
/// (or the source's `min` or shape), naming the wall, the gap found and the gap needed; above
/// kStartPushWarning a warning, returned, says how far to move it. Nothing without gravity or
/// contact stiffness (the reference is the weight). `gravity` is |g|. Symmetry-plane images of
/// the walls are not counted.
std::vector<std::string> check_start_gaps(const ScenePlaces& places, const ParticleSet& particles,
                                          const std::vector<Wall>& walls, const SourceSet& sources,
                                          const std::vector<std::string>& body_names,
                                          const SmoothingKernel& kernel,
                                          const ContactPotential& potential, double gravity,
                                          double spacing, int dimension);

} // namespace grainload::sph
