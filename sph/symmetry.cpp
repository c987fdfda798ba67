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

Vec3 image_position(const Vec3& x, const GhostImage& image, const ImageFrame& frame) {
    Vec3 y = mirror_position(x, image.mask, frame.plane_at);
    for (int a = 0; a < 3; ++a) {
        if ((image.shift_up >> a) & 1U) {
            y[a] += frame.period[a];
        } else if ((image.shift_down >> a) & 1U) {
            y[a] -= frame.period[a];
        }
    }
    return y;
}

ImageFrame image_frame(std::span<const SymmetryPlane> planes,
                       std::span<const PeriodicAxis> periodic) {
    ImageFrame frame;
    for (const SymmetryPlane& plane : planes) {
        frame.plane_at[plane.axis] = plane.at;
    }
    for (const PeriodicAxis& axis : periodic) {
        frame.period[axis.axis] = axis.period();
    }
    return frame;
}

void wrap_periodic(std::span<Vec3> positions, std::span<const char> is_wall,
                   std::span<const PeriodicAxis> periodic) {
    for (std::size_t i = 0; i < positions.size(); ++i) {
        if (is_wall[i]) {
            continue;
        }
        for (const PeriodicAxis& axis : periodic) {
            double& x = positions[i][axis.axis];
            if (x >= axis.max) {
                x -= axis.period();
            } else if (x < axis.min) {
                x += axis.period();
            }
        }
    }
}

Vec3 nearest_image(Vec3 d, std::span<const PeriodicAxis> periodic) {
    for (const PeriodicAxis& axis : periodic) {
        d[axis.axis] -= axis.period() * std::round(d[axis.axis] / axis.period());
    }
    return d;
}

namespace {

/// The axes a particle is near (its images' combinations are the subsets of `axes`), and along
/// which of them an image is shifted up or down rather than reflected.
struct NearAxes {
    MirrorMask axes = 0;
    MirrorMask up = 0;
    MirrorMask down = 0;
};

NearAxes near_axes(const Vec3& x, std::span<const SymmetryPlane> planes,
                   std::span<const PeriodicAxis> periodic, MirrorMask allowed, double cutoff) {
    const double on_plane = 1e-9 * cutoff;
    NearAxes near;
    for (const SymmetryPlane& plane : planes) {
        const double d = std::abs(x[plane.axis] - plane.at);
        if (d < cutoff && d >= on_plane) {
            near.axes = static_cast<MirrorMask>(near.axes | (1U << plane.axis));
        }
    }
    near.axes = static_cast<MirrorMask>(near.axes & allowed);
    for (const PeriodicAxis& axis : periodic) {
        const auto bit = static_cast<MirrorMask>(1U << axis.axis);
        if (x[axis.axis] - axis.min < cutoff) {
            near.axes = static_cast<MirrorMask>(near.axes | bit);
            near.up = static_cast<MirrorMask>(near.up | bit);
        } else if (axis.max - x[axis.axis] < cutoff) {
            near.axes = static_cast<MirrorMask>(near.axes | bit);
            near.down = static_cast<MirrorMask>(near.down | bit);
        }
    }
    return near;
}

} // namespace

std::vector<GhostImage> select_images(std::span<const SymmetryPlane> planes,
                                      std::span<const PeriodicAxis> periodic,
                                      std::span<const Vec3> positions,
                                      std::span<const char> is_wall,
                                      std::span<const MirrorMask> allowed, double cutoff) {
    std::vector<GhostImage> images;
    if (planes.empty() && periodic.empty()) {
        return images;
    }
    const auto n = static_cast<Index>(positions.size());
    // Per particle, which axes it is near; then one image per non-empty subset of them.
    std::vector<NearAxes> near(static_cast<std::size_t>(n));
    for (Index i = 0; i < n; ++i) {
        near[i] = near_axes(positions[i], planes, periodic, allowed[i], cutoff);
    }
    for (const char walls : {char{1}, char{0}}) {
        for (unsigned mask = 1; mask < 8; ++mask) {
            for (Index i = 0; i < n; ++i) {
                const NearAxes& a = near[i];
                if (is_wall[i] == walls && a.axes != 0 && (a.axes & mask) == mask) {
                    const auto shifted = static_cast<MirrorMask>(a.up | a.down);
                    images.push_back({i, static_cast<MirrorMask>(mask & ~shifted),
                                      static_cast<MirrorMask>(mask & a.up),
                                      static_cast<MirrorMask>(mask & a.down)});
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
typename Field::value_type image_value(const typename Field::value_type& value,
                                       const GhostImage& image, const ImageFrame& frame) {
    const MirrorMask mask = image.mask;
    using T = typename Field::value_type;
    constexpr Mirror rule = Field::mirror;
    if constexpr (rule == Mirror::copy) {
        return value;
    } else if constexpr (rule == Mirror::cleared && std::is_arithmetic_v<T>) {
        return T{0};
    } else if constexpr (rule == Mirror::point && std::is_same_v<T, Vec3>) {
        return image_position(value, image, frame);
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

void write_images(ParticleSet& p, Index real_count, std::span<const GhostImage> images,
                  const ImageFrame& frame) {
    drop_images(p, real_count + static_cast<Index>(images.size()));
    const auto count = static_cast<Index>(images.size());
#pragma omp parallel for schedule(static)
    for (Index k = 0; k < count; ++k) {
        const GhostImage& image = images[k];
        const Index g = real_count + k;
        p.for_each_field([&](const auto& field, auto& values) {
            using Field = std::remove_cvref_t<decltype(field)>;
            values[g] = image_value<Field>(values[image.source], image, frame);
        });
    }
}

} // namespace grainload::sph
