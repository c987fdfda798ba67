#include "coupling/interface_accelerator.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace grainload::coupling {
namespace {

/// A linear loop H(F) = A F + b whose gain exceeds one in two modes (eigenvalues -3 and 2) and
/// is below it in four: the plain fixed-point iteration diverges, and Aitken's one factor
/// cannot serve modes of opposite sign at once.
struct LinearLoop {
    Eigen::MatrixXd a;
    Eigen::VectorXd b;

    LinearLoop() {
        const Eigen::VectorXd eigenvalues{{-3.0, -1.5, 0.5, 0.2, -0.8, 2.0}};
        // An orthogonal basis from the QR of a fixed, well-conditioned matrix.
        Eigen::MatrixXd m(6, 6);
        for (int i = 0; i < 6; ++i) {
            for (int j = 0; j < 6; ++j) {
                m(i, j) = 1.0 / (1.0 + i + 2 * j) + (i == j ? 1.0 : 0.0);
            }
        }
        const Eigen::MatrixXd q = m.householderQr().householderQ();
        a = q * eigenvalues.asDiagonal() * q.transpose();
        b = Eigen::VectorXd::LinSpaced(6, 1.0, 6.0);
    }
    Eigen::VectorXd operator()(const Eigen::VectorXd& f) const { return a * f + b; }
    /// The fixed point, (I - A) F = b, by a direct solve: the reference.
    Eigen::VectorXd solution() const {
        return (Eigen::MatrixXd::Identity(6, 6) - a).partialPivLu().solve(b);
    }
};

/// Passes until the relative change |H(F) - F| / |H(F)| is below `tolerance` (or `limit`).
int passes_to_converge(Accelerator method, const LinearLoop& loop, double tolerance, int limit,
                       Eigen::VectorXd& f) {
    InterfaceAccelerator accelerator(method, 0.5);
    f = Eigen::VectorXd::Zero(6);
    for (int pass = 1; pass <= limit; ++pass) {
        const Eigen::VectorXd produced = loop(f);
        if ((produced - f).norm() <= tolerance * produced.norm()) {
            f = produced;
            return pass;
        }
        f = accelerator.next(f, produced);
    }
    return limit + 1;
}

// IQN-ILS on a linear loop of six unknowns is a Krylov method (Degroote et al. 2009, sec. 3.3:
// equivalent to GMRES on (I - A) F = b): it has the fixed point after at most six differences,
// so by pass 8 (the first pass, six more to build V, one to confirm) to round-off; 1e-10 leaves
// the round-off of a 6 x 6 problem with condition number 4 (1 - eigenvalue: 4 to 0.5) far
// below it.
TEST(InterfaceAccelerator, QuasiNewtonFindsTheFixedPointOfALoopWithGainAboveOne) {
    const LinearLoop loop;
    Eigen::VectorXd f;
    const int passes = passes_to_converge(Accelerator::quasi_newton, loop, 1e-12, 50, f);
    EXPECT_LE(passes, 8);
    EXPECT_LT((f - loop.solution()).norm() / loop.solution().norm(), 1e-10);
}

// Aitken's single factor on the same loop: after 50 passes it is still not at the fixed point
// (the test documents why the quasi-Newton exists; were it to converge, the loop would not be
// the hard case it is meant to be).
TEST(InterfaceAccelerator, AitkenDoesNotConvergeOnTheSameLoop) {
    const LinearLoop loop;
    Eigen::VectorXd f;
    EXPECT_GT(passes_to_converge(Accelerator::aitken, loop, 1e-6, 50, f), 50);
}

} // namespace
} // namespace grainload::coupling
