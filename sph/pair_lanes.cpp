#include "sph/pair_lanes.hpp"

#include <cmath>
#include <cstdlib>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

// Every operation below mirrors one of ForceRow::continuum_pair (force_pass.cpp) and
// ShapeTerms::gradient_factor with the cubic spline (kernels.hpp), in the same order; the
// function is compiled for AVX2 without FMA, so no product is fused into a sum and the lanes
// round as the scalar row does.

namespace grainload::sph {

#if defined(__x86_64__)

bool pair_lanes_available() {
    static const bool available = __builtin_cpu_supports("avx2") != 0;
    return available;
}

namespace {

/// Two doubles at `low` in the lower half, two at `high` in the upper.
__attribute__((target("avx2"))) inline __m256d pair(const double* low, const double* high) {
    return _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(low)), _mm_loadu_pd(high), 1);
}

/// Block k (four doubles) of the records of particles j[0..3], as lanes: r[c] holds entry c of
/// the four blocks. Built from 128-bit halves (two records per register, then one unpack per
/// entry) rather than a 4x4 transpose of whole blocks, which would put twice the shuffles on
/// the one port that runs lane-crossing ones.
__attribute__((target("avx2"))) inline void load_block(const double* base, const std::int32_t* j,
                                                       int k, __m256d (&r)[4]) {
    constexpr int kDoubles = sizeof(PairRecord) / sizeof(double);
    const double* a = base + kDoubles * j[0] + 4 * k;
    const double* b = base + kDoubles * j[1] + 4 * k;
    const double* c = base + kDoubles * j[2] + 4 * k;
    const double* d = base + kDoubles * j[3] + 4 * k;
    const __m256d ac_low = pair(a, c);          // a0 a1 c0 c1
    const __m256d bd_low = pair(b, d);          // b0 b1 d0 d1
    const __m256d ac_high = pair(a + 2, c + 2); // a2 a3 c2 c3
    const __m256d bd_high = pair(b + 2, d + 2);
    r[0] = _mm256_unpacklo_pd(ac_low, bd_low); // a0 b0 c0 d0
    r[1] = _mm256_unpackhi_pd(ac_low, bd_low);
    r[2] = _mm256_unpacklo_pd(ac_high, bd_high);
    r[3] = _mm256_unpackhi_pd(ac_high, bd_high);
}

/// Rows a, b, c, d of four doubles in, columns out: r[k] = (a[k], b[k], c[k], d[k]).
__attribute__((target("avx2"))) inline void transpose(__m256d a, __m256d b, __m256d c, __m256d d,
                                                      __m256d (&r)[4]) {
    const __m256d ab_low = _mm256_unpacklo_pd(a, b);  // a0 b0 a2 b2
    const __m256d ab_high = _mm256_unpackhi_pd(a, b); // a1 b1 a3 b3
    const __m256d cd_low = _mm256_unpacklo_pd(c, d);
    const __m256d cd_high = _mm256_unpackhi_pd(c, d);
    r[0] = _mm256_permute2f128_pd(ab_low, cd_low, 0x20);
    r[1] = _mm256_permute2f128_pd(ab_high, cd_high, 0x20);
    r[2] = _mm256_permute2f128_pd(ab_low, cd_low, 0x31);
    r[3] = _mm256_permute2f128_pd(ab_high, cd_high, 0x31);
}

__attribute__((target("avx2"))) inline __m256d select(__m256d mask, __m256d yes, __m256d no) {
    return _mm256_blendv_pd(no, yes, mask);
}

/// CubicSplineKernel::shape_derivative_inside in lanes: both pieces evaluated, one selected.
__attribute__((target("avx2"))) inline __m256d shape_derivative_inside(__m256d q) {
    const __m256d t = _mm256_sub_pd(_mm256_set1_pd(2.0), q);
    const __m256d inner = _mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(-2.0), q),
                                        _mm256_mul_pd(_mm256_mul_pd(_mm256_set1_pd(1.5), q), q));
    const __m256d outer = _mm256_mul_pd(_mm256_mul_pd(_mm256_set1_pd(-0.5), t), t);
    return select(_mm256_cmp_pd(q, _mm256_set1_pd(1.0), _CMP_LT_OQ), inner, outer);
}

