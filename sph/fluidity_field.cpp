#include "sph/fluidity_field.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <algorithm>
#include <cmath>

namespace grainload::sph {

void FluidityField::connect(const particles::NeighbourList& list, Index rows,
                            std::span<const Index> image_source, std::span<const char> carries,
                            std::span<const int> body) {
    auto source_of = [&](Index j) { return j < rows ? j : image_source[j - rows]; };
    auto joins = [&](Index i, Index j) {
        const Index s = source_of(j);
        return carries[i] != 0 && carries[s] != 0 && body[s] == body[i];
    };
    // Count, place, then sort and drop the duplicates of each row (a pair kept in both rows of
    // the list arrives twice).
    std::vector<Index> count(static_cast<std::size_t>(rows) + 1, 0);
    for (Index i = 0; i < rows; ++i) {
        for (const auto j : list.neighbours(i)) {
            if (joins(i, j)) {
                ++count[i + 1];
                if (j < rows) {
                    ++count[j + 1];
                }
            }
        }
    }
    for (Index i = 0; i < rows; ++i) {
        count[i + 1] += count[i];
    }
    std::vector<Index> places(static_cast<std::size_t>(count[rows]));
    std::vector<Index> fill(count.begin(), count.end() - 1);
    for (Index i = 0; i < rows; ++i) {
        for (const auto j : list.neighbours(i)) {
            if (joins(i, j)) {
                places[fill[i]++] = j;
                if (j < rows) {
                    places[fill[j]++] = i;
                }
            }
        }
    }
    offset_.assign(1, 0);
    place_.clear();
    for (Index i = 0; i < rows; ++i) {
        const auto first = places.begin() + count[i];
        const auto last = places.begin() + count[i + 1];
        std::sort(first, last);
        place_.insert(place_.end(), first, std::unique(first, last));
        offset_.push_back(static_cast<Index>(place_.size()));
    }
    partner_.resize(place_.size());
    std::transform(place_.begin(), place_.end(), partner_.begin(), source_of);
    weight_.assign(place_.size(), 0.0);
    active_.assign(static_cast<std::size_t>(rows), char{0});
    build_pattern();
    generation_ = list.generation();
}

void FluidityField::build_pattern() {
    const auto rows = static_cast<Index>(offset_.size()) - 1;
    std::vector<Index> outer(1, 0);
    std::vector<Index> inner;
    slot_.assign(partner_.size(), -1);
    diagonal_.resize(static_cast<std::size_t>(rows));
    std::vector<Index> columns;
    for (Index i = 0; i < rows; ++i) {
        columns.assign(partner_.begin() + offset_[i], partner_.begin() + offset_[i + 1]);
        columns.push_back(i);
        std::sort(columns.begin(), columns.end());
        columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
        const Index first = static_cast<Index>(inner.size());
        inner.insert(inner.end(), columns.begin(), columns.end());
        auto slot_of = [&](Index column) {
            return first +
                   (std::lower_bound(columns.begin(), columns.end(), column) - columns.begin());
        };
        diagonal_[i] = slot_of(i);
        for (Index e = offset_[i]; e < offset_[i + 1]; ++e) {
            // A particle beside its own mirror image: g_i - g_i adds nothing.
            slot_[e] = partner_[e] == i ? -1 : slot_of(partner_[e]);
        }
        outer.push_back(static_cast<Index>(inner.size()));
    }
    matrix_.resize(rows, rows);
    matrix_.resizeNonZeros(static_cast<Index>(inner.size()));
    std::copy(outer.begin(), outer.end(), matrix_.outerIndexPtr());
    std::copy(inner.begin(), inner.end(), matrix_.innerIndexPtr());
}

void FluidityField::weigh(std::span<const Vec3> positions, std::span<const double> volume,
                          std::span<const char> active, const SmoothingKernel& kernel) {
    const auto rows = static_cast<Index>(offset_.size()) - 1;
    const double eta_squared = 0.01 * kernel.smoothing_length() * kernel.smoothing_length();
    active_.assign(active.begin(), active.begin() + rows);
    volume_.assign(volume.begin(), volume.begin() + rows);
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < rows; ++i) {
        for (Index e = offset_[i]; e < offset_[i + 1]; ++e) {
            const Index j = partner_[e];
            if (active[i] == 0 || active[j] == 0) {
                weight_[e] = 0.0;
                continue;
            }
            const double r = (positions[i] - positions[place_[e]]).norm();
            // Brookshaw (1985): 2 V_j (x_ij . grad_i W_ij) / (r^2 + eta^2), with the sign that
            // makes the weight positive (W' < 0 inside the support).
            weight_[e] = -2.0 * volume[j] * kernel.radial_derivative(r) * r / (r * r + eta_squared);
        }
    }
}

FluiditySolve FluidityField::solve(std::span<const double> local, std::span<const double> screening,
                                   std::span<double> g, int maximum_iterations, double tolerance) {
    const auto rows = static_cast<Index>(offset_.size()) - 1;
    Eigen::VectorXd rhs(rows);
    double* values = matrix_.valuePtr();
    std::fill(values, values + matrix_.nonZeros(), 0.0);
    // Each row writes its own slots only: the fill is parallel and its sums keep their order.
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < rows; ++i) {
        if (active_[i] == 0) { // g = 0, decoupled (its weights, and its partners', are 0)
            values[diagonal_[i]] = 1.0;
            rhs[i] = 0.0;
            continue;
        }
        double diagonal = volume_[i] * screening[i];
        for (Index e = offset_[i]; e < offset_[i + 1]; ++e) {
            if (slot_[e] >= 0) {
                const double w = volume_[i] * weight_[e];
                values[slot_[e]] -= w;
                diagonal += w;
            }
        }
        rhs[i] = volume_[i] * screening[i] * local[i];
        if (!(diagonal > 0.0)) { // alone and at mu_s: nothing sets g but its local value, 0
            diagonal = 1.0;
            rhs[i] = local[i];
        }
        values[diagonal_[i]] = diagonal;
    }
    Eigen::Map<Eigen::VectorXd> field(g.data(), rows);
    if (rhs.squaredNorm() == 0.0) { // no source anywhere: the field is 0
        field.setZero();
        return {};
    }
    Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper,
                             Eigen::DiagonalPreconditioner<double>>
        solver;
    solver.setMaxIterations(maximum_iterations);
    solver.setTolerance(tolerance);
    solver.compute(matrix_);
    const Eigen::VectorXd start = field;
    field = solver.solveWithGuess(rhs, start);
    return {static_cast<int>(solver.iterations()), solver.error()};
}

double FluidityField::laplacian(std::span<const double> g, Index i) const {
    double sum = 0.0;
    for (Index e = offset_[i]; e < offset_[i + 1]; ++e) {
        sum += weight_[e] * (g[partner_[e]] - g[i]);
    }
    return sum;
}

std::size_t FluidityField::bytes() const {
    auto held = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
    return held(offset_) + held(partner_) + held(place_) + held(weight_) + held(slot_) +
           held(diagonal_) + held(active_) + held(volume_) +
           static_cast<std::size_t>(matrix_.nonZeros()) * (sizeof(double) + sizeof(Index)) +
           static_cast<std::size_t>(matrix_.outerSize() + 1) * sizeof(Index);
}

} // namespace grainload::sph
