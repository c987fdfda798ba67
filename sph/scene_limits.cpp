#include "sph/scene_limits.hpp"

#include "io/case_error.hpp"
#include "particles/cell_list.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace grainload::sph {

GravityStrain gravity_strain(const ParticleSet& particles,
                             const materials::MaterialLibrary& materials, const Vec3& gravity,
                             double spacing, double contact_stiffness) {
    GravityStrain result;
    const double g = gravity.norm();
    if (g == 0.0) {
        return result;
    }
    const Vec3 down = gravity / g;
    struct Extent {
        double low = std::numeric_limits<double>::infinity();
        double high = -std::numeric_limits<double>::infinity();
        int material = -1;
    };
    std::map<int, Extent> bodies;
    for (Index i = 0; i < particles.size(); ++i) {
        if (particles.is_wall(i)) {
            continue;
        }
        Extent& e = bodies[particles.body_id[i]];
        const double depth = particles.position[i].dot(down);
        e.low = std::min(e.low, depth);
        e.high = std::max(e.high, depth);
        e.material = particles.material_id[i];
    }
    for (const auto& [body, e] : bodies) {
        const materials::Material& law = materials[e.material];
        const materials::ElasticConstants& elastic = law.elastic();
        const double stress = law.density() * g * (e.high - e.low + spacing);
        const double modulus = elastic.bulk_modulus + 4.0 / 3.0 * elastic.shear_modulus;
        if (modulus > 0.0 && stress / modulus > result.strain) {
            result.strain = stress / modulus;
            result.material_body = body;
            result.material = e.material;
            result.stress = stress;
        }
        if (contact_stiffness > 0.0 && stress / contact_stiffness > result.contact) {
            result.contact = stress / contact_stiffness;
            result.contact_body = body;
            result.contact_stress = stress;
        }
    }
    return result;
}

void check_gravity_strain(const ScenePlaces& places, const ParticleSet& particles,
                          const materials::MaterialLibrary& materials,
                          const std::vector<std::string>& body_names, const Vec3& gravity,
                          double spacing, double contact_stiffness) {
    const GravityStrain g =
        gravity_strain(particles, materials, gravity, spacing, contact_stiffness);
    if (g.strain > kLargestGravityStrain) {
        const auto m = static_cast<std::size_t>(g.material);
        const io::KeyPlaces& table = places.materials[m];
        const bool deck = table.has("from_lsdyna");
        const char* key = table.has("stiffness_scale")  ? "stiffness_scale"
                          : deck                        ? "from_lsdyna"
                          : table.has("youngs_modulus") ? "youngs_modulus"
                                                        : "bulk_modulus";
        std::ostringstream message;
        message.precision(3);
        message << "body \"" << body_names[static_cast<std::size_t>(g.material_body)]
                << "\" carries rho g H = " << g.stress << " Pa at its base under gravity, a strain "
                << "of " << g.strain << " against the P-wave modulus K + 4G/3 of material \""
                << materials.name(g.material) << "\", above " << kLargestGravityStrain
                << ": its elastic constants no longer describe it; expected K + 4G/3 of at least "
                << g.stress / kLargestGravityStrain << " Pa";
        if (deck) {
            // Density and moduli both come from the deck, as its units convert them.
            message << " (the deck's RO, BULK and G read in \"" << places.deck_units[m] << "\")";
        }
        table.fail(key, message.str());
    }
    if (g.contact > kLargestGravityStrain) {
        std::ostringstream message;
        message.precision(3);
        message << "body \"" << body_names[static_cast<std::size_t>(g.contact_body)]
                << "\" presses rho g H = " << g.contact_stress << " Pa on what it stands on, "
                << g.contact << " of the contact stiffness: it would sink into the walls; "
                << "expected a contact stiffness of at least "
                << g.contact_stress / kLargestGravityStrain << " Pa";
        places.contact.fail("stiffness", message.str());
    }
}

std::string impact_warning(const ParticleSet& particles, const std::vector<std::string>& body_names,
                           double contact_stiffness) {
    if (!(contact_stiffness > 0.0)) {
        return "";
    }
    double worst = 0.0;
    Index at = -1;
    for (Index i = 0; i < particles.size(); ++i) {
        if (particles.is_wall(i)) {
            continue;
        }
        const double pressure = particles.density[i] * particles.velocity[i].squaredNorm();
        if (pressure > worst) {
            worst = pressure;
            at = i;
        }
    }
    if (worst <= contact_stiffness) {
        return "";
    }
    std::ostringstream message;
    message.precision(3);
    message << "body \"" << body_names[static_cast<std::size_t>(particles.body_id[at])]
            << "\" starts at " << particles.velocity[at].norm() << " m/s: rho v^2 = " << worst
            << " Pa exceeds the contact stiffness " << contact_stiffness
            << " Pa, so its particles can pass a rigid wall; a contact stiffness of at least "
            << worst << " Pa stops them";
    return message.str();
}

