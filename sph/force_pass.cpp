#include "sph/contact_force.hpp"
#include "sph/pair_lanes.hpp"
#include "sph/pair_parts.hpp"
#include "sph/rates.hpp"

#include <algorithm>
#include <cmath>

// The force pass of rates.hpp (compute_accelerations): each same-body pair once, from the row
// of its lower index (sph/pair_parts.hpp); contact pairs from both rows.

namespace grainload::sph {

namespace {

/// Settings of the force pass, read once per call.
struct ForceSettings {
    double support_squared;
    double h;
    double h2_softening; ///< 0.01 h^2 of Monaghan's mu
    double w_reference;
    bool stress_pairs;
    bool use_artificial_stress;
    double artificial_exponent;
    bool use_viscosity;
    bool use_contact;
    bool current_pairs_act; ///< whether same-body pairs of the current list exchange anything
    double alpha;
    double beta;
    double viscosity_speed;
    Vec3 gravity;

    ForceSettings(const SmoothingKernel& kernel, const SphOptions& options)
        : support_squared(kernel.support_radius() * kernel.support_radius()),
          h(kernel.smoothing_length()), h2_softening(0.01 * h * h),
          w_reference(kernel.value(options.particle_spacing)),
          stress_pairs(options.formulation == Formulation::updated_lagrangian),
          use_artificial_stress(stress_pairs && options.artificial_stress.epsilon > 0.0),
          artificial_exponent(options.artificial_stress.exponent),
          use_viscosity(options.viscosity.alpha > 0.0 || options.viscosity.beta > 0.0),
          use_contact(options.contact.stiffness > 0.0),
          current_pairs_act(stress_pairs || use_viscosity), alpha(options.viscosity.alpha),
          beta(options.viscosity.beta), viscosity_speed(options.viscosity.sound_speed),
          gravity(options.gravity) {}
};

/// Where a part of the force pass adds: 3 doubles of acceleration and 1 of heating rate of
/// particle k at 3 (k - origin) and k - origin; and, when not null, the contact dashpot's part
/// of each row's heating rate (row i writes entry i only, so every part shares one array,
/// indexed by particle).
struct ForceSums {
    double* acceleration;
    double* heating;
    double* contact_heating;
    Index origin;
};

/// Row i of the force pass in D = 2 or 3 components (plane strain: the z terms are exact zeros
/// and are left out).
template <class Shape, int D> struct ForceRow {
    const ParticleSet& p;
    const particles::NeighbourList& neighbours;
    const SmoothingKernel& kernel;
    const ShapeTerms<Shape> w;
    const ForceSettings& s;
    const ContactPotential& contact;
    const ForceInputs& in;
    const std::vector<int>& key;
    /// in.entry_factor's data, or nullptr: the kernel is evaluated here.
    const double* entry_factor;
    /// in.pair_records' data, or nullptr: the full tensors (corrected).
    const PairRecord* records;

    /// Stress, artificial stress and viscosity of a same-body pair i < j: adds m_j T g to i's
    /// acceleration and -m_i T g to j's (grad_j W_ji = -g, T symmetric in i and j), and the
    /// viscous heating 1/2 m Pi v_ij . g to both (Monaghan 1992). in_support false: computed
    /// as if, added nowhere (a branch-free skip).
    void continuum_pair(Index i, Index j, const double (&d)[D], double r, double r2,
                        const double (&g)[D], bool in_support, double (&a)[3], double& heating,
                        const ForceSums& sums) const {
        double t[D][D] = {};
        if (s.stress_pairs && records != nullptr) {
            // The six stored entries xx, yy, zz, xy, xz, yz (rates.hpp): the same sums as the
            // full tensors', each formed once.
            const double* si = records[i].stress;
            const double* sj = records[j].stress;
            constexpr int kEntry[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
            for (int row = 0; row < D; ++row) {
                t[row][row] = si[row] + sj[row];
                for (int c = row + 1; c < D; ++c) {
                    t[row][c] = si[kEntry[row][c]] + sj[kEntry[row][c]];
                    t[c][row] = t[row][c];
                }
            }
        } else if (s.stress_pairs) {
            const Mat3& si = in.stress_over_rho2[i];
            const Mat3& sj = in.stress_over_rho2[j];
            for (int row = 0; row < D; ++row) {
                for (int c = 0; c < D; ++c) {
                    t[row][c] = si(row, c) + sj(row, c);
                }
            }
        }
        if (s.use_artificial_stress) {
            const double fn = std::pow(w.value(r) / s.w_reference, s.artificial_exponent);
            const Mat3& ri = in.artificial_stress[i];
            const Mat3& rj = in.artificial_stress[j];
            for (int row = 0; row < D; ++row) {
                for (int c = 0; c < D; ++c) {
                    t[row][c] += fn * (ri(row, c) + rj(row, c));
                }
            }
        }
        const Vec3& vi = p.velocity[i];
        const Vec3& vj = p.velocity[j];
        double v_ij[D];
        double approach = 0.0;
        for (int c = 0; c < D; ++c) {
            v_ij[c] = vi[c] - vj[c];
            approach += v_ij[c] * d[c];
        }
        const double mi = p.mass[i];
        const double mj = p.mass[j];
        // Branch free: whether the pair approaches is a coin toss per pair, and a mispredicted
        // branch here costs more than the arithmetic it would skip.
        if (s.use_viscosity) {
            const double mu = s.h * approach / (r2 + s.h2_softening);
            const double c = s.viscosity_speed > 0.0
                                 ? s.viscosity_speed
                                 : 0.5 * (in.sound_speed[i] + in.sound_speed[j]);
            const double rho = 0.5 * (p.density[i] + p.density[j]);
            const double pi_all = (-s.alpha * c * mu + s.beta * mu * mu) / rho;
            double power = 0.0;
            for (int k = 0; k < D; ++k) {
                power += v_ij[k] * g[k];
            }
            const bool viscous = approach < 0.0;
            const double pi_ij = viscous ? pi_all : 0.0;
            const double heat = viscous && in_support ? 0.5 * pi_all * power : 0.0;
            heating += mj * heat;
            sums.heating[j - sums.origin] += mi * heat;
            for (int k = 0; k < D; ++k) {
                t[k][k] -= pi_ij;
            }
        }
        double* aj = sums.acceleration + 3 * (j - sums.origin);
        for (int row = 0; row < D; ++row) {
            double tg = 0.0;
            for (int c = 0; c < D; ++c) {
                tg += t[row][c] * g[c];
            }
            tg = in_support ? tg : 0.0;
            a[row] += mj * tg;
            aj[row] -= mi * tg;
        }
    }

    /// Contact potential (and the dashpot between bodies) of a pair of different bodies.
    void contact_pair(Index i, Index j, const Vec3& x_ij, double r, bool wall, double volume_i,
                      double (&a)[3], double& heating, double& contact_heating) const {
        const double volumes = volume_i * p.mass[j] / p.density[j];
        Vec3 add;
        if (wall || p.wall_id[j] >= 0) {
            // Undamped here: WallContact damps along the wall normal.
            const double repulsion = contact_repulsion(kernel, contact, s.w_reference, volumes, r);
            add = (repulsion / (r * p.mass[i])) * x_ij;
        } else {
            const ContactPair pair{x_ij, r, p.velocity[i] - p.velocity[j], volumes,
                                   p.mass[i] * p.mass[j] / (p.mass[i] + p.mass[j])};
            double dissipation = 0.0;
            add = contact_pair_force(kernel, contact, s.w_reference, pair, dissipation) / p.mass[i];
            heating += 0.5 * dissipation / p.mass[i];
            contact_heating += 0.5 * dissipation / p.mass[i];
        }
        for (int c = 0; c < 3; ++c) {
            a[c] += add[c];
        }
    }

    /// A neighbour entry of another body (or a wall particle) at squared distance r2.
    void contact_entry(Index i, Index j, double r2, bool wall, double volume_i, double (&a)[3],
                       double& heating, double& contact_heating) const {
        if (r2 < s.support_squared && r2 != 0.0 && s.use_contact && p.body_id[i] != p.body_id[j]) {
            contact_pair(i, j, p.position[i] - p.position[j], std::sqrt(r2), wall, volume_i, a,
                         heating, contact_heating);
        }
    }

    /// Row i with the terms of its same-body pairs from continuum_lanes (pair_lanes.hpp), a
    /// batch of entries at a time, added in the list's order as operator() adds them; a row of
    /// such pairs only (NeighbourList::same_key_row) goes to the lanes without picking.
    void lane_row(Index i, const ForceSums& sums, const LaneSettings& lanes) const {
        const bool wall = p.wall_id[i] >= 0;
        double a[3] = {0.0, 0.0, 0.0};
        double heating = 0.0;
        double contact_heating = 0.0;
        const double volume_i = p.mass[i] / p.density[i];
        const int key_i = key[i];
        const auto list = neighbours.neighbours(i);
        std::int32_t picked[kLaneBatch];
        LaneTerms terms;
        const bool whole = neighbours.same_key_row(i); // every entry a pair to take
        for (std::size_t first = 0; first < list.size(); first += kLaneBatch) {
            const std::size_t end = std::min(list.size(), first + kLaneBatch);
            const auto [count, others] =
                whole ? PickedPairs{static_cast<int>(end - first), 0}
                      : pick_same_body_pairs(list, first, end, key, i, picked);
            if (others == 0) { // no contact term comes between: the lanes add the terms
                double own[4] = {a[0], a[1], a[2], heating};
                if (count > 0) {
                    continuum_lanes_added(D, records, i, whole ? list.data() + first : picked,
                                          count, lanes, own, sums.acceleration, sums.heating,
                                          sums.origin);
                }
                std::copy_n(own, 3, a);
                heating = own[3];
                continue;
            }
            if (count > 0) {
                continuum_lanes(D, records, i, picked, count, lanes, terms);
            }
            int pair = 0;
            for (std::size_t k = first; k < end; ++k) {
                const Index j = list[k];
                if (key[j] != key_i) {
                    double d[D];
                    contact_entry(i, j, separation(p.position[i], p.position[j], d), wall, volume_i,
                                  a, heating, contact_heating);
                    continue;
                }
                if (j < i) {
                    continue;
                }
                heating += terms.term[6][pair];
                sums.heating[j - sums.origin] += terms.term[7][pair];
                double* aj = sums.acceleration + 3 * (j - sums.origin);
                for (int row = 0; row < D; ++row) {
                    a[row] += terms.term[row][pair];
                    aj[row] -= terms.term[3 + row][pair];
                }
                ++pair;
            }
        }
        double* ai = sums.acceleration + 3 * (i - sums.origin);
        for (int c = 0; c < 3; ++c) {
            ai[c] += a[c];
        }
        sums.heating[i - sums.origin] += heating;
        if (sums.contact_heating != nullptr) {
            sums.contact_heating[i] = contact_heating;
        }
    }

    /// Row i: its contact pairs, and its same-body pairs with the particles after it.
    void operator()(Index i, const ForceSums& sums) const {
        const bool wall = p.wall_id[i] >= 0;
        double a[3] = {0.0, 0.0, 0.0};
        double heating = 0.0;
        double contact_heating = 0.0;
        const Vec3& xi = p.position[i];
        const double volume_i = p.mass[i] / p.density[i];
        const int key_i = key[i];
        const auto list = neighbours.neighbours(i);
        const double* factor_of_entry =
            entry_factor != nullptr ? entry_factor + neighbours.first_entry(i) : nullptr;
        for (std::size_t k = 0; k < list.size(); ++k) {
            const Index j = list[k];
            double d[D];
            const double r2 = separation(xi, p.position[j], d);
            const bool same = key[j] == key_i;
            const bool in_support = r2 < s.support_squared && r2 != 0.0;
            if (!same) {
                contact_entry(i, j, r2, wall, volume_i, a, heating, contact_heating);
                continue;
            }
            if (!s.current_pairs_act || j < i) {
                continue;
            }
            // Total-Lagrangian stress forces come from TotalLagrangian over the reference
            // pairs; the viscosity still acts between current neighbours. Pairs outside the
            // support are evaluated at r = support (finite) and not added. The kinematic pass
            // left W'(r)/r of the pairs inside the support in entry_factor when it is given
            // (its value there for the others is stale but not added).
            const bool need_r = factor_of_entry == nullptr || s.use_artificial_stress;
            const double r = need_r ? std::sqrt(in_support ? r2 : s.support_squared) : 0.0;
            const double f = factor_of_entry != nullptr ? factor_of_entry[k] : w.gradient_factor(r);
            double g[D];
            for (int c = 0; c < D; ++c) {
                g[c] = f * d[c];
            }
            continuum_pair(i, j, d, r, r2, g, in_support, a, heating, sums);
        }
        double* ai = sums.acceleration + 3 * (i - sums.origin);
        for (int c = 0; c < 3; ++c) {
            ai[c] += a[c];
        }
        sums.heating[i - sums.origin] += heating;
        if (sums.contact_heating != nullptr) {
            sums.contact_heating[i] = contact_heating;
        }
    }
};

/// What the force pass's vector lanes read of the settings and the kernel's terms.
template <class Shape>
LaneSettings force_lane_settings(const ForceSettings& s, const ShapeTerms<Shape>& w) {
    return {s.support_squared, w.inverse_h, w.alpha_over_h, s.h,
            s.h2_softening,    s.alpha,     s.beta,         s.viscosity_speed};
}

/// The first part's sums before the pass (sph/pair_parts.hpp): the accelerations start from
/// gravity (zero for wall particles), the heating rates and the contact heating from zero; set
/// on all threads, in the loop that sets the particles' keys.
void start_force_sums(ParticleSet& p, const Vec3& gravity, std::vector<double>& heating_rate,
                      double* contact_heating, std::vector<int>& key) {
    const Index n = p.size();
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        key[i] = continuum_key(p.wall_id[i] >= 0, p.body_id[i], i);
        p.acceleration[i] = p.wall_id[i] >= 0 ? Vec3::Zero() : gravity;
        heating_rate[i] = 0.0;
        if (contact_heating != nullptr) {
            contact_heating[i] = 0.0;
        }
    }
}

/// A later part's window in `sums`: the accelerations of its particles, then their heating rates.
ForceSums later_part_sums(const PairParts& parts, PairScratch& sums, double* contact_heating,
                          int r) {
    double* base = sums.part(r);
    return ForceSums{base, base + 3 * parts.window(r), contact_heating, parts.origin(r)};
}

/// The later parts' sums added to the first part's, in the parts' order.
void add_later_force_sums(ParticleSet& p, std::vector<double>& heating_rate, const PairParts& parts,
                          PairScratch& sums) {
    if (parts.count() == 1) {
        return;
    }
    const Index n = p.size();
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        for_later_parts(parts, i, [&](int r, Index k) {
            const ForceSums part = later_part_sums(parts, sums, nullptr, r);
            for (int c = 0; c < 3; ++c) {
                p.acceleration[i][c] += part.acceleration[3 * k + c];
            }
            heating_rate[i] += part.heating[k];
        });
    }
}

} // namespace

