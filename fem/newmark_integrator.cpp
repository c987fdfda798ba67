#include "fem/newmark_integrator.hpp"

#include <cmath>
#include <stdexcept>

namespace grainload::fem {

NewmarkIntegrator::NewmarkIntegrator(ShellAnalysis& analysis, double beta, double gamma,
                                     double alpha, MassMatrix mass)
    : analysis_(&analysis), beta_(beta), gamma_(gamma), alpha_(alpha),
      mass_(analysis.lumped_mass()), consistent_(mass == MassMatrix::consistent) {
    if (alpha < -1.0 / 3.0 || alpha > 0.0) {
        throw std::invalid_argument("HHT alpha must lie in [-1/3, 0]");
    }
    if (consistent_) {
        mass_matrix_ = analysis.consistent_mass();
        const std::vector<Index>& eq = analysis.equation_numbers();
        std::vector<Eigen::Triplet<double>> triplets;
        for (Eigen::Index col = 0; col < mass_matrix_.outerSize(); ++col) {
            for (SparseSolver::Matrix::InnerIterator it(mass_matrix_, col); it; ++it) {
                const Index r = eq[static_cast<std::size_t>(it.row())];
                const Index c = eq[static_cast<std::size_t>(it.col())];
                if (r >= 0 && c >= 0) {
                    triplets.emplace_back(r, c, it.value());
                }
            }
        }
        mass_free_.resize(analysis.free_dof_count(), analysis.free_dof_count());
        mass_free_.setFromTriplets(triplets.begin(), triplets.end());
    }
    velocity_ = Eigen::VectorXd::Zero(mass_.size());
    acceleration_ = Eigen::VectorXd::Zero(mass_.size());
}

void NewmarkIntegrator::initialise(const Eigen::VectorXd& velocity) {
    velocity_ = velocity;
    // Initial acceleration from equilibrium at t = 0: M a = F - Fu (Bathe FEP Table 9.3).
    Eigen::VectorXd internal;
    analysis_->set_assembly_load_factor(analysis_->load_factor());
    analysis_->assemble(nullptr, internal);
    analysis_->revert_to_committed();
    const std::vector<Index>& eq = analysis_->equation_numbers();
    const Eigen::VectorXd force = analysis_->applied_forces(analysis_->load_factor()) - internal;
    acceleration_.setZero();
    if (consistent_) {
        SparseSolver mass_solver;
        mass_solver.factorize(mass_free_);
        scatter_free(eq, mass_solver.solve(free_part(eq, analysis_->free_dof_count(), force)),
                     acceleration_);
    }
    for (std::size_t d = 0; d < eq.size() && !consistent_; ++d) {
        const auto i = static_cast<Eigen::Index>(d);
        if (eq[d] >= 0 && mass_(i) > 0.0) {
            acceleration_(i) = force(i) / mass_(i);
        }
    }
    for (std::size_t d = 0; d < eq.size(); ++d) {
        if (eq[d] < 0) {
            velocity_(static_cast<Eigen::Index>(d)) = 0.0;
        }
    }
}

/// The effective system of one Newmark/HHT step: the residual
/// (1 + alpha)(F - Fu)(n+1) - alpha (F - Fu)(n) - M a(n+1) over the free DOFs, the effective
/// tangent (1 + alpha) K + c0 M, and the step's displacement increment dU.
class NewmarkIntegrator::Step final : public NewtonOperator {
  public:
    Step(NewmarkIntegrator& integrator, double dt, double load_factor);

    /// Newmark: a1 = c0 (dU - dt v0) - (1/(2 beta) - 1) a0.
    Eigen::VectorXd acceleration() const {
        return Eigen::VectorXd(c0_ * (increment_ - dt_ * integrator_.velocity_) -
                               (0.5 / integrator_.beta_ - 1.0) * integrator_.acceleration_);
    }
    Eigen::VectorXd residual(int iteration, SparseSolver::Matrix* tangent) override;
    /// Only an exact balance (at rest, unloaded): the inertia gives every other step a first
    /// residual for the ratios of eqs. 5.2.8-5.2.9 to measure against.
    bool in_balance(const Eigen::VectorXd& residual) const override {
        return residual.norm() == 0.0;
    }
    void factorize(SparseSolver::Matrix& tangent, SparseSolver& solver) const override;
    void correct(int iteration, const Eigen::VectorXd& step) override;
    double displacement_norm() const override { return increment_.norm(); }
    bool constant_tangent() const override { return integrator_.analysis_->constant_tangent(); }
    /// The effective tangent contains c0 = 1 / (beta dt^2).
    double tangent_key() const override { return dt_; }
    /// A stored stiffness gives K_fp dU_p without assembling the tangent.
    bool first_iteration_needs_tangent() const override {
        return !prescribed_.isZero(0.0) && !analysis_.uses_stored_stiffness();
    }
    const std::vector<Index>& equation_numbers() const override { return equation_; }

