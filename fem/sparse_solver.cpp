#include "fem/sparse_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>
#include <chrono>
#include <stdexcept>

namespace grainload::fem {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

struct SparseSolver::Impl {
    Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> cholesky;
    Eigen::UmfPackLU<Matrix> lu;
    Eigen::Index rows = -1;
    Eigen::Index nonzeros = -1;
    bool lu_analysed = false;
};

SparseSolver::SparseSolver() : impl_(std::make_unique<Impl>()) {
    cholmod_common& c = impl_->cholesky.cholmod();
    c.nmethods = 1;
    c.method[0].ordering = CHOLMOD_METIS;
    c.postorder = 1;
}

SparseSolver::~SparseSolver() = default;

namespace {

// Process-wide sums; the FEM runs on one thread (its solves are not parallel to each other).
SparseSolver::Totals& running_totals() {
    static SparseSolver::Totals totals;
    return totals;
}

} // namespace

SparseSolver::Totals SparseSolver::totals() {
    return running_totals();
}

void SparseSolver::factorize(const Matrix& k, bool symmetric) {
    const bool same_pattern = k.rows() == impl_->rows && k.nonZeros() == impl_->nonzeros;
    analysis_seconds_ = 0.0;
    if (!same_pattern) {
        const auto start = std::chrono::steady_clock::now();
        impl_->cholesky.analyzePattern(k);
        impl_->lu_analysed = false;
        impl_->rows = k.rows();
        impl_->nonzeros = k.nonZeros();
        analysis_seconds_ = seconds_since(start);
        running_totals().analysis += analysis_seconds_;
    }
    const auto start = std::chrono::steady_clock::now();
    if (symmetric) {
        impl_->cholesky.factorize(k);
    }
    if (symmetric && impl_->cholesky.info() == Eigen::Success) {
        method_ = Method::cholmod_supernodal_llt;
        factorization_seconds_ = seconds_since(start);
        running_totals().factorization += factorization_seconds_;
        return;
    }
    if (!impl_->lu_analysed) {
        impl_->lu.analyzePattern(k);
        impl_->lu_analysed = true;
    }
    impl_->lu.factorize(k);
    factorization_seconds_ = seconds_since(start);
    running_totals().factorization += factorization_seconds_;
    if (impl_->lu.info() != Eigen::Success) {
        method_ = Method::none;
        throw std::runtime_error("stiffness matrix is singular (CHOLMOD and UMFPACK both failed); "
                                 "check the boundary conditions for rigid-body modes");
    }
    method_ = Method::umfpack_lu;
}

Eigen::VectorXd SparseSolver::solve(const Eigen::VectorXd& rhs) const {
    const auto start = std::chrono::steady_clock::now();
    Eigen::VectorXd x;
    switch (method_) {
    case Method::cholmod_supernodal_llt:
        x = impl_->cholesky.solve(rhs);
        break;
    case Method::umfpack_lu:
        x = impl_->lu.solve(rhs);
        break;
    case Method::none:
        throw std::logic_error("SparseSolver::solve called before a successful factorize");
    }
    running_totals().solve += seconds_since(start);
    return x;
}

double SparseSolver::cholesky_flops() const {
    return impl_->cholesky.cholmod().fl;
}

std::string_view SparseSolver::name(Method method) {
    switch (method) {
    case Method::cholmod_supernodal_llt:
        return "CHOLMOD supernodal LLT (METIS)";
    case Method::umfpack_lu:
        return "UMFPACK LU";
    case Method::none:
        break;
    }
    return "none";
}

} // namespace grainload::fem
