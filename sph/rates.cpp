#include "sph/rates.hpp"

#include "sph/pair_parts.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <type_traits>

namespace grainload::sph {

// Randles & Libersky (1996): M^-1 makes L M^-1 exact for linear fields. In plane strain M
// has no z row or column; its zz entry is set to 1 so that the inverse exists and z stays
// untouched.
//
// M -> I in the interior, and its smallest singular value s is about 0.5 at a flat free
// surface and 0.27 (2D) / 0.21 (3D) at a lattice corner. A particle whose neighbours are nearly
// collinear (a thinning flow front) has s -> 0 while det M can still be well above any fixed
// threshold; M^-1 then multiplies the velocity gradient by 1/s and the continuity equation can
// drive the density negative in one step. So the correction is blended to the plain gradient
// by s: full for s >= 0.15 (every lattice configuration), none for s <= 0.05, linear between.
Mat3 correction_inverse(Mat3 moment, int dimension) {
    if (dimension == 2) {
        moment(2, 2) = 1.0;
    }
    constexpr double full = 0.15;
    constexpr double none = 0.05;
    Eigen::SelfAdjointEigenSolver<Mat3> eigen;
    eigen.computeDirect(moment.transpose() * moment, Eigen::EigenvaluesOnly);
    const double smallest = std::sqrt(std::max(eigen.eigenvalues()(0), 0.0));
    if (!(smallest > none)) {
        return Mat3::Identity();
    }
    const Mat3 inverse = moment.inverse();
    if (smallest >= full) {
        return inverse;
    }
    const double weight = (smallest - none) / (full - none);
    return weight * inverse + (1.0 - weight) * Mat3::Identity();
}

void store_kinematics(ParticleSet& p, Index i, const Mat3& l) {
    p.density_rate[i] = -p.density[i] * l.trace();
    const Mat3 d = 0.5 * (l + l.transpose());
    p.strain_rate[i] << d(0, 0), d(1, 1), d(2, 2), 2.0 * d(0, 1), 2.0 * d(1, 2), 2.0 * d(2, 0);
    const Mat3 w = 0.5 * (l - l.transpose());
    p.spin[i] = Vec3(w(2, 1), w(0, 2), w(1, 0));
}

namespace {

/// Where a part of the kinematic pass adds: L and M of particle k as 9 doubles (column major,
/// as Mat3 stores them) at 9 (k - origin); `moment` is nullptr without the correction.
struct GradientSums {
    double* l;
    double* moment;
    Index origin;
};

/// Row i of the velocity-gradient pass in D = 2 or 3 components (plane-strain particles have
/// z = 0, so the z row and column of L and M are exact zeros and are left out). Each same-body
/// pair is taken once, from the row of its lower index (sph/pair_parts.hpp): with
/// dv = v_j - v_i and g = grad_i W_ij, i gains m_j dv g^T and j gains m_i dv g^T (grad_j W_ji =
/// -g and v_i - v_j = -dv); the moment -m x_ij g^T likewise.
template <class Shape, int D, bool Corrected> struct GradientRow {
    const ParticleSet& p;
    const particles::NeighbourList& neighbours;
    const ShapeTerms<Shape> w;
    const std::vector<int>& key;
    const double support_squared;
    double* entry_factor; ///< nullptr, or W'(r)/r of each same-body entry in the support
    /// The records (pair_lanes.hpp) where the pairs run in vector lanes (3D cubic spline without
    /// correction, on AVX2; the same bits), else nullptr.
    const PairRecord* records;

    /// The row's entries in batches: first the same-body pairs in the support are picked and
    /// their W'(r)/r computed in a loop of their own (no branch and no dependence between
    /// pairs, so the square roots and divisions of successive pairs overlap instead of each
    /// pair's chain waiting on them), then the sums are added in the entries' order.
    void operator()(Index i, const GradientSums& sums) const {
        if (p.wall_id[i] >= 0) {
            return; // a wall particle's key is its own: no same-body pair
        }
        if (records != nullptr) {
            lane_row(i, sums);
            return;
        }
        Sums acc{};
        const auto list = neighbours.neighbours(i);
        double* factor_of_entry =
            entry_factor != nullptr ? entry_factor + neighbours.first_entry(i) : nullptr;
        Batch b;
        for (std::size_t start = 0; start < list.size(); start += kBatch) {
            pick(i, list, start, std::min(list.size(), start + kBatch), b);
            for (int m = 0; m < b.count; ++m) {
                b.f[m] = w.gradient_factor_inside(std::sqrt(b.r2[m]));
            }
            if (factor_of_entry != nullptr) {
                for (int m = 0; m < b.count; ++m) {
                    factor_of_entry[b.k[m]] = b.f[m];
                }
            }
            add_batch(i, b, acc, sums);
        }
        double* li = sums.l + 9 * (i - sums.origin);
        for (int r = 0; r < D; ++r) {
            for (int c = 0; c < D; ++c) {
                li[3 * c + r] += acc.l[r][c];
            }
        }
        if constexpr (Corrected) {
            double* mo_i = sums.moment + 9 * (i - sums.origin);
            for (int r = 0; r < D; ++r) {
                for (int c = 0; c < D; ++c) {
                    mo_i[3 * c + r] += acc.moment[r][c];
                }
            }
        }
    }

  private:
    static constexpr std::size_t kBatch = 64;

    /// Row i in vector lanes (gradient_lanes): the row's same-body pairs i < j picked a batch
    /// of entries at a time, in the list's order, inside the support or not (the entries as
    /// they are where the whole row is such pairs, NeighbourList::same_key_row).
    void lane_row(Index i, const GradientSums& sums) const {
        const LaneSettings lanes{
            support_squared, w.inverse_h, w.alpha_over_h, 0.0, 0.0, 0.0, 0.0, 0.0};
        double acc[9] = {}; // column major
        const auto list = neighbours.neighbours(i);
        std::int32_t picked[kLaneBatch];
        const bool whole = neighbours.same_key_row(i); // every entry a pair to take
        for (std::size_t first = 0; first < list.size(); first += kLaneBatch) {
            const std::size_t end = std::min(list.size(), first + kLaneBatch);
            const int count = whole ? static_cast<int>(end - first)
                                    : pick_same_body_pairs(list, first, end, key, i, picked).count;
            if (count > 0) {
                gradient_lanes(records, i, whole ? list.data() + first : picked, count, lanes,
                               sums.l, sums.origin, acc);
            }
        }
        double* li = sums.l + 9 * (i - sums.origin);
        for (int c = 0; c < 9; ++c) {
            li[c] += acc[c];
        }
    }

    /// A batch's same-body pairs i < j in the support: j, list entry, r^2, x_ij, W'(r)/r.
    struct Batch {
        int count;
        Index j[kBatch];
        std::size_t k[kBatch];
        double r2[kBatch];
        double d[D][kBatch];
        double f[kBatch];
    };
    struct Sums {
        double l[D][D];
        double moment[D][D];
    };

    /// Entries [start, end) of row i that are same-body pairs i < j in the support.
    void pick(Index i, std::span<const std::int32_t> list, std::size_t start, std::size_t end,
              Batch& b) const {
        b.count = 0;
        const Vec3 xi = p.position[i];
        const int key_i = key[i];
        for (std::size_t k = start; k < end; ++k) {
            const Index j = list[k];
            if (key[j] != key_i || j < i) {
                continue; // another body, a wall, or the pair's other row
            }
            double d[D];
            const double r2 = separation(xi, p.position[j], d);
            if (r2 >= support_squared || r2 == 0.0) {
                continue;
            }
            b.j[b.count] = j;
            b.k[b.count] = k;
            b.r2[b.count] = r2;
            for (int c = 0; c < D; ++c) {
                b.d[c][b.count] = d[c];
            }
            ++b.count;
        }
    }

    /// i gains m_j dv g^T, j gains m_i dv g^T (and the moments), pair by pair in order.
    void add_batch(Index i, const Batch& b, Sums& acc, const GradientSums& sums) const {
        const Vec3 vi = p.velocity[i];
        const double mi = p.mass[i];
        for (int m = 0; m < b.count; ++m) {
            const Index j = b.j[m];
            double g[D];
            for (int c = 0; c < D; ++c) {
                g[c] = b.f[m] * b.d[c][m];
            }
            const double mj = p.mass[j];
            const Vec3& vj = p.velocity[j];
            double* lj = sums.l + 9 * (j - sums.origin);
            for (int r = 0; r < D; ++r) {
                const double dv = vj[r] - vi[r];
                for (int c = 0; c < D; ++c) {
                    const double term = dv * g[c];
                    acc.l[r][c] += mj * term;
                    lj[3 * c + r] += mi * term;
                }
            }
            if constexpr (Corrected) {
                double* mo_j = sums.moment + 9 * (j - sums.origin);
                for (int r = 0; r < D; ++r) {
                    for (int c = 0; c < D; ++c) {
                        const double term = b.d[r][m] * g[c];
                        acc.moment[r][c] -= mj * term;
                        mo_j[3 * c + r] -= mi * term;
                    }
                }
            }
        }
    }
};

/// Adds part r's sums of particle i (r >= 1) to the first part's: 9 doubles from `from`.
void add_nine(double* to, const double* from) {
    for (int c = 0; c < 9; ++c) {
        to[c] += from[c];
    }
}

/// Particle i's position, velocity and mass in its record: all the kinematic lanes read.
void write_kinematic_fields(const ParticleSet& p, Index i, PairRecord& record) {
    for (int c = 0; c < 3; ++c) {
        record.position[c] = p.position[i][c];
        record.velocity[c] = p.velocity[i][c];
    }
    record.mass = p.mass[i];
}

/// The later parts' sums added to the first part's in the parts' order, then L = sum / rho
/// (times the correction's inverse, whose transpose is kept for the force pass), stored with its
/// strain rate and spin.
template <bool Corrected, class SumsOf>
void finish_velocity_gradient(ParticleSet& p, const SmoothingKernel& kernel, const PairParts& parts,
                              const SumsOf& sums_of, std::vector<Mat3>& velocity_gradient,
                              std::vector<Mat3>& correction) {
    const Index n = p.size();
    // Dynamic: the material particles, whose sums are finished here, and the walls, which
    // have none, lie in blocks.
#pragma omp parallel for schedule(dynamic, 256)
    for (Index i = 0; i < n; ++i) {
        if (p.wall_id[i] >= 0) {
            if constexpr (Corrected) {
                correction[i] = Mat3::Identity();
            }
            continue;
        }
        for_later_parts(parts, i, [&](int r, Index k) {
            const GradientSums part = sums_of(r);
            add_nine(velocity_gradient[i].data(), part.l + 9 * k);
            if constexpr (Corrected) {
                add_nine(correction[i].data(), part.moment + 9 * k);
            }
        });
        Mat3 l = velocity_gradient[i] / p.density[i];
        if constexpr (Corrected) {
            const Mat3 inverse =
                correction_inverse(correction[i] / p.density[i], kernel.dimension());
            l = l * inverse;
            correction[i] = inverse.transpose();
        }
        velocity_gradient[i] = l;
        store_kinematics(p, i, l);
    }
}

template <class Shape, int D, bool Corrected>
void velocity_gradient_pass(ParticleSet& p, const particles::NeighbourList& neighbours,
                            const SmoothingKernel& kernel, std::vector<Mat3>& velocity_gradient,
                            std::vector<Mat3>& correction, double* entry_factor,
                            PairScratch& scratch, PairArithmetic arithmetic,
                            std::vector<PairRecord>* records) {
    const Index n = p.size();
    const bool lanes = records != nullptr && entry_factor == nullptr &&
                       arithmetic == PairArithmetic::lanes_where_available && D == 3 &&
                       !Corrected && std::is_same_v<Shape, CubicSplineKernel> &&
                       pair_lanes_available();
    std::vector<int> key(static_cast<std::size_t>(n));
    if (lanes) {
        records->resize(static_cast<std::size_t>(n));
    }
    const GradientRow<Shape, D, Corrected> row{p,
                                               neighbours,
                                               ShapeTerms<Shape>(kernel),
                                               key,
                                               kernel.support_radius() * kernel.support_radius(),
                                               entry_factor,
                                               lanes ? records->data() : nullptr};
    // The first part sums into velocity_gradient and (the moments) correction themselves.
    // Zeroed on all threads (a serial fill of 72 bytes a particle had the other thread wait), in
    // the loop that sets the particles' keys and the material particles' kinematic records.
    velocity_gradient.resize(static_cast<std::size_t>(n));
    if constexpr (Corrected) {
        correction.resize(static_cast<std::size_t>(n));
    }
    if (n == 0) {
        return;
    }
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        key[i] = continuum_key(p.wall_id[i] >= 0, p.body_id[i], i);
        if (lanes && p.wall_id[i] < 0) {
            write_kinematic_fields(p, i, (*records)[static_cast<std::size_t>(i)]);
        }
        velocity_gradient[i].setZero();
        if constexpr (Corrected) {
            correction[i].setZero();
        }
    }
    const PairParts parts = split_rows(neighbours, n, n, pass_parts());
    constexpr int width = Corrected ? 18 : 9;
    scratch.reserve(parts, width);
    // A later part's window: L of its particles, then (corrected) their moments.
    auto sums_of = [&](int r) {
        if (r == 0) {
            return GradientSums{velocity_gradient.data()->data(),
                                Corrected ? correction.data()->data() : nullptr, 0};
        }
        double* base = scratch.part(r);
        return GradientSums{base, Corrected ? base + 9 * parts.window(r) : nullptr,
                            parts.origin(r)};
    };
    for_each_part(parts, scratch, width, [&](Index i, int r) { row(i, sums_of(r)); });
    finish_velocity_gradient<Corrected>(p, kernel, parts, sums_of, velocity_gradient, correction);
}

/// Particle i's record of the force pass, written in place: sigma/rho^2 entries, each product
/// formed as the full tensor's was, and the fields its pair terms read.
void write_pair_record(const ParticleSet& p, Index i, const Mat3& sigma, double inv_rho2,
                       const std::vector<double>& sound_speed, PairRecord& record) {
    const double stress[6] = {sigma(0, 0), sigma(1, 1), sigma(2, 2),
                              sigma(0, 1), sigma(0, 2), sigma(1, 2)};
    for (int k = 0; k < 6; ++k) {
        record.stress[k] = stress[k] * inv_rho2;
    }
    record.density = p.density[i];
    record.unused = 0.0;
    write_kinematic_fields(p, i, record);
    record.sound_speed = sound_speed.empty() ? 0.0 : sound_speed[static_cast<std::size_t>(i)];
}

} // namespace

