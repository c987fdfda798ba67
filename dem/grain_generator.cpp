#include "dem/grain_generator.hpp"

#include "io/case_error.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <unordered_map>

namespace grainload::dem {

namespace {

/// The spheres placed so far, hashed by cell, for the overlap test of each new draw.
class PlacementGrid {
  public:
    PlacementGrid(const SphereSet& spheres, double cell) : spheres_(spheres), cell_(cell) {
        for (Index i = 0; i < spheres.size(); ++i) {
            insert(i);
        }
    }
    void insert(Index i) { cells_[key(cell_of(spheres_.position[i]))].push_back(i); }
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
                        const double reach = radius + spheres_.radius[j];
                        if ((spheres_.position[j] - centre).squaredNorm() < reach * reach) {
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
    const SphereSet& spheres_;
    double cell_;
    std::unordered_map<std::uint64_t, std::vector<Index>> cells_;
};

/// A centre drawn uniformly where a grain of `shape`, turned by `turned`, lies wholly inside the
/// body's box.
Vec3 draw_centre(const BodySettings& body, const GrainShape& shape,
                 const Eigen::Quaterniond& turned, std::mt19937_64& generator) {
    const Vec3 margin = grain_reach(shape, turned);
    Vec3 centre;
    for (int a = 0; a < 3; ++a) {
        centre[a] = body.min[a] + margin[a] +
                    (body.max[a] - body.min[a] - 2.0 * margin[a]) * uniform(generator);
    }
    return centre;
}

/// A clump of spheres at `body.sphere_centres` (in the grain's radius r), of radii
/// `body.sphere_radii` (the same units; all r when none): its mass the spheres' sum, its centre
/// of mass their mass-weighted centre, its inertia tensor about that centre the sum of
/// (2/5) m_k r_k^2 1 + m_k (|d_k|^2 1 - d_k d_k^T) over the spheres at d_k from it (the parallel
/// axis theorem; touching spheres share no volume), diagonalised: the principal moments are the
/// grain's, and its own frame is the principal one (right-handed), in which the sphere offsets
/// are stated.
GrainShape clump_shape(const BodySettings& body, double radius, double density) {
    const std::vector<Vec3>& centres = body.sphere_centres;
    GrainShape shape;
    shape.radius = radius;
    const double one = sphere_mass(radius, density);
    const auto k = static_cast<double>(centres.size());
    // Each sphere's mass over one of radius r: its radius cubed (1 for equal spheres, whose
    // sums below are those of k equal terms).
    std::vector<double> weight;
    for (std::size_t s = 0; s < centres.size(); ++s) {
        const double r = body.sphere_radius(s);
        weight.push_back(r * r * r);
        shape.radii.push_back(r * radius);
    }
    const double total = body.volume_ratio();
    shape.mass = total * one;
    Vec3 centroid = Vec3::Zero();
    for (std::size_t s = 0; s < centres.size(); ++s) {
        centroid += weight[s] * centres[s];
    }
    centroid /= total;
    Mat3 tensor = k * 0.4 * one * radius * radius * Mat3::Identity();
    if (!body.sphere_radii.empty()) {
        tensor.setZero();
        for (std::size_t s = 0; s < centres.size(); ++s) {
            tensor += 0.4 * weight[s] * one * shape.radii[s] * shape.radii[s] * Mat3::Identity();
        }
    }
    for (std::size_t s = 0; s < centres.size(); ++s) {
        const Vec3 d = radius * (centres[s] - centroid);
        tensor += weight[s] * one * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
    }
    const Eigen::SelfAdjointEigenSolver<Mat3> principal(tensor);
    Mat3 axes = principal.eigenvectors();
    if (axes.determinant() < 0.0) {
        axes.col(2) = -axes.col(2);
    }
    shape.inertia = principal.eigenvalues();
    for (const Vec3& c : centres) {
        shape.offsets.push_back(axes.transpose() * (radius * (c - centroid)));
    }
    return shape;
}

} // namespace

double uniform(std::mt19937_64& generator) {
    return static_cast<double>(generator() >> 11) * 0x1.0p-53;
}

Eigen::Quaterniond random_orientation(std::mt19937_64& generator) {
    const double u1 = uniform(generator);
    const double u2 = 2.0 * std::numbers::pi * uniform(generator);
    const double u3 = 2.0 * std::numbers::pi * uniform(generator);
    const double a = std::sqrt(1.0 - u1);
    const double b = std::sqrt(u1);
    return Eigen::Quaterniond(b * std::cos(u3), a * std::sin(u2), a * std::cos(u2),
                              b * std::sin(u3));
}

Vec3 grain_reach(const GrainShape& shape, const Eigen::Quaterniond& turned) {
    Vec3 reach = Vec3::Zero();
    for (std::size_t s = 0; s < shape.offsets.size(); ++s) {
        reach = reach.cwiseMax(
            Vec3(Vec3::Constant(shape.radii[s]) + (turned * shape.offsets[s]).cwiseAbs()));
    }
    return reach;
}

double draw_radius(const BodySettings& body, std::mt19937_64& generator) {
    return body.radius_min + (body.radius_max - body.radius_min) * uniform(generator);
}

Index add_grain(const BodySettings& body, int body_id, const GrainShape& shape, const Vec3& centre,
                const Eigen::Quaterniond& turned, const Vec3& velocity,
                const Vec3& angular_velocity, GrainSet& grains, SphereSet& spheres) {
    const Index g = grains.add(body_id, shape.mass, body.rotation ? shape.inertia : Vec3::Zero(),
                               centre, turned);
    grains.velocity[static_cast<std::size_t>(g)] = velocity;
    grains.angular_velocity[static_cast<std::size_t>(g)] =
        body.rotation ? angular_velocity : Vec3::Zero();
    for (std::size_t s = 0; s < shape.offsets.size(); ++s) {
        spheres.add(g, shape.radii[s], shape.offsets[s]);
    }
    return g;
}

GrainShape grain_shape(const BodySettings& body, double radius, double density) {
    if (!body.sphere_centres.empty()) {
        return clump_shape(body, radius, density);
    }
    GrainShape shape;
    shape.radius = radius;
    shape.radii.assign(static_cast<std::size_t>(body.spheres), radius);
    const double one = sphere_mass(radius, density);
    const double own = 0.4 * one * radius * radius;
    const double spacing = body.sphere_distance * 2.0 * radius;
    const auto k = static_cast<double>(body.spheres);
    shape.mass = k * one;
    shape.inertia = Vec3(k * own, 0.0, 0.0);
    for (int j = 0; j < body.spheres; ++j) {
        const double x = (static_cast<double>(j) - 0.5 * (k - 1.0)) * spacing;
        shape.offsets.emplace_back(x, 0.0, 0.0);
        shape.inertia.y() += own + one * x * x;
    }
    shape.inertia.z() = shape.inertia.y();
    return shape;
}

void place_grains(const BodySettings& body, int body_id, double density, GrainSet& grains,
                  SphereSet& spheres) {
    if (body.centre) {
        const Vec3 axis = body.axis.normalized();
        add_grain(body, body_id, grain_shape(body, body.radius_min, density), *body.centre,
                  Eigen::Quaterniond::FromTwoVectors(Vec3::UnitX(), axis), body.velocity,
                  body.angular_velocity, grains, spheres);
        spheres.place(grains);
        return;
    }
    double largest = body.radius_max * body.largest_sphere();
    for (const double r : spheres.radius) {
        largest = std::max(largest, r);
    }
    PlacementGrid grid(spheres, 2.0 * largest);
    std::mt19937_64 generator(body.seed);
    // Ten thousand draws per grain before the box is called full: random sequential addition
    // jams near 0.38 of the volume (Torquato & Stillinger 2010), long before that runs out.
    // Each grain's radius is drawn once and kept through the draws of its centre: drawing it
    // anew with each centre would favour the small grains, which fit more often, and bias the
    // size distribution (by 2.7 % of the mass in the hopper's fill).
    const Index most_draws = 10000;
    Index placed = 0;
    for (bool fits = true; fits && placed < body.count;) {
        const double r = draw_radius(body, generator);
        const GrainShape shape = grain_shape(body, r, density);
        fits = false;
        for (Index draw = 0; draw < most_draws && !fits; ++draw) {
            // A sphere keeps the identity: its draws are the centre's alone. A clump's
            // orientation comes first, and the centre where each of its spheres fits.
            const Eigen::Quaterniond turned =
                body.spheres > 1 ? random_orientation(generator) : Eigen::Quaterniond::Identity();
            const Vec3 centre = draw_centre(body, shape, turned, generator);
            fits = true;
            for (std::size_t s = 0; s < shape.offsets.size() && fits; ++s) {
                fits = grid.free(centre + turned * shape.offsets[s], shape.radii[s]);
            }
            if (fits) {
                add_grain(body, body_id, shape, centre, turned, body.velocity,
                          body.angular_velocity, grains, spheres);
                spheres.place(grains);
                for (std::size_t k = 0; k < shape.offsets.size(); ++k) {
                    grid.insert(spheres.size() - 1 - static_cast<Index>(k));
                }
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
