#pragma once
// The direct solver of the shell's stiffness system: CHOLMOD Cholesky, else UMFPACK LU.

#include <Eigen/SparseCore>
#include <memory>
#include <string_view>

namespace grainload::fem {

/// Direct solver for the global stiffness system. Symmetric positive definite tangents go to
/// CHOLMOD's supernodal Cholesky with a forced METIS fill-reducing ordering (CHOLMOD by default
/// tries AMD first); an indefinite tangent (after buckling or a limit point) makes CHOLMOD
/// report NumericalIssue, and the same matrix is then factorised by UMFPACK's LU. The symbolic
/// analysis is reused while the sparsity pattern does not change.
class SparseSolver {
  public:
    enum class Method { none, cholmod_supernodal_llt, umfpack_lu };
    using Matrix = Eigen::SparseMatrix<double>;

    SparseSolver();
    ~SparseSolver();
    SparseSolver(const SparseSolver&) = delete;
    SparseSolver& operator=(const SparseSolver&) = delete;

    /// Factorise `k` (both triangles stored). A non-symmetric `k` goes straight to UMFPACK.
    /// Throws std::runtime_error when neither method succeeds (singular matrix).
    void factorize(const Matrix& k, bool symmetric = true);
    Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const;

    Method method() const { return method_; }
    static std::string_view name(Method method);
    /// Seconds spent in the last symbolic analysis and numeric factorisation.
    double analysis_seconds() const { return analysis_seconds_; }
    double factorization_seconds() const { return factorization_seconds_; }
    /// Seconds spent by every SparseSolver of the process so far, by phase: symbolic analysis,
    /// numeric factorisation, forward and back substitution (for the cost split of a coupled
    /// run: bench/coupling_cost).
    struct Totals {
        double analysis = 0.0;
        double factorization = 0.0;
        double solve = 0.0;
    };
    static Totals totals();
    /// CHOLMOD's floating-point operation count of its last symbolic analysis (cholmod_common
    /// `fl`), to turn the factorisation time into a rate; 0 before any analysis.
    double cholesky_flops() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    Method method_ = Method::none;
    double analysis_seconds_ = 0.0;
    double factorization_seconds_ = 0.0;
};

} // namespace grainload::fem