/// ((0 + a0 b0) + a1 b1) [+ a2 b2], as the scalar row's accumulating loops over D components.
template <int D>
__attribute__((target("avx2"))) inline __m256d dot(const __m256d (&a)[D], const __m256d (&b)[D]) {
    __m256d sum = _mm256_setzero_pd();
    for (int c = 0; c < D; ++c) {
        sum = _mm256_add_pd(sum, _mm256_mul_pd(a[c], b[c]));
    }
    return sum;
}

/// A group's terms, lane p for pair p: m_j T g and m_j times the heating (own), m_i T g and
/// m_i times the heating (other), as x, y, z, heating (plane strain: z exactly 0).
struct GroupTerms {
    __m256d own[4];
    __m256d other[4];
};

/// The terms of the pairs (i, lane_j[0..3]) in D = 2 or 3 components (plane strain leaves out
/// the z terms, as the scalar row does): every operation one of ForceRow::continuum_pair's.
template <int D>
__attribute__((target("avx2"))) inline void group_terms(const double* base, const PairRecord& ri,
                                                        const std::int32_t* lane_j,
                                                        const LaneSettings& s, GroupTerms& out) {
    const __m256d zero = _mm256_setzero_pd();
    const __m256d support_squared = _mm256_set1_pd(s.support_squared);
    const __m256d mi = _mm256_set1_pd(ri.mass);
    const bool fixed_speed = s.viscosity_speed > 0.0;
    __m256d stress[4], stress_mass[4], place[4], motion[4];
    load_block(base, lane_j, 0, stress);      // xx yy zz xy
    load_block(base, lane_j, 1, stress_mass); // xz yz rho -
    load_block(base, lane_j, 2, place);       // x y z vx
    load_block(base, lane_j, 3, motion);      // vy vz c m
    const __m256d velocity[3] = {place[3], motion[0], motion[1]};
    __m256d d[D], v[D], g[D];
    for (int c = 0; c < D; ++c) {
        d[c] = _mm256_sub_pd(_mm256_set1_pd(ri.position[c]), place[c]);
        v[c] = _mm256_sub_pd(_mm256_set1_pd(ri.velocity[c]), velocity[c]);
    }
    const __m256d r2 = dot<D>(d, d);
    const __m256d inside = _mm256_and_pd(_mm256_cmp_pd(r2, support_squared, _CMP_LT_OQ),
                                         _mm256_cmp_pd(r2, zero, _CMP_NEQ_UQ));
    // W'(r)/r, evaluated at the support for the pairs outside it (then not added).
    const __m256d r = _mm256_sqrt_pd(select(inside, r2, support_squared));
    // shape_derivative(q): 0 from q = 2 on.
    const __m256d q = _mm256_mul_pd(r, _mm256_set1_pd(s.inverse_h));
    const __m256d shape =
        select(_mm256_cmp_pd(q, _mm256_set1_pd(2.0), _CMP_LT_OQ), shape_derivative_inside(q), zero);
    const __m256d f = _mm256_div_pd(_mm256_mul_pd(_mm256_set1_pd(s.alpha_over_h), shape), r);
    for (int c = 0; c < D; ++c) {
        g[c] = _mm256_mul_pd(f, d[c]);
    }
    // sigma_i/rho_i^2 + sigma_j/rho_j^2: entries xx yy zz xy xz yz of the records.
    const __m256d entry_j[6] = {stress[0], stress[1],      stress[2],
                                stress[3], stress_mass[0], stress_mass[1]};
    constexpr int kEntry[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
    __m256d entry[6];
    for (int e = 0; e < 6; ++e) {
        entry[e] = _mm256_add_pd(_mm256_set1_pd(ri.stress[e]), entry_j[e]);
    }
    const __m256d approach = dot<D>(v, d);
    const __m256d mj = motion[3];
    // Monaghan's viscosity, as continuum_pair.
    const __m256d mu = _mm256_div_pd(_mm256_mul_pd(_mm256_set1_pd(s.h), approach),
                                     _mm256_add_pd(r2, _mm256_set1_pd(s.h2_softening)));
    const __m256d half = _mm256_set1_pd(0.5);
    const __m256d c =
        fixed_speed ? _mm256_set1_pd(s.viscosity_speed)
                    : _mm256_mul_pd(half, _mm256_add_pd(_mm256_set1_pd(ri.sound_speed), motion[2]));
    const __m256d rho =
        _mm256_mul_pd(half, _mm256_add_pd(_mm256_set1_pd(ri.density), stress_mass[2]));
    const __m256d linear = _mm256_mul_pd(_mm256_mul_pd(_mm256_set1_pd(-s.alpha), c), mu);
    const __m256d quadratic = _mm256_mul_pd(_mm256_mul_pd(_mm256_set1_pd(s.beta), mu), mu);
    const __m256d pi_all = _mm256_div_pd(_mm256_add_pd(linear, quadratic), rho);
    const __m256d power = dot<D>(v, g);
    const __m256d viscous = _mm256_cmp_pd(approach, zero, _CMP_LT_OQ);
    const __m256d pi_ij = select(viscous, pi_all, zero);
    const __m256d heat = select(_mm256_and_pd(viscous, inside),
                                _mm256_mul_pd(_mm256_mul_pd(half, pi_all), power), zero);
    for (int k = 0; k < D; ++k) {
        entry[k] = _mm256_sub_pd(entry[k], pi_ij);
    }
    for (int row = 0; row < 3; ++row) {
        __m256d tg = zero; // plane strain: the z row is left out, an exact 0
        if (row < D) {
            __m256d t_row[D];
            for (int col = 0; col < D; ++col) {
                t_row[col] = entry[kEntry[row][col]];
            }
            tg = select(inside, dot<D>(t_row, g), zero);
        }
        out.own[row] = row < D ? _mm256_mul_pd(mj, tg) : zero;
        out.other[row] = row < D ? _mm256_mul_pd(mi, tg) : zero;
    }
    out.own[3] = _mm256_mul_pd(mj, heat);
    out.other[3] = _mm256_mul_pd(mi, heat);
}

/// j[0..count) and the last of them repeated to a whole number of groups of four (spare lanes
/// compute terms that are never read).
inline void pad_lanes(const std::int32_t* j, int count, std::int32_t (&lane_j)[kLaneBatch + 3]) {
    for (int p = 0; p < count; ++p) {
        lane_j[p] = j[p];
    }
    for (int p = count; p < ((count + 3) & ~3); ++p) {
        lane_j[p] = j[count - 1];
    }
}

template <int D>
__attribute__((target("avx2"))) void terms_stored(const PairRecord* records, Index i,
                                                  const std::int32_t* j, int count,
                                                  const LaneSettings& s, LaneTerms& out) {
    const auto* base = reinterpret_cast<const double*>(records);
    std::int32_t lane_j[kLaneBatch + 3];
    pad_lanes(j, count, lane_j);
    for (int g = 0; g < count; g += 4) {
        GroupTerms terms;
        group_terms<D>(base, records[i], lane_j + g, s, terms);
        for (int c = 0; c < 4; ++c) {
            _mm256_store_pd(out.term[c == 3 ? 6 : c] + g, terms.own[c]);
            _mm256_store_pd(out.term[c == 3 ? 7 : 3 + c] + g, terms.other[c]);
        }
    }
}

template <int D>
__attribute__((target("avx2"))) void
terms_added(const PairRecord* records, Index i, const std::int32_t* j, int count,
            const LaneSettings& s, double (&own)[4], double* acceleration, double* heating,
            Index origin) {
    const auto* base = reinterpret_cast<const double*>(records);
    std::int32_t lane_j[kLaneBatch + 3];
    pad_lanes(j, count, lane_j);
    __m256d sum = _mm256_loadu_pd(own); // x, y, z, heating: each its own scalar sum in order
    // First every group's terms (independent groups: their square roots and divisions overlap,
    // where a loop that also added them waited on each group's chain), then the sums.
    GroupTerms groups[kLaneBatch / 4];
    for (int g = 0; g < count; g += 4) {
        group_terms<D>(base, records[i], lane_j + g, s, groups[g / 4]);
    }
    for (int g = 0; g < count; g += 4) {
        const GroupTerms& terms = groups[g / 4];
        __m256d mine[4], theirs[4]; // per pair: x, y, z, heating
        transpose(terms.own[0], terms.own[1], terms.own[2], terms.own[3], mine);
        transpose(terms.other[0], terms.other[1], terms.other[2], terms.other[3], theirs);
        const int pairs = count - g < 4 ? count - g : 4;
        for (int p = 0; p < pairs; ++p) {
            sum = _mm256_add_pd(sum, mine[p]);
            const Index j_local = lane_j[g + p] - origin;
            double* aj = acceleration + 3 * j_local;
            _mm_storeu_pd(aj, _mm_sub_pd(_mm_loadu_pd(aj), _mm256_castpd256_pd128(theirs[p])));
            const __m128d z_heat = _mm256_extractf128_pd(theirs[p], 1);
            aj[2] -= _mm_cvtsd_f64(z_heat);
            heating[j_local] += _mm_cvtsd_f64(_mm_unpackhi_pd(z_heat, z_heat));
        }
    }
    _mm256_storeu_pd(own, sum);
}

} // namespace

