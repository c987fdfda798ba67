#include "dem/grain_generator.hpp"

#include "io/case_error.hpp"

#include <cmath>
#include <random>
#include <unordered_map>

namespace grainload::dem {

namespace {

/// Uniform in [0, 1) from 53 bits of the generator, the same on every standard library.
double uniform(std::mt19937_64& generator) {
    return static_cast<double>(generator() >> 11) * 0x1.0p-53;
}

/// The grains placed so far, hashed by cell, for the overlap test of each new draw.
class PlacementGrid {
  public:
    PlacementGrid(const GrainSet& grains, double cell) : grains_(grains), cell_(cell) {
        for (Index i = 0; i < grains.size(); ++i) {
            insert(i);
        }
    }
    void insert(Index i) { cells_[key(cell_of(grains_.position[i]))].push_back(i); }
    bool free(const Vec3& centre, double radius) const {
        const Eigen::Vector3i c = cell_of(centre);
        for (int dx = -1; dx <= 1; ++dx) {
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dz = -1; dz <= 1; ++dz) {
                    const auto found = cells_.find(key(c + Eigen::Vector3i(dx, dy, dz)));
                    if (found == cells_.end()) {
                        continue;
                    }
                    for (const Index j : found->second) {
                        const double reach = radius + grains_.radius[j];
                        if ((grains_.position[j] - centre).squaredNorm() < reach * reach) {
                            return false;
                        }
                    }
                }
            }
        }
        return true;
    }

  private:
    Eigen::Vector3i cell_of(const Vec3& x) const { return (x / cell_).array().floor().cast<int>(); }
    static std::uint64_t key(const Eigen::Vector3i& c) {
        const auto part = [](int v) {
            return static_cast<std::uint64_t>(v + (1 << 20)) & 0x1fffff;
        };
        return part(c.x()) | part(c.y()) << 21 | part(c.z()) << 42;
    }
    const GrainSet& grains_;
    double cell_;
    std::unordered_map<std::uint64_t, std::vector<Index>> cells_;
};

} // namespace

void place_grains(const BodySettings& body, int body_id, double density, GrainSet& grains) {
    if (body.centre) {
        grains.add(body_id, body.radius_min, density, *body.centre, body.rotation);
        grains.velocity.back() = body.velocity;
        return;
    }
    double largest = body.radius_max;
    for (const double r : grains.radius) {
        largest = std::max(largest, r);
    }
    PlacementGrid grid(grains, 2.0 * largest);
    std::mt19937_64 generator(body.seed);
    // Ten thousand draws per grain before the box is called full: random sequential addition
    // jams near 0.38 of the volume (Torquato & Stillinger 2010), long before that runs out.
    // Each grain's radius is drawn once and kept through the draws of its centre: drawing it
    // anew with each centre would favour the small grains, which fit more often, and bias the
    // size distribution (by 2.7 % of the mass in the hopper's fill).
    const Index most_draws = 10000;
    Index placed = 0;
    for (bool fits = true; fits && placed < body.count;) {
        const double r = body.radius_min + (body.radius_max - body.radius_min) * uniform(generator);
        fits = false;
        for (Index draw = 0; draw < most_draws && !fits; ++draw) {
            Vec3 centre;
            for (int a = 0; a < 3; ++a) {
                centre[a] =
                    body.min[a] + r + (body.max[a] - body.min[a] - 2.0 * r) * uniform(generator);
            }
            fits = grid.free(centre, r);
            if (fits) {
                grains.add(body_id, r, density, centre, body.rotation);
                grains.velocity.back() = body.velocity;
                grid.insert(grains.size() - 1);
                ++placed;
            }
        }
    }
    if (placed < body.count) {
        throw io::CaseError(body.where + ": only " + std::to_string(placed) + " of its " +
                            std::to_string(body.count) +
                            " grains fit in its box at random; expected a larger box or a "
                            "smaller count (random packings jam near 0.38 of the volume)");
    }
}

} // namespace grainload::dem