void compute_velocity_gradient(ParticleSet& p, const particles::NeighbourList& neighbours,
                               const SmoothingKernel& kernel, bool gradient_correction,
                               std::vector<Mat3>& velocity_gradient, std::vector<Mat3>& correction,
                               std::vector<double>* entry_factor, PairScratch* scratch,
                               PairArithmetic arithmetic, std::vector<PairRecord>* records) {
    if (entry_factor != nullptr) {
        entry_factor->resize(static_cast<std::size_t>(neighbours.pair_entries()));
    }
    double* factors = entry_factor != nullptr ? entry_factor->data() : nullptr;
    if (!gradient_correction) {
        correction.clear();
    }
    PairScratch own;
    PairScratch& sums = scratch != nullptr ? *scratch : own;
    kernel.visit_shape([&](auto shape) {
        using Shape = decltype(shape);
        auto pass = [&](auto dimension, auto corrected) {
            velocity_gradient_pass<Shape, decltype(dimension)::value, decltype(corrected)::value>(
                p, neighbours, kernel, velocity_gradient, correction, factors, sums, arithmetic,
                records);
        };
        using Two = std::integral_constant<int, 2>;
        using Three = std::integral_constant<int, 3>;
        if (kernel.dimension() == 2) {
            gradient_correction ? pass(Two{}, std::true_type{}) : pass(Two{}, std::false_type{});
        } else {
            gradient_correction ? pass(Three{}, std::true_type{})
                                : pass(Three{}, std::false_type{});
        }
    });
}

