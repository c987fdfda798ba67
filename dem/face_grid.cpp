#include "dem/face_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grainload::dem {

namespace {

/// Cells along the grid's longest side at most: 64^3 cells bound the grid's memory whatever the
/// spheres' size.
constexpr double kMostCellsPerSide = 64.0;

} // namespace

void FaceGrid::build(std::span<const Box> faces, double reach) {
    reach_ = reach;
    Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 high = -low;
    for (const Box& box : faces) {
        low = low.cwiseMin(box.min);
        high = high.cwiseMax(box.max);
    }
    low.array() -= reach;
    high.array() += reach;
    origin_ = low;
    cell_ = std::max(reach, (high - low).maxCoeff() / kMostCellsPerSide);
    per_cell_ = 1.0 / cell_;
    for (int a = 0; a < 3; ++a) {
        dims_[a] = std::max<std::int64_t>(
            1, static_cast<std::int64_t>(std::ceil((high[a] - low[a]) / cell_)));
        end_[a] = origin_[a] + cell_ * static_cast<double>(dims_[a]);
    }
    // Two sweeps over the same ranges: count per cell, then fill, faces in ascending order.
    const auto cells = static_cast<std::size_t>(dims_[0] * dims_[1] * dims_[2]);
    first_.assign(cells + 1, 0);
    auto sweep = [&](auto&& visit) {
        for (std::size_t f = 0; f < faces.size(); ++f) {
            std::array<std::int64_t, 3> from{};
            std::array<std::int64_t, 3> to{};
            for (int a = 0; a < 3; ++a) {
                const auto at = [&](double x) {
                    return std::clamp<std::int64_t>(
                        static_cast<std::int64_t>(std::floor((x - origin_[a]) / cell_)), 0,
                        dims_[a] - 1);
                };
                from[a] = at(faces[f].min[a] - reach);
                to[a] = at(faces[f].max[a] + reach);
            }
            for (std::int64_t k = from[2]; k <= to[2]; ++k) {
                for (std::int64_t j = from[1]; j <= to[1]; ++j) {
                    for (std::int64_t i = from[0]; i <= to[0]; ++i) {
                        visit((k * dims_[1] + j) * dims_[0] + i, static_cast<std::int32_t>(f));
                    }
                }
            }
        }
    };
    sweep([&](std::int64_t cell, std::int32_t) { ++first_[static_cast<std::size_t>(cell) + 1]; });
    for (std::size_t c = 0; c < cells; ++c) {
        first_[c + 1] += first_[c];
    }
    faces_.resize(static_cast<std::size_t>(first_[cells]));
    std::vector<std::int64_t> next(first_.begin(), first_.end() - 1);
    sweep([&](std::int64_t cell, std::int32_t f) {
        faces_[static_cast<std::size_t>(next[static_cast<std::size_t>(cell)]++)] = f;
    });
}

std::span<const std::int32_t> FaceGrid::near(const Vec3& centre) const {
    // Most spheres lie outside most walls' grids (a silo's bands above and below theirs):
    // comparisons first.
    if (!((centre.array() >= origin_.array()).all() && (centre.array() < end_.array()).all())) {
        return {};
    }
    std::int64_t cell = 0;
    for (int a = 2; a >= 0; --a) {
        const auto x = static_cast<std::int64_t>((centre[a] - origin_[a]) * per_cell_);
        cell = cell * dims_[a] + std::min(x, dims_[a] - 1);
    }
    const auto c = static_cast<std::size_t>(cell);
    return {faces_.data() + first_[c], static_cast<std::size_t>(first_[c + 1] - first_[c])};
}

} // namespace grainload::dem
