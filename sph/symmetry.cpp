#include "sph/symmetry.hpp"

#include <algorithm>
#include <cmath>

namespace grainload::sph {

Vec3 mirror_signs(MirrorMask mask) {
    Vec3 s;
    for (int a = 0; a < 3; ++a) {
        s[a] = (mask >> a) & 1U ? -1.0 : 1.0;
    }
    return s;
}

Vec3 mirror_position(const Vec3& x, MirrorMask mask, const Vec3& plane_at) {
    Vec3 y = x;
    for (int a = 0; a < 3; ++a) {
        if ((mask >> a) & 1U) {
            y[a] = 2.0 * plane_at[a] - x[a];
        }
    }
    return y;
}

Vec3 mirror_vector(const Vec3& v, MirrorMask mask) {
    return mirror_signs(mask).cwiseProduct(v);
}

Vec3 mirror_axial(const Vec3& w, MirrorMask mask) {
    // An axial vector transforms with det(R) R: a reflection (det -1) keeps the component
    // normal to the plane and flips those in it (Goldstein, Classical Mechanics, sec. 4.8).
    const Vec3 s = mirror_signs(mask);
    const double det = s[0] * s[1] * s[2];
    return det * s.cwiseProduct(w);
}

Voigt6 mirror_tensor(const Voigt6& t, MirrorMask mask) {
    const Vec3 s = mirror_signs(mask);
    Voigt6 y = t;
    y[3] *= s[0] * s[1]; // xy
    y[4] *= s[1] * s[2]; // yz
    y[5] *= s[2] * s[0]; // zx
    return y;
}

Mat3 mirror_matrix(const Mat3& m, MirrorMask mask) {
    const Vec3 s = mirror_signs(mask);
    return s.asDiagonal() * m * s.asDiagonal();
}

Vec3 plane_coordinates(std::span<const SymmetryPlane> planes) {
    Vec3 at = Vec3::Zero();
    for (const SymmetryPlane& plane : planes) {
        at[plane.axis] = plane.at;
    }
    return at;
}

std::vector<MirrorImage> select_images(std::span<const SymmetryPlane> planes,
                                       std::span<const Vec3> positions,
                                       std::span<const char> is_wall,
                                       std::span<const MirrorMask> allowed, double cutoff) {
    std::vector<MirrorImage> images;
    if (planes.empty()) {
        return images;
    }
    const auto n = static_cast<Index>(positions.size());
    const double on_plane = 1e-9 * cutoff;
    // Per particle, which planes it is near; then one image per non-empty subset of them.
    std::vector<MirrorMask> near(static_cast<std::size_t>(n), 0);
    for (Index i = 0; i < n; ++i) {
        for (const SymmetryPlane& plane : planes) {
            const double d = std::abs(positions[i][plane.axis] - plane.at);
            if (d < cutoff && d >= on_plane) {
                near[i] = static_cast<MirrorMask>(near[i] | (1U << plane.axis));
            }
        }
        near[i] = static_cast<MirrorMask>(near[i] & allowed[i]);
    }
    for (const char walls : {char{1}, char{0}}) {
        for (unsigned mask = 1; mask < 8; ++mask) {
            for (Index i = 0; i < n; ++i) {
                if (is_wall[i] == walls && near[i] != 0 && (near[i] & mask) == mask) {
                    images.push_back({i, static_cast<MirrorMask>(mask)});
                }
            }
        }
    }
    return images;
}

namespace {

template <class T> void resize_field(std::vector<T>& field, Index count) {
    field.resize(static_cast<std::size_t>(count));
}

} // namespace

void drop_images(ParticleSet& p, Index real_count) {
    resize_field(p.position, real_count);
    resize_field(p.velocity, real_count);
    resize_field(p.acceleration, real_count);
    resize_field(p.mass, real_count);
    resize_field(p.density, real_count);
    resize_field(p.density_rate, real_count);
    resize_field(p.internal_energy, real_count);
    resize_field(p.energy_rate, real_count);
    resize_field(p.stress, real_count);
    resize_field(p.strain_rate, real_count);
    resize_field(p.spin, real_count);
    resize_field(p.plastic_strain, real_count);
    resize_field(p.plastic_region, real_count);
    resize_field(p.body_id, real_count);
    resize_field(p.material_id, real_count);
    resize_field(p.wall_id, real_count);
    resize_field(p.clamped, real_count);
    resize_field(p.state_offset, real_count);
}

void write_images(ParticleSet& p, Index real_count, std::span<const MirrorImage> images,
                  const Vec3& plane_at) {
    drop_images(p, real_count + static_cast<Index>(images.size()));
    const auto count = static_cast<Index>(images.size());
#pragma omp parallel for schedule(static)
    for (Index k = 0; k < count; ++k) {
        const Index s = images[k].source;
        const MirrorMask mask = images[k].mask;
        const Index g = real_count + k;
        p.position[g] = mirror_position(p.position[s], mask, plane_at);
        p.velocity[g] = mirror_vector(p.velocity[s], mask);
        p.acceleration[g] = mirror_vector(p.acceleration[s], mask);
        p.mass[g] = p.mass[s];
        p.density[g] = p.density[s];
        p.density_rate[g] = p.density_rate[s];
        p.internal_energy[g] = p.internal_energy[s];
        p.energy_rate[g] = p.energy_rate[s];
        p.stress[g] = mirror_tensor(p.stress[s], mask);
        p.strain_rate[g] = mirror_tensor(p.strain_rate[s], mask);
        p.spin[g] = mirror_axial(p.spin[s], mask);
        p.plastic_strain[g] = p.plastic_strain[s];
        p.plastic_region[g] = p.plastic_region[s];
        p.body_id[g] = p.body_id[s];
        p.material_id[g] = p.material_id[s];
        p.wall_id[g] = p.wall_id[s];
        p.clamped[g] = 0;
        p.state_offset[g] = p.state_offset[s];
    }
}

} // namespace grainload::sph