  private:
    NewmarkIntegrator& integrator_;
    ShellAnalysis& analysis_;
    const std::vector<Index>& equation_;
    double dt_;
    double c0_;
    Eigen::VectorXd applied_;
    Eigen::VectorXd previous_;
    Eigen::VectorXd prescribed_;
    Eigen::VectorXd increment_;
    Eigen::VectorXd internal_;
    Eigen::VectorXd coupling_;
};

NewmarkIntegrator::Step::Step(NewmarkIntegrator& integrator, double dt, double load_factor)
    : integrator_(integrator), analysis_(*integrator.analysis_),
      equation_(integrator.analysis_->equation_numbers()), dt_(dt),
      c0_(1.0 / (integrator.beta_ * dt * dt)), applied_(analysis_.applied_forces(load_factor)),
      previous_(Eigen::VectorXd::Zero(integrator.mass_.size())),
      increment_(Eigen::VectorXd::Zero(integrator.mass_.size())) {
    // HHT-alpha: the out-of-balance force of the converged state n (its follower loads at
    // t(n)), weighted by -alpha.
    if (integrator_.alpha_ != 0.0) {
        Eigen::VectorXd internal_n;
        analysis_.set_assembly_load_factor(analysis_.load_factor());
        analysis_.assemble(nullptr, internal_n);
        analysis_.revert_to_committed();
        previous_ = analysis_.applied_forces(analysis_.load_factor()) - internal_n;
    }
    analysis_.set_assembly_load_factor(load_factor);
    // Prescribed values follow their histories; they enter the first iteration through
    // -K_fp dU_p. A lumped M does not couple them to the free DOFs; a consistent M does, and
    // that coupling enters through the residual from the second iteration on.
    prescribed_ =
        analysis_.prescribed_at(load_factor) - analysis_.prescribed_at(analysis_.load_factor());
}

Eigen::VectorXd NewmarkIntegrator::Step::residual(int iteration, SparseSolver::Matrix* tangent) {
    analysis_.assemble(tangent, internal_, iteration == 0 ? &prescribed_ : nullptr, &coupling_);
    const double alpha = integrator_.alpha_;
    Eigen::VectorXd full = (1.0 + alpha) * (applied_ - internal_) - alpha * previous_ -
                           integrator_.inertia(acceleration());
    if (iteration == 0) {
        full -= (1.0 + alpha) * coupling_;
    }
    return free_part(equation_, analysis_.free_dof_count(), full);
}

void NewmarkIntegrator::Step::factorize(SparseSolver::Matrix& tangent, SparseSolver& solver) const {
    // Effective tangent (1 + alpha) K + c0 M. The consistent M couples only DOFs that K
    // couples too, so the sum keeps the pattern (and the reused symbolic analysis).
    tangent *= 1.0 + integrator_.alpha_;
    if (integrator_.consistent_) {
        tangent += c0_ * integrator_.mass_free_;
    }
    for (std::size_t d = 0; d < equation_.size() && !integrator_.consistent_; ++d) {
        if (equation_[d] >= 0) {
            tangent.coeffRef(equation_[d], equation_[d]) +=
                c0_ * integrator_.mass_(static_cast<Eigen::Index>(d));
        }
    }
    solver.factorize(tangent, analysis_.tangent_symmetric());
}

void NewmarkIntegrator::Step::correct(int iteration, const Eigen::VectorXd& step) {
    Eigen::VectorXd delta =
        iteration == 0 ? prescribed_ : Eigen::VectorXd::Zero(integrator_.mass_.size());
    scatter_free(equation_, step, delta);
    increment_ += delta;
    analysis_.update_state(delta);
}

StepReport NewmarkIntegrator::step(double dt, double load_factor, const NewtonSettings& settings) {
    Step problem(*this, dt, load_factor);
    StepReport report;
    if (!newton_.solve(problem, settings, report.log, report)) {
        analysis_->revert_to_committed();
        return report;
    }
    const Eigen::VectorXd a1 = problem.acceleration();
    velocity_ += dt * ((1.0 - gamma_) * acceleration_ + gamma_ * a1);
    acceleration_ = a1;
    analysis_->set_load_factor(load_factor);
    analysis_->commit();
    report.converged = true;
    report.increments = 1;
    report.load_factor = load_factor;
    report.iterations.push_back(static_cast<int>(report.log.size()));
    return report;
}

double NewmarkIntegrator::kinetic_energy() const {
    return 0.5 * velocity_.dot(inertia(velocity_));
}

Eigen::VectorXd NewmarkIntegrator::inertia(const Eigen::VectorXd& x) const {
    return consistent_ ? Eigen::VectorXd(mass_matrix_ * x) : Eigen::VectorXd(mass_.cwiseProduct(x));
}

double NewmarkIntegrator::strain_energy() {
    Eigen::VectorXd internal;
    analysis_->assemble(nullptr, internal);
    analysis_->revert_to_committed();
    return 0.5 * analysis_->dofs().dot(internal);
}

} // namespace grainload::fem
