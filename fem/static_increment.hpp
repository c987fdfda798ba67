#pragma once
// A static load increment of a structure as the operator of its Newton solve.

#include "fem/newton_solver.hpp"
#include "fem/static_system.hpp"

namespace grainload::fem {

/// A static load increment of a StaticSystem (a ShellAnalysis) as the operator of its Newton solve
/// (thesis Table 5.2.2): residual F(to) - Fu(i) over the free DOFs, the tangent K, and additive
/// (rotations: multiplicative) state updates. Prescribed increments enter the first iteration
/// through the right-hand side, -K_fp dU_p, with the tangent of the converged state (Bathe FEP
/// section 8.4): imposing them on the state first would strain only the elements next to the
/// constrained nodes and, with plasticity, yield them spuriously.
class StaticIncrement final : public NewtonOperator {
  public:
    /// The increment of `analysis` from load factor `from` to `to`.
    StaticIncrement(StaticSystem& analysis, double from, double to, const NewtonSettings& settings);

    Eigen::VectorXd residual(int iteration, SparseSolver::Matrix* tangent) override;
    bool in_balance(const Eigen::VectorXd& residual) const override;
    void factorize(SparseSolver::Matrix& tangent, SparseSolver& solver) const override;
    void correct(int iteration, const Eigen::VectorXd& step) override;
    void settle() override;
    double displacement_norm() const override;
    bool constant_tangent() const override;
    bool first_iteration_needs_tangent() const override;
    const std::vector<Index>& equation_numbers() const override { return equation_; }

  private:
    StaticSystem& analysis_;
    const std::vector<Index>& equation_;
    double force_tolerance_;
    Eigen::VectorXd prescribed_increment_;
    Eigen::VectorXd applied_;
    double applied_norm_ = 0.0; ///< of the free DOFs
    Eigen::VectorXd internal_;
    Eigen::VectorXd coupling_;
};

} // namespace grainload::fem