namespace {

/// The particles of the walls, binned for the search, with each one's wall and spacing.
struct WallPoints {
    std::vector<Vec3> position;
    std::vector<int> wall;
    std::vector<double> spacing;
    particles::CellList cells;
};

WallPoints wall_points(const ParticleSet& p, const std::vector<Wall>& walls, double reach,
                       int dimension) {
    WallPoints w;
    for (std::size_t k = 0; k < walls.size(); ++k) {
        for (Index i = walls[k].first; i < walls[k].first + walls[k].count; ++i) {
            w.position.push_back(p.position[i]);
            w.wall.push_back(static_cast<int>(k));
            // A wall particle stands for the volume mass / density = spacing^d (sph::add_wall).
            w.spacing.push_back(std::pow(p.mass[i] / p.density[i], 1.0 / dimension));
        }
    }
    w.cells.build(w.position, reach, dimension);
    return w;
}

bool acts_on(const Wall& wall, int body) {
    return wall.bodies.empty() ||
           std::find(wall.bodies.begin(), wall.bodies.end(), body) != wall.bodies.end();
}

/// Points of body `body` inside each wall's particles (kInsideWall): how many, the nearest.
struct Overlap {
    Index count = 0;
    double nearest = std::numeric_limits<double>::infinity();
};

/// The first wall (in case order) that `points` overlap, or none.
std::optional<std::pair<int, Overlap>> first_overlap(const WallPoints& w,
                                                     const std::vector<Wall>& walls,
                                                     const std::vector<Vec3>& points, int body,
                                                     double spacing) {
    std::map<int, Overlap> by_wall;
    for (const Vec3& x : points) {
        std::map<int, double> inside; // wall -> nearest of its particles
        w.cells.for_each_candidate(x, [&](Index j) {
            const auto k = static_cast<std::size_t>(j);
            const double d = (w.position[k] - x).norm();
            if (d < kInsideWall * 0.5 * (spacing + w.spacing[k]) &&
                acts_on(walls[static_cast<std::size_t>(w.wall[k])], body)) {
                auto [it, fresh] = inside.emplace(w.wall[k], d);
                it->second = fresh ? d : std::min(it->second, d);
            }
        });
        for (const auto& [wall, d] : inside) {
            Overlap& o = by_wall[wall];
            ++o.count;
            o.nearest = std::min(o.nearest, d);
        }
    }
    if (by_wall.empty()) {
        return std::nullopt;
    }
    return *by_wall.begin();
}

/// The key of a shape table that places it: its box corner, its file, else its type.
const char* placing_key(const io::KeyPlaces& shape) {
    return shape.has("min") ? "min" : shape.has("file") ? "file" : "type";
}

} // namespace

void check_wall_overlaps(const ScenePlaces& places, const ParticleSet& particles,
                         const std::vector<Wall>& walls, const SourceSet& sources,
                         const std::vector<std::string>& body_names, double spacing, int dimension,
                         double support_radius) {
    if (walls.empty()) {
        return;
    }
    const WallPoints w = wall_points(particles, walls, kInsideWall * spacing, dimension);
    std::ostringstream clear;
    clear.precision(3);
    clear << "touch it without force " << support_radius
          << " m (the kernel's support radius 2h) from the wall's first layer";
    for (std::size_t b = 0; b < body_names.size(); ++b) {
        std::vector<Vec3> points;
        for (Index i = 0; i < particles.size(); ++i) {
            if (!particles.is_wall(i) && particles.body_id[i] == static_cast<int>(b)) {
                points.push_back(particles.position[i]);
            }
        }
        if (const auto o = first_overlap(w, walls, points, static_cast<int>(b), spacing)) {
            std::ostringstream message;
            message.precision(3);
            message << "body \"" << body_names[b] << "\" overlaps wall \""
                    << walls[static_cast<std::size_t>(o->first)].name << "\": " << o->second.count
                    << " of its " << points.size() << " particles lie inside the wall's particles "
                    << "(the nearest " << o->second.nearest << " m from one), where the contact "
                    << "potential throws them off at the first step; expected the body clear of "
                    << "the wall: its particles " << clear.str();
            const io::KeyPlaces& shape = places.body_shapes[b];
            shape.fail(placing_key(shape), message.str());
        }
    }
    for (std::size_t s = 0; s < sources.sources().size(); ++s) {
        const SourceSet::Source& source = sources.sources()[s];
        if (const auto o = first_overlap(w, walls, source.sites, source.body, spacing)) {
            std::ostringstream message;
            message << "source \"" << source.name << "\" overlaps wall \""
                    << walls[static_cast<std::size_t>(o->first)].name << "\": " << o->second.count
                    << " of its " << source.sites.size() << " sites lie inside the wall's "
                    << "particles; the particles it makes there and beside them start inside or "
                    << "against the wall, where the contact potential throws them off; expected "
                    << "the source's region clear of the wall: particles " << clear.str();
            if (places.sources[s].has("min")) {
                places.sources[s].fail("min", message.str());
            }
            const io::KeyPlaces& shape = places.source_shapes[s];
            shape.fail(placing_key(shape), message.str());
        }
    }
}

