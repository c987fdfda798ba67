#pragma once
// Newton-Raphson equilibrium iterations on a NewtonOperator, with their tolerances and log.

#include "fem/sparse_solver.hpp"
#include "io/types.hpp"

#include <Eigen/Core>
#include <string>
#include <vector>

namespace grainload::fem {

/// Tolerances of the incremental-iterative procedure (thesis Table 5.2.2). A tolerance <= 0
/// switches its criterion off; an iteration has converged when every active one is met.
struct NewtonSettings {
    double displacement_tolerance = 0.0; ///< eps_U of thesis eq. 5.2.7
    double force_tolerance = 1e-6;       ///< eps_F of thesis eq. 5.2.8
    double energy_tolerance = 1e-10;     ///< eps_E of thesis eq. 5.2.9
    int max_iterations = 20;
    int max_cutbacks = 6; ///< halvings of a load increment that did not converge
};

/// One equilibrium iteration: the three norm ratios of thesis eqs. 5.2.7-5.2.9.
struct NewtonIteration {
    int iteration = 0;
    double displacement_ratio = 0.0; ///< ||dU(i)|| / ||U(i)||
    double force_ratio = 0.0;        ///< ||F - Fu(i)|| / ||F - Fu(t)||
    double energy_ratio = 0.0;       ///< dU(i).(F - Fu(i)) / dU(1).(F - Fu(t))
    double residual_norm = 0.0;      ///< ||F - Fu(i)|| [N, N m mixed]
};

struct StepReport {
    bool converged = false;
    double load_factor = 0.0;
    int increments = 0;
    int cutbacks = 0;
    std::string solver;               ///< which factorisation ran last
    int factorisations = 0;           ///< of the tangent, in this solve (0: a kept one solved)
    int back_substitutions = 0;       ///< solves with a factorisation, one per iteration
    std::vector<NewtonIteration> log; ///< iterations of every accepted increment, in order
    std::vector<int> iterations;      ///< iterations per accepted increment
    /// Where the last increment that did not converge was furthest out of balance: the global
    /// DOF (node * 6 + component, components ux uy uz rx ry rz) with the largest |residual| (a
    /// non-finite one first) of its last iteration, and that residual [N or N m]; -1: none.
    Index worst_dof = -1;
    double worst_residual = 0.0;
};

/// Sets report.worst_dof and worst_residual from the free-DOF `residual` of a failed increment
/// (`equation_numbers` maps global DOFs to its rows, -1 for constrained ones).
void record_worst_dof(const std::vector<Index>& equation_numbers, const Eigen::VectorXd& residual,
                      StepReport& report);

/// "node 12 uz" for a global DOF.
std::string dof_name(Index dof);

/// The free-DOF rows of the full-size vector `full` (`equation_numbers` as above).
Eigen::VectorXd free_part(const std::vector<Index>& equation_numbers, Index free_count,
                          const Eigen::VectorXd& full);
/// Writes the free-DOF vector `free` into its DOFs of the full-size `full`, the others kept.
void scatter_free(const std::vector<Index>& equation_numbers, const Eigen::VectorXd& free,
                  Eigen::VectorXd& full);

/// The problem side of a Newton solve (the operator of MFEM's operator/solver split): the
/// out-of-balance force over the free DOFs at the current state, its tangent, and the update
/// of the state. The static load increment (fem/static_increment.hpp) and the Newmark/HHT step
/// (fem/newmark_integrator.cpp) provide one each.
class NewtonOperator {
  public:
    virtual ~NewtonOperator() = default;
    /// Out-of-balance force over the free DOFs at the current state in iteration `iteration`
    /// (0: before any correction), with the tangent into `tangent` unless it is null.
    virtual Eigen::VectorXd residual(int iteration, SparseSolver::Matrix* tangent) = 0;
    /// True when `residual` (of the latest residual() call) is balanced without the ratios of
    /// eqs. 5.2.8-5.2.9, which would then compare round-off with round-off.
    virtual bool in_balance(const Eigen::VectorXd& residual) const = 0;
    /// Factorise the system matrix formed from the `tangent` that residual() assembled.
    virtual void factorize(SparseSolver::Matrix& tangent, SparseSolver& solver) const = 0;
    /// Apply the free-DOF correction `step` of iteration `iteration` to the state.
    virtual void correct(int iteration, const Eigen::VectorXd& step) = 0;
    /// Called instead of correct() when the first residual is already in balance.
    virtual void settle() {}
    /// ||U(i)|| of the displacement ratio of eq. 5.2.7.
    virtual double displacement_norm() const = 0;
    /// True when the system matrix does not change with the state, so that its factorisation
    /// can be reused from one solve to the next while tangent_key() stays the same (Newmark:
    /// the time step, which the effective tangent contains).
    virtual bool constant_tangent() const = 0;
    virtual double tangent_key() const { return 0.0; }
    /// True when the first iteration needs the assembled tangent whether or not its
    /// factorisation is reused (prescribed increments enter it as -K_fp dU_p).
    virtual bool first_iteration_needs_tangent() const = 0;
    virtual const std::vector<Index>& equation_numbers() const = 0;
};

/// Newton-Raphson on a NewtonOperator (thesis Table 5.2.2): iterations
/// K(i-1) dU(i) = F - Fu(i-1) until every active criterion of eqs. 5.2.7-5.2.9 holds, with the
/// iteration log and, for a solve that fails, the worst DOF. It keeps the factorisation of a
/// constant tangent for the next solves.
class NewtonSolver {
  public:
    /// Iterate from the operator's current state. Appends every iteration to `log`; sets
    /// report.solver and, when the solve fails (not converged in settings.max_iterations, or a
    /// residual that is not finite), report.worst_dof and worst_residual. Exceptions of the
    /// linear solver (a singular tangent) and of the operator propagate.
    bool solve(NewtonOperator& op, const NewtonSettings& settings,
               std::vector<NewtonIteration>& log, StepReport& report);

  private:
    bool iterate(NewtonOperator& op, const NewtonSettings& settings,
                 std::vector<NewtonIteration>& log, StepReport& report);
    /// True when solver_ holds the factorisation of the operator's constant tangent.
    bool holds_factorization(const NewtonOperator& op) const;

    SparseSolver solver_;
    SparseSolver::Matrix factorized_; ///< the matrix solver_ factorised last
    bool kept_ = false;               ///< solver_ holds a constant tangent's factorisation
    double kept_key_ = 0.0;           ///< its tangent_key()
};

} // namespace grainload::fem
