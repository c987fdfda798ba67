#include "fem/sparse_solver.hpp"

#include <gtest/gtest.h>

namespace grainload::fem {
namespace {

SparseSolver::Matrix tridiagonal(int n, double diagonal) {
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < n; ++i) {
        t.emplace_back(i, i, diagonal);
        if (i + 1 < n) {
            t.emplace_back(i, i + 1, -1.0);
            t.emplace_back(i + 1, i, -1.0);
        }
    }
    SparseSolver::Matrix k(n, n);
    k.setFromTriplets(t.begin(), t.end());
    return k;
}

TEST(SparseSolver, PositiveDefiniteUsesCholmod) {
    const SparseSolver::Matrix k = tridiagonal(50, 2.5);
    SparseSolver solver;
    solver.factorize(k);
    EXPECT_EQ(solver.method(), SparseSolver::Method::cholmod_supernodal_llt);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(50, 1.0, 2.0);
    EXPECT_LT((k * solver.solve(b) - b).norm(), 1e-12 * b.norm());
}

TEST(SparseSolver, IndefiniteFallsBackToUmfpack) {
    SparseSolver::Matrix k = tridiagonal(50, 2.5);
    k.coeffRef(10, 10) = -3.0; // one negative pivot, as after a limit point
    SparseSolver solver;
    solver.factorize(k);
    EXPECT_EQ(solver.method(), SparseSolver::Method::umfpack_lu);
    const Eigen::VectorXd b = Eigen::VectorXd::Ones(50);
    EXPECT_LT((k * solver.solve(b) - b).norm(), 1e-12 * b.norm());
    EXPECT_EQ(SparseSolver::name(solver.method()), "UMFPACK LU");
}

TEST(SparseSolver, SingularMatrixThrows) {
    SparseSolver::Matrix k(3, 3);
    k.insert(0, 0) = 1.0;
    k.insert(1, 1) = 0.0;
    k.insert(2, 2) = 1.0;
    SparseSolver solver;
    EXPECT_THROW(solver.factorize(k), std::runtime_error);
}

} // namespace
} // namespace grainload::fem
