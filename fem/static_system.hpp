#pragma once
// What a static load increment needs of the structure it solves: its equations, loads and state.

#include "fem/sparse_solver.hpp"
#include "io/types.hpp"

#include <Eigen/Core>
#include <vector>

namespace grainload::fem {

/// A structure under a load factor lambda as a static increment (fem/static_increment.hpp)
/// solves it: the free DOFs' equation numbers, the applied and prescribed values at a load
/// factor, the tangent and internal forces at the current state, and the state's update.
/// ShellAnalysis is one; the increment sees it through this view alone.
class StaticSystem {
  public:
    virtual ~StaticSystem() = default;

    /// Per DOF its equation (-1 where fixed or prescribed).
    virtual const std::vector<Index>& equation_numbers() = 0;
    virtual Index free_dof_count() const = 0;
    /// Values of all constrained DOFs at load factor `lambda` (zero at free DOFs).
    virtual Eigen::VectorXd prescribed_at(double lambda) const = 0;
    /// Everything applied at load factor `lambda` (6 per node).
    virtual Eigen::VectorXd applied_forces(double lambda) const = 0;
    /// Load factor at which assemble() evaluates the state-dependent (follower) loads.
    virtual void set_assembly_load_factor(double lambda) = 0;
    /// The tangent (free DOFs) and the full internal force vector at the current state; with
    /// `prescribed` also coupling = K * prescribed over all DOFs.
    virtual void assemble(SparseSolver::Matrix* tangent, Eigen::VectorXd& internal,
                          const Eigen::VectorXd* prescribed, Eigen::VectorXd* coupling) = 0;
    virtual bool tangent_symmetric() const = 0;
    /// True when the tangent never changes (a factorisation can be reused).
    virtual bool constant_tangent() const = 0;
    /// True when assemble() works from a stored stiffness (K_fp dU_p without the tangent).
    virtual bool uses_stored_stiffness() const = 0;
    /// Add a full-size DOF increment to the state.
    virtual void update_state(const Eigen::VectorXd& increment) = 0;
    /// All DOF values.
    virtual const Eigen::VectorXd& dofs() const = 0;
};

} // namespace grainload::fem
