#include "fem/newton_solver.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace grainload::fem {
namespace {

/// Two uncoupled hardening springs k u + c u^3 = f (DOFs 0 and 2 of three; DOF 1 is fixed),
/// or (c = 0) a linear system with the coupled stiffness K below. Counts its factorisations.
class Springs final : public NewtonOperator {
  public:
    Springs(double c, Eigen::Vector2d force) : c_(c), force_(std::move(force)) {}

    Eigen::VectorXd residual(int, SparseSolver::Matrix* tangent) override {
        Eigen::Matrix2d k;
        k << 3.0, -1.0, -1.0, 2.0;
        if (c_ != 0.0) {
            k = Eigen::Vector2d(3.0 + 3.0 * c_ * u_(0) * u_(0), 2.0 + 3.0 * c_ * u_(1) * u_(1))
                    .asDiagonal();
        }
        if (tangent != nullptr) {
            *tangent = k.sparseView();
        }
        const Eigen::Vector2d internal =
            c_ != 0.0 ? Eigen::Vector2d(3.0 * u_(0) + c_ * std::pow(u_(0), 3),
                                        2.0 * u_(1) + c_ * std::pow(u_(1), 3))
                      : Eigen::Vector2d(k * u_);
        return force_ - internal;
    }
    bool in_balance(const Eigen::VectorXd& residual) const override {
        return residual.norm() == 0.0;
    }
    void factorize(SparseSolver::Matrix& tangent, SparseSolver& solver) const override {
        ++factorizations;
        solver.factorize(tangent);
    }
    void correct(int, const Eigen::VectorXd& step) override { u_ += step; }
    double displacement_norm() const override { return u_.norm(); }
    bool constant_tangent() const override { return c_ == 0.0; }
    double tangent_key() const override { return key; }
    bool first_iteration_needs_tangent() const override { return false; }
    const std::vector<Index>& equation_numbers() const override { return equation_; }

    const Eigen::Vector2d& u() const { return u_; }
    mutable int factorizations = 0;
    double key = 0.0;

  private:
    double c_;
    Eigen::Vector2d force_;
    Eigen::Vector2d u_ = Eigen::Vector2d::Zero();
    std::vector<Index> equation_{0, -1, 1};
};

// Newton on 3 u + u^3 = 14 and 2 u + u^3 = 12 (roots u = 2 exactly) converges quadratically:
// each force ratio of eq. 5.2.8 is at most a constant times the square of the one before.
TEST(NewtonSolver, NonlinearSpringsConvergeQuadraticallyToTheRoot) {
    Springs springs(1.0, Eigen::Vector2d(14.0, 12.0));
    NewtonSolver newton;
    NewtonSettings settings;
    settings.force_tolerance = 1e-12;
    settings.energy_tolerance = 0.0;
    std::vector<NewtonIteration> log;
    StepReport report;
    ASSERT_TRUE(newton.solve(springs, settings, log, report));
    // The force criterion 1e-12 of ||F - Fu(0)|| = 18.4 N bounds the residual; the tangent
    // 3 + 3 u^2 >= 14 turns it into a displacement error below 2e-12.
    constexpr double kRootTolerance = 2e-12;
    EXPECT_NEAR(springs.u()(0), 2.0, kRootTolerance);
    EXPECT_NEAR(springs.u()(1), 2.0, kRootTolerance);
    ASSERT_GE(log.size(), 3U);
    // Quadratic convergence: r(i+1) <= C r(i)^2 with C = f''/(2 f'^2), about 0.03 here;
    // 1 leaves room for the first, farther iterations. Ratios are r(i) / r(0).
    constexpr double kQuadraticConstant = 1.0;
    const double r0 = Eigen::Vector2d(14.0, 12.0).norm();
    for (std::size_t i = 1; i + 1 < log.size(); ++i) {
        EXPECT_LE(log[i].force_ratio * r0,
                  kQuadraticConstant * std::pow(log[i - 1].force_ratio * r0, 2));
    }
    EXPECT_EQ(report.worst_dof, -1);
}

// A constant tangent is factorised once and then reused by later solves while its key holds
// (the solution still the exact K^-1 f: 3u - v = 1, -u + 2v = 3 -> u = 1, v = 2).
TEST(NewtonSolver, ConstantTangentFactorisationIsReusedWhileItsKeyHolds) {
    Springs springs(0.0, Eigen::Vector2d(1.0, 3.0));
    NewtonSolver newton;
    std::vector<NewtonIteration> log;
    StepReport report;
    ASSERT_TRUE(newton.solve(springs, NewtonSettings{}, log, report));
    // One solve of a 2 x 2 system: round-off of a few ulp.
    constexpr double kSolveTolerance = 1e-14;
    EXPECT_NEAR(springs.u()(0), 1.0, kSolveTolerance);
    EXPECT_NEAR(springs.u()(1), 2.0, kSolveTolerance);
    EXPECT_EQ(springs.factorizations, 1);
    Springs again(0.0, Eigen::Vector2d(2.0, 6.0));
    ASSERT_TRUE(newton.solve(again, NewtonSettings{}, log, report));
    EXPECT_EQ(again.factorizations, 0);
    EXPECT_NEAR(again.u()(1), 4.0, 2.0 * kSolveTolerance);
    Springs other_step(0.0, Eigen::Vector2d(2.0, 6.0));
    other_step.key = 1.0;
    ASSERT_TRUE(newton.solve(other_step, NewtonSettings{}, log, report));
    EXPECT_EQ(other_step.factorizations, 1);
}

// A solve that does not converge reports the free DOF furthest out of balance (global DOF 2,
// the second spring, whose residual after one iteration is the larger); a constant tangent's
// factorisation does not outlive a failed solve; a non-finite residual stops at once.
TEST(NewtonSolver, FailureNamesTheWorstDofAndDropsTheFactorisation) {
    Springs springs(1.0, Eigen::Vector2d(4.0, 120.0));
    NewtonSolver newton;
    NewtonSettings settings;
    settings.max_iterations = 1;
    std::vector<NewtonIteration> log;
    StepReport report;
    EXPECT_FALSE(newton.solve(springs, settings, log, report));
    const double u = springs.u()(1);
    EXPECT_EQ(report.worst_dof, 2);
    EXPECT_DOUBLE_EQ(report.worst_residual, 120.0 - (2.0 * u + std::pow(u, 3)));
    Springs linear(0.0, Eigen::Vector2d(1.0, 3.0));
    ASSERT_TRUE(newton.solve(linear, NewtonSettings{}, log, report));
    EXPECT_EQ(linear.factorizations, 1);
    settings.max_iterations = 0;
    Springs failing(0.0, Eigen::Vector2d(1.0, 3.0));
    EXPECT_FALSE(newton.solve(failing, settings, log, report));
    EXPECT_EQ(failing.factorizations, 0);
    Springs after(0.0, Eigen::Vector2d(1.0, 3.0));
    ASSERT_TRUE(newton.solve(after, NewtonSettings{}, log, report));
    EXPECT_EQ(after.factorizations, 1);
    Springs broken(0.0, Eigen::Vector2d(std::numeric_limits<double>::quiet_NaN(), 3.0));
    EXPECT_FALSE(newton.solve(broken, NewtonSettings{}, log, report));
    EXPECT_EQ(report.worst_dof, 0);
    EXPECT_TRUE(std::isnan(report.worst_residual));
}

} // namespace
} // namespace grainload::fem
