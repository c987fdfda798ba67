#pragma once
// The stiffness of a linear shell, assembled once, whose internal force is exactly K u.

#include "fem/sparse_solver.hpp"
#include "io/types.hpp"

#include <Eigen/SparseCore>
#include <vector>

namespace grainload::fem {

/// The stiffness of a linear shell (linear kinematics, linear elastic parts) over all DOFs,
/// prescribed ones included, assembled once. Its internal force is exactly K u: with strains
/// linear in u (eps = B u) and stresses linear in the strains (sigma = C eps), the element
/// loop's sum of B^T sigma dV (thesis eq. 5.2.10) is the sum of B^T C B dV times u, the
/// stiffness of Bathe FEP section 4.2.1; only the summation order differs. The drilling spring
/// (fem/mitc4_shell.hpp) is kept apart: it belongs to the tangent, not to the internal force.
class StoredStiffness {
  public:
    using Triplets = std::vector<Eigen::Triplet<double>>;

    /// From the element matrices' entries at global DOFs (duplicates are summed).
    StoredStiffness(Index dofs, const Triplets& material, const Triplets& drilling);

    /// The internal force K u over all DOFs (the reactions at constrained ones).
    Eigen::VectorXd internal_force(const Eigen::VectorXd& u) const;
    /// The tangent (stiffness plus drilling spring) times v over all DOFs: the right-hand side
    /// K_fp dU_p of a prescribed increment (fem/static_increment.hpp).
    Eigen::VectorXd tangent_times(const Eigen::VectorXd& v) const;
    /// The tangent's block of the free DOFs (`equation_numbers`: row per DOF or -1).
    SparseSolver::Matrix free_tangent(const std::vector<Index>& equation_numbers,
                                      Index free_count) const;

  private:
    /// Row-major: each entry of a product is one row's sum, the same on any thread count.
    using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
    RowMatrix material_;
    RowMatrix drilling_;
};

} // namespace grainload::fem