void continuum_lanes(int dimension, const PairRecord* records, Index i, const std::int32_t* j,
                     int count, const LaneSettings& settings, LaneTerms& out) {
    if (dimension == 2) {
        terms_stored<2>(records, i, j, count, settings, out);
    } else {
        terms_stored<3>(records, i, j, count, settings, out);
    }
}

void continuum_lanes_added(int dimension, const PairRecord* records, Index i, const std::int32_t* j,
                           int count, const LaneSettings& settings, double (&own)[4],
                           double* acceleration, double* heating, Index origin) {
    if (dimension == 2) {
        terms_added<2>(records, i, j, count, settings, own, acceleration, heating, origin);
    } else {
        terms_added<3>(records, i, j, count, settings, own, acceleration, heating, origin);
    }
}

namespace {

/// Four of the nine entries (entries first..first+3, column major) of the pairs' m_j dv g^T
/// and m_i dv g^T, lane p for pair p, added pair by pair in order: to `acc` and to the four
/// doubles of particle j[p] at l + 9 (j[p] - origin) + first.
__attribute__((target("avx2"))) inline void
add_four_entries(const __m256d (&dv)[3], const __m256d (&grad)[3], __m256d mj, __m256d mi,
                 int first, const std::int32_t* j, int pairs, double* l, Index origin,
                 __m256d& acc) {
    __m256d own[4], other[4];
    for (int e = 0; e < 4; ++e) {
        const int entry = first + e; // t_rc = dv_r g_c at entry 3c + r
        const __m256d t = _mm256_mul_pd(dv[entry % 3], grad[entry / 3]);
        own[e] = _mm256_mul_pd(mj, t);
        other[e] = _mm256_mul_pd(mi, t);
    }
    __m256d mine[4], theirs[4];
    transpose(own[0], own[1], own[2], own[3], mine);
    transpose(other[0], other[1], other[2], other[3], theirs);
    for (int p = 0; p < pairs; ++p) {
        acc = _mm256_add_pd(acc, mine[p]);
        double* lj = l + 9 * (j[p] - origin) + first;
        _mm256_storeu_pd(lj, _mm256_add_pd(_mm256_loadu_pd(lj), theirs[p]));
    }
}

} // namespace

