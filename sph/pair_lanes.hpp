#pragma once
// The SPH pair passes' same-body terms in AVX2 lanes, bit for bit the scalar rows.

#include "io/types.hpp"

#include <cstdint>

// The same-body pair terms of the kinematic and force passes (rates.hpp) in the vector units
// (AVX2, checked at run time). Each lane does the scalar row's operations in the scalar row's
// order (no fused multiply-add, IEEE division and square root) and the sums are added in the
// list's order, so the lanes give the same bits as the scalar rows.

namespace grainload::sph {

/// What the pair passes read of one particle, packed so that four neighbours load as 4x4
/// blocks of doubles, transposed into lanes: sigma/rho^2 (xx yy zz xy xz yz) and the density in
/// the first cache line (all the plane-strain scalar row reads of it), then position, velocity,
/// the viscosity's sound speed c and the mass: the second line is all the kinematic pass reads.
struct alignas(64) PairRecord {
    double stress[6];
    double density;
    double unused;
    double position[3];
    double velocity[3];
    double sound_speed;
    double mass;
};
static_assert(sizeof(PairRecord) == 128, "four 32-byte blocks");

/// Settings of the cubic-spline pair terms (rates.hpp compute_accelerations and, its first three,
/// compute_velocity_gradient).
struct LaneSettings {
    double support_squared;
    double inverse_h;
    double alpha_over_h; ///< the kernel's normalisation over h^(d+1)
    double h;
    double h2_softening; ///< 0.01 h^2 of Monaghan's mu
    double alpha;
    double beta;
    double viscosity_speed; ///< > 0: fixed c; 0: the mean of the pair's records
};

/// Pairs per call: a row is taken in batches of this many list entries.
constexpr int kLaneBatch = 64;

/// Per picked pair p of a batch: m_j T g (0-2), m_i T g (3-5), m_j and m_i times the viscous
/// heating 1/2 Pi v_ij . g (6, 7); zeros where the pair is outside the support. The rows are
/// padded to whole groups of four.
struct LaneTerms {
    alignas(32) double term[8][kLaneBatch];
};

/// As continuum_lanes, with the terms added in the pairs' order: m_j T g and m_j times the
/// heating to own (x, y, z, heating of i); m_i T g taken from acceleration + 3 (j[p] - origin),
/// m_i times the heating added to heating[j[p] - origin]. For a batch without entries of other
/// bodies, whose contact terms would come between.
void continuum_lanes_added(int dimension, const PairRecord* records, Index i, const std::int32_t* j,
                           int count, const LaneSettings& settings, double (&own)[4],
                           double* acceleration, double* heating, Index origin);

/// Whether this processor runs the lanes (AVX2, checked once).
bool pair_lanes_available();

/// The kinematic pass's pairs (i, j[p]), p < count <= kLaneBatch, of one body in 3D, cubic
/// spline, from the records' positions, velocities and masses: for the pairs inside the support,
/// with g = W'(r)/r x_ij (ShapeTerms::gradient_factor_inside) and dv = v_j - v_i, adds m_j dv
/// g^T to `acc` and m_i dv g^T to particle j's nine doubles at l + 9 (j - origin), both column
/// major, pair
/// by pair in order (a pair outside the support adds +0 or -0, which leaves every sum's bits as
/// skipping it would: a sum that starts at +0 never becomes -0). Only support_squared, inverse_h
/// and alpha_over_h of `settings` are read. Requires pair_lanes_available().
void gradient_lanes(const PairRecord* records, Index i, const std::int32_t* j, int count,
                    const LaneSettings& settings, double* l, Index origin, double (&acc)[9]);

/// The terms of the pairs (i, j[p]), p < count <= kLaneBatch, of one body: stress
/// sigma_i/rho_i^2 + sigma_j/rho_j^2 and Monaghan's viscosity, cubic spline, in `dimension` 3
/// or 2 (plane strain: the z terms left out, as the scalar row leaves them). Requires
/// pair_lanes_available().
void continuum_lanes(int dimension, const PairRecord* records, Index i, const std::int32_t* j,
                     int count, const LaneSettings& settings, LaneTerms& out);

} // namespace grainload::sph
