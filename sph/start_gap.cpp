#include "sph/start_gap.hpp"

#include "sph/contact_force.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace grainload::sph {

int StartContact::main_wall() const {
    int main = -1;
    for (std::size_t k = 0; k < walls.size(); ++k) {
        if (walls[k].energy > 0.0 &&
            (main < 0 || walls[k].energy > walls[static_cast<std::size_t>(main)].energy)) {
            main = static_cast<int>(k);
        }
    }
    return main;
}

WallParticleIndex::WallParticleIndex(const ParticleSet& particles, const std::vector<Wall>& walls,
                                     double support_radius, int dimension)
    : walls_(&walls) {
    for (std::size_t k = 0; k < walls.size(); ++k) {
        for (Index i = walls[k].first; i < walls[k].first + walls[k].count; ++i) {
            position_.push_back(particles.position[i]);
            volume_.push_back(particles.mass[i] / particles.density[i]);
            wall_.push_back(static_cast<int>(k));
        }
    }
    cells_.build(position_, support_radius, dimension);
}

StartContact WallParticleIndex::contact(const std::vector<Vec3>& points, double volume, int body,
                                        const SmoothingKernel& kernel,
                                        const ContactPotential& potential, double spacing,
                                        int only_wall) const {
    StartContact result;
    result.walls.resize(walls_->size());
    std::vector<char> acts(walls_->size());
    for (std::size_t k = 0; k < walls_->size(); ++k) {
        const std::vector<int>& bodies = (*walls_)[k].bodies;
        acts[k] = (only_wall < 0 || only_wall == static_cast<int>(k)) &&
                  (bodies.empty() || std::find(bodies.begin(), bodies.end(), body) != bodies.end());
    }
    const double support = kernel.support_radius();
    const double w_reference = kernel.value(spacing);
    for (const Vec3& x : points) {
        cells_.for_each_candidate(x, [&](Index j) {
            const auto k = static_cast<std::size_t>(j);
            const Vec3 x_ij = x - position_[k];
            const double r = x_ij.norm();
            const auto w = static_cast<std::size_t>(wall_[k]);
            // r = 0: a point on a wall particle, inside the wall (check_wall_overlaps).
            if (!(r < support) || !(r > 0.0) || acts[w] == 0) {
                return;
            }
            const double volumes = volume * volume_[k];
            WallShare& share = result.walls[w];
            share.energy += contact_energy(kernel, potential, w_reference, volumes, r);
            share.gap = std::min(share.gap, r);
            share.force += contact_repulsion(kernel, potential, w_reference, volumes, r) / r * x_ij;
        });
    }
    for (const WallShare& share : result.walls) {
        result.energy += share.energy;
    }
    return result;
}