__attribute__((target("avx2"))) void gradient_lanes(const PairRecord* records, Index i,
                                                    const std::int32_t* j, int count,
                                                    const LaneSettings& s, double* l, Index origin,
                                                    double (&acc)[9]) {
    const auto* base = reinterpret_cast<const double*>(records);
    const PairRecord& ri = records[i];
    std::int32_t lane_j[kLaneBatch + 3];
    pad_lanes(j, count, lane_j);
    const __m256d zero = _mm256_setzero_pd();
    const __m256d mi = _mm256_set1_pd(ri.mass);
    const __m256d support_squared = _mm256_set1_pd(s.support_squared);
    __m256d acc_low = _mm256_loadu_pd(acc);
    __m256d acc_high = _mm256_loadu_pd(acc + 4);
    double acc_last = acc[8];
    // First every group's dv and g (independent groups: their square roots and divisions
    // overlap), then the sums pair by pair.
    struct Group {
        __m256d dv[3];
        __m256d grad[3];
        __m256d mj;
    };
    Group groups[kLaneBatch / 4];
    for (int g = 0; g < count; g += 4) {
        Group& group = groups[g / 4];
        __m256d place[4], motion[4];
        load_block(base, lane_j + g, 2, place);  // x y z vx
        load_block(base, lane_j + g, 3, motion); // vy vz c m
        const __m256d velocity[3] = {place[3], motion[0], motion[1]};
        __m256d d[3];
        for (int c = 0; c < 3; ++c) {
            d[c] = _mm256_sub_pd(_mm256_set1_pd(ri.position[c]), place[c]); // separation()
            group.dv[c] = _mm256_sub_pd(velocity[c], _mm256_set1_pd(ri.velocity[c]));
        }
        const __m256d r2 = dot<3>(d, d);
        const __m256d inside = _mm256_and_pd(_mm256_cmp_pd(r2, support_squared, _CMP_LT_OQ),
                                             _mm256_cmp_pd(r2, zero, _CMP_NEQ_UQ));
        // W'(r)/r as ShapeTerms::gradient_factor_inside, at the support for the pairs outside,
        // whose g is then +0 (their terms +0 or -0, which leave every sum's bits alone).
        const __m256d r = _mm256_sqrt_pd(select(inside, r2, support_squared));
        const __m256d shape =
            shape_derivative_inside(_mm256_mul_pd(r, _mm256_set1_pd(s.inverse_h)));
        const __m256d f = _mm256_div_pd(_mm256_mul_pd(_mm256_set1_pd(s.alpha_over_h), shape), r);
        for (int c = 0; c < 3; ++c) {
            group.grad[c] = select(inside, _mm256_mul_pd(f, d[c]), zero);
        }
        group.mj = motion[3];
    }
    for (int g = 0; g < count; g += 4) {
        const Group& group = groups[g / 4];
        const int pairs = count - g < 4 ? count - g : 4;
        add_four_entries(group.dv, group.grad, group.mj, mi, 0, lane_j + g, pairs, l, origin,
                         acc_low);
        add_four_entries(group.dv, group.grad, group.mj, mi, 4, lane_j + g, pairs, l, origin,
                         acc_high);
        const __m256d t = _mm256_mul_pd(group.dv[2], group.grad[2]);
        alignas(32) double mine[4];
        alignas(32) double theirs[4];
        _mm256_store_pd(mine, _mm256_mul_pd(group.mj, t));
        _mm256_store_pd(theirs, _mm256_mul_pd(mi, t));
        for (int p = 0; p < pairs; ++p) {
            acc_last += mine[p];
            l[9 * (lane_j[g + p] - origin) + 8] += theirs[p];
        }
    }
    _mm256_storeu_pd(acc, acc_low);
    _mm256_storeu_pd(acc + 4, acc_high);
    acc[8] = acc_last;
}

#else

bool pair_lanes_available() {
    return false;
}

void continuum_lanes(int, const PairRecord*, Index, const std::int32_t*, int, const LaneSettings&,
                     LaneTerms&) {
    std::abort(); // unreachable: pair_lanes_available() is false
}

void continuum_lanes_added(int, const PairRecord*, Index, const std::int32_t*, int,
                           const LaneSettings&, double (&)[4], double*, double*) {
    std::abort();
}

void gradient_lanes(const PairRecord*, Index, const std::int32_t*, int, const LaneSettings&,
                    double*, double (&)[9]) {
    std::abort();
}

#endif

} // namespace grainload::sph