namespace {

/// Per body, what the sinks hold of it at t = 0.
struct Held {
    Index total = 0;
    Index held = 0;
    std::set<int> sinks; ///< the sinks holding them
    bool fed = false;    ///< a source of the body makes particles outside the sinks
    bool leaves() const { return total > 0 && held == total && !fed; }
};

std::vector<Held> held_bodies(const ParticleSet& particles, const particles::SinkSet& sinks,
                              const SourceSet& sources, std::size_t bodies) {
    const auto& list = sinks.sinks();
    // The first sink that takes a particle of `body` at x, as SinkSet::collect, or -1.
    auto taker = [&](const Vec3& x, int body) {
        for (std::size_t s = 0; s < list.size(); ++s) {
            if ((list[s].body < 0 || list[s].body == body) && list[s].region.contains(x)) {
                return static_cast<int>(s);
            }
        }
        return -1;
    };
    std::vector<Held> held(bodies);
    for (Index i = 0; i < particles.size(); ++i) {
        if (particles.is_wall(i)) {
            continue;
        }
        Held& h = held[static_cast<std::size_t>(particles.body_id[i])];
        ++h.total;
        if (const int s = taker(particles.position[i], particles.body_id[i]); s >= 0) {
            ++h.held;
            h.sinks.insert(s);
        }
    }
    for (const SourceSet::Source& source : sources.sources()) {
        Held& h = held[static_cast<std::size_t>(source.body)];
        h.fed = h.fed || std::any_of(source.sites.begin(), source.sites.end(),
                                     [&](const Vec3& x) { return taker(x, source.body) < 0; });
    }
    return held;
}

} // namespace

std::vector<std::string> check_sinks_hold_bodies(const ScenePlaces& places,
                                                 const ParticleSet& particles,
                                                 const particles::SinkSet& sinks,
                                                 const SourceSet& sources,
                                                 const std::vector<std::string>& body_names) {
    std::vector<std::string> warnings;
    if (sinks.empty()) {
        return warnings;
    }
    const std::vector<Held> held = held_bodies(particles, sinks, sources, body_names.size());
    const bool kept =
        std::any_of(held.begin(), held.end(), [](const Held& h) { return !h.leaves(); });
    const std::vector<io::KeyPlaces>& tables = places.sinks;
    for (std::size_t b = 0; b < held.size(); ++b) {
        if (!held[b].leaves()) {
            continue;
        }
        const auto s = static_cast<std::size_t>(*held[b].sinks.begin());
        const particles::SinkSet::Sink& sink = sinks.sinks()[s];
        const bool plane = sink.region.kind == io::Region::Kind::half_space;
        const char* key = plane ? "normal" : "min";
        const std::string what = "sink \"" + sink.name + "\" holds all " +
                                 std::to_string(held[b].total) + " particles of body \"" +
                                 body_names[b] + "\" at t = 0" +
                                 (held[b].sinks.size() > 1 ? " (with the other sinks)" : "") +
                                 ", so they leave in the first step";
        if (!kept) {
            tables[s].fail(key, what +
                                    " and the run has nothing left to do; expected the sink "
                                    "outside the body" +
                                    (plane ? " (a plane sink's normal points out of the scene, "
                                             "to the side particles leave by)"
                                           : ""));
        }
        warnings.push_back(tables[s].where(key) + ": " + what);
    }
    return warnings;
}

} // namespace grainload::sph
