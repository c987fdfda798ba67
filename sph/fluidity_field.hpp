#pragma once
// The non-local fluidity field on the particles: a screened Poisson equation solved over the
// neighbour list each step.

#include "particles/neighbour_list.hpp"
#include "sph/kernels.hpp"

#include <Eigen/SparseCore>
#include <span>
#include <vector>

namespace grainload::sph {

/// The field's solve per step: conjugate gradients to a relative residual of
/// kFluidityTolerance, from the last step's field. The iterations are capped so that a field
/// that does not converge cannot stall a run; summary.json reports the iterations and the
/// residual left (FluidityUpdate), and a capped solve's residual says by how much it missed.
inline constexpr int kFluidityMaximumIterations = 1000;
inline constexpr double kFluidityTolerance = 1e-6;

/// What one solve did.
struct FluiditySolve {
    int iterations = 0;
    double residual = 0.0; ///< |b - A g| / |b| of the symmetric system below, at the end
};

/// The field equation of the non-local fluidity (materials/nonlocal_fluidity.hpp) over the
/// particles that carry it, c_i (g_i - g_loc_i) = laplacian(g)_i with c = 1/xi^2, the
/// Laplacian in the form of Brookshaw (1985) and Cleary & Monaghan (1999):
///
///     laplacian(g)_i = sum_j a_ij (g_j - g_i),   a_ij = -2 V_j W'(r_ij) r_ij / (r_ij^2 + eta^2),
///
/// V_j = m_j / rho_j, eta = 0.1 h. The form is second order on a regular lattice and needs no
/// second derivative of the kernel. Particles that carry no fluidity (wall particles, other
/// materials, other bodies, points without pressure) are left out of the sums, which is a
/// zero-flux condition at walls and free surfaces. Each row times V_i is a symmetric system
/// (V_i a_ij = V_j a_ji), diagonally dominant with non-negative c, positive definite wherever a
/// particle of a connected region has c > 0:
///
///     (V_i c_i + sum_j V_i a_ij) g_i - sum_j V_i a_ij g_j = V_i c_i g_loc_i,
///
/// solved by Eigen's conjugate gradients with a diagonal preconditioner. Where the cooperativity
/// length spans many particles (mu near mu_s, where c vanishes) the field is set by the whole
/// region at once: a relaxation that sweeps a few neighbours per step (Jacobi) would leave it
/// far from the solution and the flow dependent on the number of sweeps.
class FluidityField {
  public:
    /// The pairs of the field from a neighbour list over `rows` particles and the images after
    /// them (`image_source[k]` is the particle of list position rows + k): a pair joins i and
    /// j when both carry the field (`carries`) and share a body. A pair the list keeps in one
    /// row (halved) goes into both rows here; an image's pair stays in its row only, as the
    /// image's source has the mirrored pair in its own row.
    void connect(const particles::NeighbourList& list, Index rows,
                 std::span<const Index> image_source, std::span<const char> carries,
                 std::span<const int> body);
    /// Whether connect() saw this list generation last.
    bool connected_to(Index generation) const { return generation_ == generation; }

    /// The coefficients a_ij at the list positions `positions` (particles then images) with the
    /// particles' volumes; `active[i]` false leaves particle i out of every sum this step.
    void weigh(std::span<const Vec3> positions, std::span<const double> volume,
               std::span<const char> active, const SmoothingKernel& kernel);
    /// Solve for g (in: the start; out: the field) from the sources g_loc and screenings c of
    /// the particles; inactive particles get g = 0.
    FluiditySolve solve(std::span<const double> local, std::span<const double> screening,
                        std::span<double> g, int maximum_iterations = kFluidityMaximumIterations,
                        double tolerance = kFluidityTolerance);
    /// The discrete Laplacian of a field at particle i, sum_j a_ij (g_j - g_i).
    double laplacian(std::span<const double> g, Index i) const;

    std::size_t bytes() const;

  private:
    using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor, Index>;
    /// The symmetric system's pattern: each row's partners once (a particle may meet another
    /// and its image), its diagonal among them.
    void build_pattern();

    Index generation_ = -1;
    std::vector<Index> offset_;   ///< rows over the particles
    std::vector<Index> partner_;  ///< the particle whose value an entry gathers
    std::vector<Index> place_;    ///< the list position (particle or image) of the entry
    std::vector<double> weight_;  ///< a_ij of the entry; 0 where either end is inactive
    std::vector<Index> slot_;     ///< the entry's place in the matrix's values; -1: itself
    std::vector<Index> diagonal_; ///< each row's diagonal in the matrix's values
    std::vector<char> active_;
    std::vector<double> volume_;
    Matrix matrix_;
};

} // namespace grainload::sph