namespace {

/// One group of points judged at the start: a body's particles or a source's sites.
struct Group {
    std::string what;         ///< "body \"fill\"" or "source \"top\""
    std::vector<Vec3> points; ///< positions at t = 0
    int body = -1;
    std::string weight_of; ///< "its weight", ...
    double mass = 0.0;     ///< of all the points' particles
    double refusal = 0.0;  ///< ratio E0 / (M g s) refused
};

/// A move that clears a start: how far, and the gap from the wall's particles after it.
struct Clearing {
    double shift = -1.0; ///< -1: none within 2h
    double gap = 0.0;
};

/// How far to move the points along `direction` (a unit vector, away from wall `wall`) for their
/// contact with it to fall to `fraction` of what it stores at t = 0. Only the points the wall
/// pushes along `direction` (within 45 degrees) move: the others face another side of it (a
/// box's other faces), which this move does not clear. The energy is scanned in steps of
/// 2h / 50, as it may rise again where a far side comes near, then the crossing is bisected to a
/// ten-thousandth of a spacing (the side it errs on is the safe one).
Clearing clearing_shift(const WallParticleIndex& index, const Group& group, double volume, int wall,
                        const Vec3& direction, double fraction, const SmoothingKernel& kernel,
                        const ContactPotential& potential, double spacing) {
    std::vector<Vec3> facing;
    for (const Vec3& x : group.points) {
        const Vec3 force = index.contact({x}, volume, group.body, kernel, potential, spacing, wall)
                               .walls[static_cast<std::size_t>(wall)]
                               .force;
        if (force.dot(direction) > std::sqrt(0.5) * force.norm()) {
            facing.push_back(x);
        }
    }
    if (facing.empty()) { // pushes that cancel (a body wedged between two faces): no one way out
        return {};
    }
    auto moved = [&](double shift) {
        std::vector<Vec3> points = facing;
        for (Vec3& x : points) {
            x += shift * direction;
        }
        return index.contact(points, volume, group.body, kernel, potential, spacing, wall)
            .walls[static_cast<std::size_t>(wall)];
    };
    const double target = fraction * moved(0.0).energy;
    const double reach = kernel.support_radius();
    constexpr int kSteps = 50;
    double low = 0.0;
    for (int step = 1; step <= kSteps; ++step) {
        double high = reach * step / kSteps;
        if (moved(high).energy > target) {
            low = high;
            continue;
        }
        while (high - low > 1e-4 * spacing) {
            const double middle = 0.5 * (low + high);
            (moved(middle).energy > target ? low : high) = middle;
        }
        return {high, moved(high).gap};
    }
    return {};
}

std::string judge(const WallParticleIndex& index, const Group& group,
                  const std::vector<Wall>& walls, const SmoothingKernel& kernel,
                  const ContactPotential& potential, double gravity, double spacing, int dimension,
                  bool& refused) {
    const double volume = std::pow(spacing, dimension);
    const StartContact start =
        index.contact(group.points, volume, group.body, kernel, potential, spacing);
    const double weight = group.mass * gravity * spacing; // M g s
    const int main = start.main_wall();
    refused = false;
    if (main < 0 || !(start.energy > kStartPushWarning * weight)) {
        return "";
    }
    refused = start.energy > group.refusal * weight;
    const WallShare& share = start.walls[static_cast<std::size_t>(main)];
    const double reach = kernel.support_radius();
    // Each wall's share of the start falls below the warning's in proportion: the main wall's
    // facing side is moved until it stores that fraction of what it stores now.
    const Vec3 away = share.force.norm() > 0.0 ? Vec3(share.force.normalized()) : Vec3::Zero();
    const Clearing clearing =
        clearing_shift(index, group, volume, main, away, kStartPushWarning * weight / start.energy,
                       kernel, potential, spacing);
    const char* unit = dimension == 2 ? " J/m" : " J";
    std::ostringstream m;
    m.precision(3);
    m << group.what << " starts " << 1e3 * share.gap << " mm from the particles of wall \""
      << walls[static_cast<std::size_t>(main)].name << "\" (" << share.gap / reach
      << " of the contact reach 2h = " << 1e3 * reach << " mm): the contact potential stores "
      << start.energy << unit << " at t = 0, " << start.energy / weight << " times "
      << group.weight_of << " times one spacing (M g s = " << weight << unit << "), and ";
    if (refused) {
        m << "such starts (above " << group.refusal << " M g s) threw the material out of the "
          << "scene (exit 3, docs/validation/stability.md); expected ";
        if (clearing.shift > 0.0) {
            m << "a gap of at least " << 1e3 * clearing.gap << " mm: move it "
              << 1e3 * clearing.shift << " mm away from the wall";
        } else {
            m << "its particles 2h from the wall's first layer";
        }
    } else {
        m << "throws it off harder than it settles from 2h (above " << kStartPushWarning
          << " M g s); ";
        if (clearing.shift > 0.0) {
            m << "move it " << 1e3 * clearing.shift << " mm away from the wall, to a gap of "
              << 1e3 * clearing.gap << " mm";
        } else {
            m << "place its particles 2h from the wall's first layer";
        }
    }
    m << " (at 2h it touches without force)";
    return m.str();
}

/// The key of a shape table that places it: its box corner, its base or centre (a cylinder or
/// cone, a disc), its file, else its type.
const char* placing_key(const io::KeyPlaces& shape) {
    for (const char* key : {"min", "base", "centre", "file"}) {
        if (shape.has(key)) {
            return key;
        }
    }
    return "type";
}

} // namespace

std::vector<std::string> check_start_gaps(const ScenePlaces& places, const ParticleSet& particles,
                                          const std::vector<Wall>& walls, const SourceSet& sources,
                                          const std::vector<std::string>& body_names,
                                          const SmoothingKernel& kernel,
                                          const ContactPotential& potential, double gravity,
                                          double spacing, int dimension) {
    std::vector<std::string> warnings;
    if (walls.empty() || !(gravity > 0.0) || !(potential.stiffness > 0.0)) {
        return warnings;
    }
    const WallParticleIndex index(particles, walls, kernel.support_radius(), dimension);
    auto say = [&](const Group& group, const io::KeyPlaces& table, const char* key) {
        bool refused = false;
        const std::string message =
            judge(index, group, walls, kernel, potential, gravity, spacing, dimension, refused);
        if (refused) {
            table.fail(key, message);
        }
        if (!message.empty()) {
            warnings.push_back(table.where(key) + ": " + message);
        }
    };
    for (std::size_t b = 0; b < body_names.size(); ++b) {
        Group group{"body \"" + body_names[b] + "\"",
                    {},
                    static_cast<int>(b),
                    "its weight",
                    0.0,
                    kStartPushRefusal};
        for (Index i = 0; i < particles.size(); ++i) {
            if (!particles.is_wall(i) && particles.body_id[i] == group.body) {
                group.points.push_back(particles.position[i]);
                group.mass += particles.mass[i];
            }
        }
        const io::KeyPlaces& shape = places.body_shapes[b];
        say(group, shape, placing_key(shape));
    }
    for (std::size_t s = 0; s < sources.sources().size(); ++s) {
        const SourceSet::Source& source = sources.sources()[s];
        const Group group{"source \"" + source.name + "\"",
                          source.sites,
                          source.body,
                          "the weight of the particles that fill its sites",
                          source.particle_mass * static_cast<double>(source.sites.size()),
                          kSourcePushRefusal};
        if (places.sources[s].has("min")) {
            say(group, places.sources[s], "min");
        } else {
            const io::KeyPlaces& shape = places.source_shapes[s];
            say(group, shape, placing_key(shape));
        }
    }
    return warnings;
}

} // namespace grainload::sph
