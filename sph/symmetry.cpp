#include "sph/symmetry.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

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

template <class> inline constexpr bool unsupported_rule = false;

/// The value particle s's image carries in a field registered as `Field` (its Mirror rule,
/// sph/particle_set.hpp); a rule that does not fit the field's value type stops the build.
template <class Field>
typename Field::value_type image_value(const typename Field::value_type& value, MirrorMask mask,
                                       const Vec3& plane_at) {
    using T = typename Field::value_type;
    constexpr Mirror rule = Field::mirror;
    if constexpr (rule == Mirror::copy) {
        return value;
    } else if constexpr (rule == Mirror::cleared && std::is_arithmetic_v<T>) {
        return T{0};
    } else if constexpr (rule == Mirror::point && std::is_same_v<T, Vec3>) {
        return mirror_position(value, mask, plane_at);
    } else if constexpr (rule == Mirror::polar && std::is_same_v<T, Vec3>) {
        return mirror_vector(value, mask);
    } else if constexpr (rule == Mirror::axial && std::is_same_v<T, Vec3>) {
        return mirror_axial(value, mask);
    } else if constexpr (rule == Mirror::tensor && std::is_same_v<T, Voigt6>) {
        return mirror_tensor(value, mask);
    } else {
        static_assert(unsupported_rule<Field>, "Mirror rule does not fit the field's type");
    }
}

} // namespace

void drop_images(ParticleSet& p, Index real_count) {
    const auto count = static_cast<std::size_t>(real_count);
    p.for_each_field([count](const auto&, auto& values) { values.resize(count); });
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
        p.for_each_field([&](const auto& field, auto& values) {
            using Field = std::remove_cvref_t<decltype(field)>;
            values[g] = image_value<Field>(values[s], mask, plane_at);
        });
    }
}

} // namespace grainload::sph
