#pragma once

#include "fem/shell_analysis.hpp"

namespace grainload::fem {

/// Implicit Newmark time integration of a ShellAnalysis with its lumped mass (Bathe FEP
/// section 9.2.4, Table 9.3): beta = 1/4, gamma = 1/2 is the trapezoidal rule (no numerical
/// damping, energy conserving for linear systems); gamma > 1/2 with beta = (gamma + 1/2)^2 / 4
/// damps high frequencies. Every step is solved by Newton-Raphson on the effective system
/// (K + M / (beta dt^2)) dU = F - Fu - M a, with the norms of thesis eqs. 5.2.7-5.2.9.
/// Rotations are integrated as additive rotation vectors (moderate rotations per step).
/// Constrained DOFs follow their prescribed values times the load factor.
class NewmarkIntegrator {
  public:
    NewmarkIntegrator(ShellAnalysis& analysis, double beta = 0.25, double gamma = 0.5);

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
    ShellAnalysis* analysis_;
    double beta_;
    double gamma_;
    Eigen::VectorXd mass_;
    Eigen::VectorXd velocity_;
    Eigen::VectorXd acceleration_;
    SparseSolver solver_;
};

} // namespace grainload::fem