bool force_pass_uses_lanes(const SmoothingKernel& kernel, const SphOptions& options,
                           PairArithmetic arithmetic) {
    const ForceSettings s(kernel, options);
    return arithmetic == PairArithmetic::lanes_where_available &&
           kernel.type() == KernelType::cubic_spline && s.stress_pairs && s.use_viscosity &&
           !s.use_artificial_stress && !options.kernel_gradient_correction &&
           pair_lanes_available();
}

void compute_accelerations(ParticleSet& p, const particles::NeighbourList& neighbours,
                           const SmoothingKernel& kernel, const SphOptions& options,
                           const ForceInputs& in, std::vector<double>& heating_rate,
                           PairScratch* scratch, PairArithmetic arithmetic,
                           std::vector<double>* contact_heating_rate) {
    const Index n = p.size();
    heating_rate.resize(static_cast<std::size_t>(n));
    double* contact_heating = nullptr;
    if (contact_heating_rate != nullptr) {
        contact_heating_rate->resize(static_cast<std::size_t>(n));
        contact_heating = contact_heating_rate->data();
    }
    if (n == 0) {
        return;
    }
    const ForceSettings settings(kernel, options);
    const bool use_lanes = force_pass_uses_lanes(kernel, options, arithmetic);
    std::vector<int> key(static_cast<std::size_t>(n));
    start_force_sums(p, settings.gravity, heating_rate, contact_heating, key);
    const PairParts parts = split_rows(neighbours, n, n, pass_parts());
    constexpr int width = 4;
    PairScratch own;
    PairScratch& sums = scratch != nullptr ? *scratch : own;
    sums.reserve(parts, width);
    auto sums_of = [&](int r) {
        return r == 0 ? ForceSums{p.acceleration.data()->data(), heating_rate.data(),
                                  contact_heating, 0}
                      : later_part_sums(parts, sums, contact_heating, r);
    };
    kernel.visit_shape([&](auto shape) {
        using Shape = decltype(shape);
        auto pass = [&](auto dimension) {
            const ForceRow<Shape, decltype(dimension)::value> row{
                p,
                neighbours,
                kernel,
                ShapeTerms<Shape>(kernel),
                settings,
                options.contact,
                in,
                key,
                in.entry_factor.empty() ? nullptr : in.entry_factor.data(),
                in.pair_records.empty() ? nullptr : in.pair_records.data()};
            if (use_lanes && row.records != nullptr) {
                const LaneSettings lanes = force_lane_settings(settings, row.w);
                for_each_part(parts, sums, width,
                              [&](Index i, int r) { row.lane_row(i, sums_of(r), lanes); });
                return;
            }
            for_each_part(parts, sums, width, [&](Index i, int r) { row(i, sums_of(r)); });
        };
        if (kernel.dimension() == 2) {
            pass(std::integral_constant<int, 2>{});
        } else {
            pass(std::integral_constant<int, 3>{});
        }
    });
    add_later_force_sums(p, heating_rate, parts, sums);
}

} // namespace grainload::sph
