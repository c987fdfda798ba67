#include "sph/outlet_reach.hpp"

#include "sph/rigid_wall.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

namespace grainload::sph {

namespace {

// At one byte per cell twice over, 2^24 cells take 32 MiB; a scene whose box needs more at its
// spacing gets coarser cells (thin walls may then leak, which only widens the flood).
constexpr double kMostCells = 16777216.0;

// A step is upwards when it rises by more than half a cell against gravity: with gravity along
// an axis, a step is up, level or down; a tilted gravity keeps level steps along every axis
// within 30 deg of the horizontal.
constexpr double kLevel = 0.5;

/// A wall that material cannot pass while the run lasts (see ReachMap).
bool stays(const Wall& wall) {
    if (wall.count == 0 || std::isfinite(wall.removal_time) || wall.removal_on_settle ||
        wall.removal_phase >= 0 || !wall.bodies.empty()) {
        return false;
    }
    const auto* motion = dynamic_cast<const RigidMotion*>(wall.driver.get());
    return motion == nullptr || motion->at_rest();
}

/// Whether anything starts moving or can lift the material: then it may climb.
bool may_climb(const ParticleSet& p, const std::vector<Wall>& walls, const SourceSet& sources,
               const Vec3& gravity) {
    if (gravity.squaredNorm() == 0.0) {
        return true;
    }
    for (Index i = 0; i < p.size(); ++i) {
        if (!p.is_wall(i) && p.velocity[i].squaredNorm() > 0.0) {
            return true;
        }
    }
    for (const SourceSet::Source& s : sources.sources()) {
        if (s.velocity.squaredNorm() > 0.0) {
            return true;
        }
    }
    return std::any_of(walls.begin(), walls.end(), [](const Wall& w) {
        const auto* motion = dynamic_cast<const RigidMotion*>(w.driver.get());
        return motion != nullptr && !motion->at_rest();
    });
}

/// The box of every particle, source site and region (a plane by its point and the cells
/// beyond it), grown by two spacings.
std::pair<Vec3, Vec3> scene_box(const ParticleSet& p, const SourceSet& sources,
                                const std::vector<io::Region>& regions, double spacing) {
    Vec3 lower = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 upper = -lower;
    auto take = [&](const Vec3& x) {
        lower = lower.cwiseMin(x);
        upper = upper.cwiseMax(x);
    };
    for (Index i = 0; i < p.size(); ++i) {
        take(p.position[i]);
    }
    for (const SourceSet::Source& s : sources.sources()) {
        std::for_each(s.sites.begin(), s.sites.end(), take);
    }
    for (const io::Region& r : regions) {
        if (r.kind == io::Region::Kind::box) {
            take(r.lower);
            take(r.upper);
        } else {
            take(r.point);
            take(r.point + 2.0 * spacing * r.normal);
        }
    }
    const Vec3 margin = Vec3::Constant(2.0 * spacing);
    return {lower - margin, upper + margin};
}

} // namespace

ReachMap::ReachMap(const ParticleSet& p, const std::vector<Wall>& walls, const SourceSet& sources,
                   const std::vector<io::Region>& regions, const Vec3& gravity, double spacing,
                   int dimension, int body)
    : dimension_(dimension) {
    const auto [lower, upper] = scene_box(p, sources, regions, spacing);
    if (!lay_grid(lower, upper, spacing)) {
        everywhere_ = true; // no grid to flood (a scene at infinity): no region is out of reach
        return;
    }
    for (const Wall& wall : walls) {
        if (stays(wall)) {
            for (Index i = wall.first; i < wall.first + wall.count; ++i) {
                block(p.position[i], std::pow(p.mass[i] / p.density[i], 1.0 / dimension));
            }
        }
    }
    std::vector<Index> front;
    auto seed = [&](const Vec3& x) {
        const Index k = index(cell_of(x));
        if (!flooded_[static_cast<std::size_t>(k)]) {
            flooded_[static_cast<std::size_t>(k)] = 1;
            front.push_back(k);
        }
    };
    for (Index i = 0; i < p.size(); ++i) {
        if (!p.is_wall(i) && (body < 0 || p.body_id[i] == body)) {
            seed(p.position[i]);
        }
    }
    for (const SourceSet::Source& s : sources.sources()) {
        if (body < 0 || s.body == body) {
            std::for_each(s.sites.begin(), s.sites.end(), seed);
        }
    }
    const Vec3 up = gravity.squaredNorm() > 0.0 ? Vec3(-gravity.normalized()) : Vec3::Zero();
    flood(front, may_climb(p, walls, sources, gravity), up);
}

bool ReachMap::lay_grid(const Vec3& lower, const Vec3& upper, double spacing) {
    const Vec3 extent = upper - lower;
    if (!extent.allFinite() || !(spacing > 0.0)) {
        return false;
    }
    origin_ = lower;
    double cells = 1.0;
    for (int a = 0; a < dimension_; ++a) {
        cells *= std::ceil(extent[a] / spacing);
    }
    cell_ = spacing * std::max(1.0, std::pow(cells / kMostCells, 1.0 / dimension_));
    for (int a = 0; a < dimension_; ++a) {
        count_[a] = std::max<Index>(1, static_cast<Index>(std::ceil(extent[a] / cell_)));
    }
    const auto total = static_cast<std::size_t>(count_[0] * count_[1] * count_[2]);
    blocked_.assign(total, 0);
    flooded_.assign(total, 0);
    return true;
}

void ReachMap::block(const Vec3& x, double size) {
    // Every cell the particle's own volume (a cube of its spacing, sph::add_wall) touches: the
    // cells of a wall's particles alone leave holes where its spacing, rounded to fit its
    // extent, is a little wider than a cell, and its layers' holes line up.
    const Vec3 half = Vec3::Constant(0.5 * size);
    const Cell low = cell_of(x - half);
    const Cell high = cell_of(x + half);
    for (Index k = low[2]; k <= high[2]; ++k) {
        for (Index j = low[1]; j <= high[1]; ++j) {
            for (Index i = low[0]; i <= high[0]; ++i) {
                blocked_[static_cast<std::size_t>(index({i, j, k}))] = 1;
            }
        }
    }
}

ReachMap::Cell ReachMap::cell_of(const Vec3& x) const {
    Cell c{0, 0, 0};
    for (int a = 0; a < dimension_; ++a) {
        const auto k = static_cast<Index>(std::floor((x[a] - origin_[a]) / cell_));
        c[a] = std::clamp<Index>(k, 0, count_[a] - 1);
    }
    return c;
}

Vec3 ReachMap::centre(const Cell& c) const {
    Vec3 x = origin_;
    for (int a = 0; a < dimension_; ++a) {
        x[a] += (static_cast<double>(c[a]) + 0.5) * cell_;
    }
    return x;
}

void ReachMap::flood(std::vector<Index>& front, bool climb, const Vec3& up) {
    // Breadth first over face neighbours; `front` holds the cells still to spread from.
    while (!front.empty()) {
        const Index k = front.back();
        front.pop_back();
        const Cell c{k % count_[0], (k / count_[0]) % count_[1], k / (count_[0] * count_[1])};
        for (int a = 0; a < dimension_; ++a) {
            for (const Index step : {Index{-1}, Index{1}}) {
                Cell n = c;
                n[a] += step;
                if (n[a] < 0 || n[a] >= count_[a] ||
                    (!climb && static_cast<double>(step) * up[a] > kLevel)) {
                    continue;
                }
                const auto m = static_cast<std::size_t>(index(n));
                if (!blocked_[m] && !flooded_[m]) {
                    flooded_[m] = 1;
                    front.push_back(index(n));
                }
            }
        }
    }
}

bool ReachMap::reaches(const Vec3& x) const {
    return everywhere_ || flooded_[static_cast<std::size_t>(index(cell_of(x)))] != 0;
}

bool ReachMap::reaches(const io::Region& region) const {
    if (everywhere_) {
        return true;
    }
    const double half = 0.5 * cell_;
    for (Index k = 0; k < static_cast<Index>(flooded_.size()); ++k) {
        if (!flooded_[static_cast<std::size_t>(k)]) {
            continue;
        }
        const Vec3 x =
            centre({k % count_[0], (k / count_[0]) % count_[1], k / (count_[0] * count_[1])});
        bool meets = true;
        if (region.kind == io::Region::Kind::box) {
            for (int a = 0; a < dimension_; ++a) {
                meets = meets && x[a] - half <= region.upper[a] && x[a] + half >= region.lower[a];
            }
        } else {
            // The cell's corner farthest along the normal lies beyond the plane.
            double reach = (x - region.point).dot(region.normal);
            for (int a = 0; a < dimension_; ++a) {
                reach += half * std::abs(region.normal[a]);
            }
            meets = reach > 0.0;
        }
        if (meets) {
            return true;
        }
    }
    return false;
}

namespace {

/// Whether the flood reaches a cell of the wall's particles.
bool touches(const ReachMap& reach, const ParticleSet& particles, const Wall& wall) {
    for (Index i = wall.first; i < wall.first + wall.count; ++i) {
        if (reach.reaches(particles.position[i])) {
            return true;
        }
    }
    return false;
}

} // namespace

std::vector<std::string> outlet_reach_warnings(const ScenePlaces& places,
                                               const ParticleSet& particles,
                                               const std::vector<Wall>& walls,
                                               const particles::SinkSet& sinks,
                                               const SourceSet& sources, const Vec3& gravity,
                                               double spacing, int dimension) {
    const std::vector<io::KeyPlaces>& wall_tables = places.walls;
    std::vector<std::size_t> gates;
    for (std::size_t k = 0; k < wall_tables.size() && k < walls.size(); ++k) {
        if (wall_tables[k].has("remove_at") && walls[k].count > 0) {
            gates.push_back(k);
        }
    }
    std::vector<std::string> warnings;
    if (sinks.empty() && gates.empty()) {
        return warnings;
    }
    std::vector<io::Region> regions;
    for (const particles::SinkSet::Sink& sink : sinks.sinks()) {
        regions.push_back(sink.region);
    }
    // One flood per body a sink takes (-1: all), made when first needed.
    std::map<int, ReachMap> floods;
    auto flood = [&](int body) -> const ReachMap& {
        auto found = floods.find(body);
        if (found == floods.end()) {
            found = floods
                        .emplace(body, ReachMap(particles, walls, sources, regions, gravity,
                                                spacing, dimension, body))
                        .first;
        }
        return found->second;
    };
    const std::string beyond = "from where the bodies and sources start, the walls that stay "
                               "close it off or it lies above them";
    for (std::size_t s = 0; s < sinks.sinks().size(); ++s) {
        const particles::SinkSet::Sink& sink = sinks.sinks()[s];
        if (flood(sink.body).reaches(sink.region)) {
            continue;
        }
        const io::KeyPlaces& table = places.sinks[s];
        warnings.push_back(
            table.where(sink.region.kind == io::Region::Kind::box ? "min" : "point") + ": sink \"" +
            sink.name + "\" is out of reach of every particle: " + beyond +
            "; it will take nothing" +
            (sink.outlet ? ", and the Beverloo rate its outlet_width gives will not be seen" : ""));
    }
    for (const std::size_t k : gates) {
        if (!touches(flood(-1), particles, walls[k])) {
            warnings.push_back(wall_tables[k].where("remove_at") + ": wall \"" + walls[k].name +
                               "\" is removed but no body or source can reach it: " + beyond +
                               "; removing it releases nothing");
        }
    }
    return warnings;
}

} // namespace grainload::sph
