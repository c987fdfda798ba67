#include "fem/shell_analysis.hpp"
#include "fem/shell_mesh_generators.hpp"
#include "materials/linear_elastic.hpp"

#include <gtest/gtest.h>
#include <limits>
#include <memory>
#include <random>

namespace grainload::fem {
namespace {

constexpr int kDofs = 6;

const materials::LinearElastic& steel() {
    static const materials::LinearElastic material(
        materials::ElasticConstants::from_young(7850.0, 2.1e11, 0.3));
    return material;
}

/// A curved panel (a cylinder segment 1 m long, 46 deg wide, 10 mm thick, 3 points through
/// the thickness), clamped along y = 0: every element couples membrane, bending and drilling.
/// With `stored`, the analysis works from its stored stiffness.
std::unique_ptr<ShellAnalysis> curved_panel(bool stored) {
    auto analysis = std::make_unique<ShellAnalysis>(make_cylinder(1.0, 1.0, 0.0, 0.8, 6, 4, 0.01),
                                                    steel(), Kinematics::linear, 3);
    analysis->prescribe(analysis->mesh().node_set("y0"), {0, 1, 2, 3, 4, 5});
    if (stored) {
        analysis->store_stiffness();
    }
    return analysis;
}

/// Translations up to 1 mm and rotations up to 10 mrad at every DOF, constrained ones too.
Eigen::VectorXd random_state(Index nodes, unsigned seed) {
    std::mt19937 generator(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Eigen::VectorXd u(kDofs * nodes);
    for (Eigen::Index i = 0; i < u.size(); ++i) {
        u(i) = (i % kDofs < 3 ? 1e-3 : 1e-2) * uniform(generator);
    }
    return u;
}

/// sum over elements of |k_e| |v_e| at every DOF (k_e with its drilling spring): the size of
/// the terms whose sums K v and the element loop's internal force are.
Eigen::VectorXd absolute_sum(const ShellAnalysis& analysis, const Eigen::VectorXd& v) {
    const ShellMesh& mesh = analysis.mesh();
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(v.size());
    for (Index e = 0; e < mesh.element_count(); ++e) {
        const ShellElement& element = mesh.element(e);
        Mitc4Shell copy = analysis.elements()[static_cast<std::size_t>(e)];
        ShellNodes nodes;
        Vector24 ve;
        for (int k = 0; k < 4; ++k) {
            const Index n = element.nodes[static_cast<std::size_t>(k)];
            nodes.x[static_cast<std::size_t>(k)] = mesh.node(n);
            nodes.director[static_cast<std::size_t>(k)] = analysis.initial_director(e, k);
            ve.segment<kDofs>(kDofs * k) = v.segment<kDofs>(kDofs * n);
        }
        Vector24 force;
        Matrix24 stiffness;
        copy.evaluate(nodes, ve, Kinematics::linear, force, &stiffness);
        const Vector24 terms = stiffness.cwiseAbs() * ve.cwiseAbs();
        for (int a = 0; a < 24; ++a) {
            sum(kDofs * element.nodes[static_cast<std::size_t>(a / kDofs)] + a % kDofs) += terms(a);
        }
    }
    return sum;
}

/// Largest |a_i - b_i| / scale_i.
double worst_ratio(const Eigen::VectorXd& a, const Eigen::VectorXd& b,
                   const Eigen::VectorXd& scale) {
    return ((a - b).cwiseAbs().array() / scale.array()).maxCoeff();
}

// For a linear shell the element loop's internal force sum B^T sigma dV is K u (linear strains,
// linear elastic stresses: fem/stored_stiffness.hpp); the two sum the same products
// w B_ai C_ab B_bj u_j in another order. On either side a product passes through at most
// 24 + 5 + 5 + 12 + 4 additions (DOFs, the two strain components, 12 points, 4 elements) and 4
// multiplications, so either sum is within gamma_54 = 54 eps / (1 - 54 eps) = 6e-15 of
// sum|terms| (Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., section 3.1).
// sum_e |k_e| |u_e| is below sum|terms| by the cancellation within k_e's Gauss sums only, so
// 1e-12 of it allows that cancellation up to 80x on both sides (measured: 2.9e-16).
TEST(StoredStiffness, InternalForceIsTheElementLoopsAtARandomState) {
    auto loop = curved_panel(false);
    auto stored = curved_panel(true);
    ASSERT_TRUE(stored->uses_stored_stiffness());
    ASSERT_FALSE(loop->uses_stored_stiffness());
    const Eigen::VectorXd u = random_state(loop->mesh().node_count(), 15);
    loop->update_state(u);
    stored->update_state(u);
    Eigen::VectorXd expected;
    Eigen::VectorXd internal;
    loop->assemble(nullptr, expected);
    stored->assemble(nullptr, internal);
    const Eigen::VectorXd scale = absolute_sum(*loop, u);
    EXPECT_LT(worst_ratio(internal, expected, scale), 1e-12);
    // Not a comparison of round-off: the force is of the size of its terms' sum.
    EXPECT_GT(expected.cwiseAbs().maxCoeff(), 1e-3 * scale.maxCoeff());
}

// The tangent and the prescribed DOFs' right-hand side K dU_p (fem/static_increment.hpp) come
// from the stored matrices too. A tangent entry sums at most 4 element entries and a drilling
// entry, each below the largest diagonal entry (element matrices are positive semi-definite,
// and the diagonal of K sums their non-negative diagonals), so the two orders differ by at
// most 5 eps of it (measured: 1.5e-19); K dU_p is bounded as the internal force above (measured:
// 4.2e-16).
TEST(StoredStiffness, TangentAndPrescribedIncrementAreTheElementLoops) {
    auto loop = curved_panel(false);
    auto stored = curved_panel(true);
    const Eigen::VectorXd prescribed = random_state(loop->mesh().node_count(), 26);
    SparseSolver::Matrix k_loop;
    SparseSolver::Matrix k_stored;
    Eigen::VectorXd internal;
    Eigen::VectorXd coupling_loop;
    Eigen::VectorXd coupling_stored;
    loop->assemble(&k_loop, internal, &prescribed, &coupling_loop);
    stored->assemble(&k_stored, internal, &prescribed, &coupling_stored);
    const double largest = k_loop.diagonal().cwiseAbs().maxCoeff();
    EXPECT_LE(Eigen::MatrixXd(k_loop - k_stored).cwiseAbs().maxCoeff(),
              5.0 * std::numeric_limits<double>::epsilon() * largest);
    EXPECT_LT(worst_ratio(coupling_stored, coupling_loop, absolute_sum(*loop, prescribed)), 1e-12);
}

// Stresses the stored stiffness leaves behind are evaluated when read, from the committed state
// to the committed DOFs by the element loop's own arithmetic: bit for bit what the element
// loop's convergence check would have left at the same DOFs.
TEST(StoredStiffness, StressesEvaluatedWhenReadAreTheElementLoopsBitForBit) {
    auto stored = curved_panel(true);
    stored->add_pressure(2e4);
    ASSERT_TRUE(stored->advance_load(1.0, 1, NewtonSettings{}).converged);
    auto loop = curved_panel(false);
    loop->update_state(stored->dofs());
    Eigen::VectorXd internal;
    loop->assemble(nullptr, internal);
    loop->commit();
    double largest = 0.0;
    for (std::size_t e = 0; e < loop->elements().size(); ++e) {
        const ShellResultants eager = loop->elements()[e].resultants();
        const ShellResultants lazy = stored->elements()[e].resultants();
        EXPECT_EQ(lazy.membrane, eager.membrane);
        EXPECT_EQ(lazy.bending, eager.bending);
        EXPECT_EQ(lazy.von_mises_top, eager.von_mises_top);
        EXPECT_EQ(lazy.von_mises_middle, eager.von_mises_middle);
        EXPECT_EQ(lazy.von_mises_bottom, eager.von_mises_bottom);
        largest = std::max(largest, eager.von_mises_top);
    }
    EXPECT_GT(largest, 1e6); // the pressure bends the panel: real stresses, not zeros
}

// Load steps with a prescribed edge motion and a pressure, stresses read after every step (as
// the coupling's extremes are): the stored stiffness and the element loop take the same Newton
// iterations to the same state. The two states differ by the round-off of the residuals above
// amplified by the conditioning of the thin panel's stiffness: with a condition number up to
// (L/t)^2 (L/h)^2 = 1e4 x 36 from bending against membrane action and the mesh, 1e-8 of the
// largest DOF bounds it (measured: 1.0e-11; von Mises stresses 1.9e-13).
TEST(StoredStiffness, LoadStepsWithPrescribedMotionFollowTheElementLoop) {
    auto stored = curved_panel(true);
    auto loop = curved_panel(false);
    for (ShellAnalysis* a : {stored.get(), loop.get()}) {
        a->prescribe(a->mesh().node_set("y1"), {2}, 0.01);
        a->add_pressure(2e4);
    }
    for (int step = 1; step <= 4; ++step) {
        const StepReport s = stored->advance_load(0.25 * step, 1, NewtonSettings{});
        const StepReport l = loop->advance_load(0.25 * step, 1, NewtonSettings{});
        ASSERT_TRUE(s.converged && l.converged);
        EXPECT_EQ(s.log.size(), l.log.size());
        const double scale = loop->dofs().cwiseAbs().maxCoeff();
        EXPECT_LT((stored->dofs() - loop->dofs()).cwiseAbs().maxCoeff(), 1e-8 * scale);
        double von_mises = 0.0;
        double difference = 0.0;
        for (std::size_t e = 0; e < loop->elements().size(); ++e) {
            const ShellResultants a = stored->elements()[e].resultants();
            const ShellResultants b = loop->elements()[e].resultants();
            von_mises = std::max(von_mises, b.von_mises_top);
            difference = std::max(difference, std::abs(a.von_mises_top - b.von_mises_top));
        }
        EXPECT_LT(difference, 1e-8 * von_mises);
        const Eigen::VectorXd reactions = loop->reactions();
        EXPECT_LT((stored->reactions() - reactions).cwiseAbs().maxCoeff(),
                  1e-8 * reactions.cwiseAbs().maxCoeff());
    }
}

// A follower pressure makes the tangent depend on the state: the element loop takes over.
TEST(StoredStiffness, FollowerPressureUsesTheElementLoop) {
    auto stored = curved_panel(true);
    stored->add_follower_pressure(1e3);
    EXPECT_FALSE(stored->uses_stored_stiffness());
}

} // namespace
} // namespace grainload::fem