void prepare_force_inputs(const ParticleSet& p, const ArtificialStress& artificial,
                          ForceInputs& inputs) {
    const Index n = p.size();
    const bool corrected = !inputs.gradient_correction.empty();
    if (corrected) {
        inputs.stress_over_rho2.resize(static_cast<std::size_t>(n));
        inputs.pair_records.clear();
    } else {
        inputs.pair_records.resize(static_cast<std::size_t>(n));
        inputs.stress_over_rho2.clear();
    }
    const bool artificial_on = artificial.epsilon > 0.0;
    if (artificial_on) {
        inputs.artificial_stress.resize(static_cast<std::size_t>(n));
    } else {
        inputs.artificial_stress.clear(); // 72 bytes per particle that nothing reads
    }
    // Wall particles are skipped: the force pass reads these only for pairs of one body
    // (their entries keep whatever they held). Dynamic, as walls and grains alternate in
    // blocks.
#pragma omp parallel for schedule(dynamic, 256)
    for (Index i = 0; i < n; ++i) {
        if (p.wall_id[i] >= 0) {
            continue;
        }
        const double inv_rho2 = 1.0 / (p.density[i] * p.density[i]);
        const Mat3 sigma = stress_tensor(p.stress[i]);
        // With the correction the momentum equation needs sigma_i/rho_i^2 C_i: formed once here
        // rather than per pair. Without it the entries are those of sigma * inv_rho2, each
        // product formed as the full tensor's was.
        if (corrected) {
            inputs.stress_over_rho2[i] = sigma * inv_rho2 * inputs.gradient_correction[i];
        } else {
            write_pair_record(p, i, sigma, inv_rho2, inputs.sound_speed, inputs.pair_records[i]);
        }
        if (!artificial_on) {
            continue;
        }
        // Gray, Monaghan & Swift (2001) eq. (4.7): only tensile principal stresses.
        Eigen::SelfAdjointEigenSolver<Mat3> eigen;
        eigen.computeDirect(sigma);
        const Vec3 principal = eigen.eigenvalues();
        Vec3 scaled = Vec3::Zero();
        for (int a = 0; a < 3; ++a) {
            scaled[a] = principal[a] > 0.0 ? -artificial.epsilon * principal[a] * inv_rho2 : 0.0;
        }
        inputs.artificial_stress[i] =
            eigen.eigenvectors() * scaled.asDiagonal() * eigen.eigenvectors().transpose();
    }
}

} // namespace grainload::sph
