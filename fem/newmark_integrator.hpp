#pragma once
// Implicit Newmark and HHT-alpha time integration of a shell, with lumped or consistent mass.

#include "fem/shell_analysis.hpp"

namespace grainload::fem {

/// How the inertia is discretised: diagonal lumped (row-sum) or the consistent element matrix
/// (Bathe FEP section 4.2.1). Consistent mass bounds the frequencies from above (Rayleigh-Ritz);
/// lumped mass usually approaches them from below.
enum class MassMatrix { lumped, consistent };

/// Implicit Newmark time integration of a ShellAnalysis with its lumped or consistent mass (Bathe
/// FEP section 9.2.4, Table 9.3): beta = 1/4, gamma = 1/2 is the trapezoidal rule (no numerical
/// damping, energy conserving for linear systems); gamma > 1/2 with beta = (gamma + 1/2)^2 / 4
/// damps high frequencies. Every step is solved by Newton-Raphson (fem/newton_solver.hpp) on
/// the effective system (K + M / (beta dt^2)) dU = F - Fu - M a, with the norms of thesis
/// eqs. 5.2.7-5.2.9.
/// Rotations are integrated as additive rotation vectors (moderate rotations per step).
/// Constrained DOFs follow their prescribed histories.
///
/// With alpha != 0 this is the HHT-alpha method (Hilber, Hughes & Taylor 1977, Earthquake Eng.
/// Struct. Dyn. 5:283-292): equilibrium is enforced at the weighted point
///   M a(n+1) = (1 + alpha) (F - Fu)(n+1) - alpha (F - Fu)(n),   -1/3 <= alpha <= 0,
/// with beta = (1 - alpha)^2 / 4, gamma = (1 - 2 alpha) / 2: unconditionally stable,
/// second-order accurate, and damping high frequencies down to the spectral radius
/// rho_inf = (1 + alpha) / (1 - alpha). alpha = 0 is the trapezoidal rule.
class NewmarkIntegrator {
  public:
    NewmarkIntegrator(ShellAnalysis& analysis, double beta = 0.25, double gamma = 0.5,
                      double alpha = 0.0, MassMatrix mass = MassMatrix::lumped);
    /// The HHT-alpha method with its second-order beta and gamma.
    static NewmarkIntegrator hht(ShellAnalysis& analysis, double alpha,
                                 MassMatrix mass = MassMatrix::lumped) {
        return NewmarkIntegrator(analysis, 0.25 * (1.0 - alpha) * (1.0 - alpha), 0.5 - alpha, alpha,
                                 mass);
    }

    /// Start from the analysis' current (committed) state with the given velocity (full-size).
    void initialise(const Eigen::VectorXd& velocity);
    /// Advance by dt with the load factor `load_factor` at the end of the step.
    StepReport step(double dt, double load_factor, const NewtonSettings& settings);

    /// Restore the velocity and acceleration of a checkpoint.
    void restore(const Eigen::VectorXd& velocity, const Eigen::VectorXd& acceleration) {
        velocity_ = velocity;
        acceleration_ = acceleration;
    }
    const Eigen::VectorXd& velocity() const { return velocity_; }
    const Eigen::VectorXd& acceleration() const { return acceleration_; }
    double kinetic_energy() const;
    /// Work of the internal forces, u . Fu / 2: the strain energy of a linear model.
    double strain_energy();

  private:
    class Step; ///< one step's effective system, the operator of its Newton solve

    /// M x over all DOFs.
    Eigen::VectorXd inertia(const Eigen::VectorXd& x) const;

    ShellAnalysis* analysis_;
    double beta_;
    double gamma_;
    double alpha_;
    Eigen::VectorXd mass_; ///< lumped mass per DOF
    bool consistent_ = false;
    SparseSolver::Matrix mass_matrix_; ///< consistent: all DOFs
    SparseSolver::Matrix mass_free_;   ///< consistent: free-free block
    Eigen::VectorXd velocity_;
    Eigen::VectorXd acceleration_;
    /// Solves the steps; keeps a linear shell's factorised effective tangent while dt holds.
    NewtonSolver newton_;
};

} // namespace grainload::fem
