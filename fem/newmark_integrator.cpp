#include "fem/newmark_integrator.hpp"

#include <cmath>
#include <stdexcept>

namespace grainload::fem {

NewmarkIntegrator::NewmarkIntegrator(ShellAnalysis& analysis, double beta, double gamma)
    : analysis_(&analysis), beta_(beta), gamma_(gamma), mass_(analysis.lumped_mass()) {
    velocity_ = Eigen::VectorXd::Zero(mass_.size());
    acceleration_ = Eigen::VectorXd::Zero(mass_.size());
}

void NewmarkIntegrator::initialise(const Eigen::VectorXd& velocity) {
    velocity_ = velocity;
    // Initial acceleration from equilibrium at t = 0: M a = F - Fu (Bathe FEP Table 9.3).
    Eigen::VectorXd internal;
    analysis_->assemble(nullptr, internal);
    analysis_->revert_to_committed();
    const std::vector<Index>& eq = analysis_->equation_numbers();
    const Eigen::VectorXd force = analysis_->applied_forces(analysis_->load_factor()) - internal;
    acceleration_.setZero();
    for (std::size_t d = 0; d < eq.size(); ++d) {
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

StepReport NewmarkIntegrator::step(double dt, double load_factor, const NewtonSettings& settings) {
    const std::vector<Index>& eq = analysis_->equation_numbers();
    const Index free = analysis_->free_dof_count();
    const double c0 = 1.0 / (beta_ * dt * dt);
    const Eigen::VectorXd applied = analysis_->applied_forces(load_factor);
    // Prescribed values follow the load factor; they enter the first iteration through
    // -K_fp dU_p (M is diagonal, so inertia does not couple them to the free DOFs).
    Eigen::VectorXd prescribed = Eigen::VectorXd::Zero(mass_.size());
    for (std::size_t d = 0; d < eq.size(); ++d) {
        const double value = analysis_->prescribed_values()[d];
        if (eq[d] < 0 && !std::isnan(value)) {
            prescribed(static_cast<Eigen::Index>(d)) =
                (load_factor - analysis_->load_factor()) * value;
        }
    }
    Eigen::VectorXd increment = Eigen::VectorXd::Zero(mass_.size());
    // Newmark: a1 = c0 (dU - dt v0) - (1/(2 beta) - 1) a0.
    const auto new_acceleration = [&] {
        return Eigen::VectorXd(c0 * (increment - dt * velocity_) -
                               (0.5 / beta_ - 1.0) * acceleration_);
    };
    StepReport report;
    SparseSolver::Matrix k;
    Eigen::VectorXd internal;
    Eigen::VectorXd coupling;
    Eigen::VectorXd step;
    Eigen::VectorXd residual0;
    double energy0 = 0.0;
    for (int i = 0;; ++i) {
        analysis_->assemble(&k, internal, i == 0 ? &prescribed : nullptr, &coupling);
        Eigen::VectorXd full = applied - internal - mass_.cwiseProduct(new_acceleration());
        if (i == 0) {
            full -= coupling;
        }
        Eigen::VectorXd residual(free);
        for (std::size_t d = 0; d < eq.size(); ++d) {
            if (eq[d] >= 0) {
                residual(eq[d]) = full(static_cast<Eigen::Index>(d));
            }
        }
        if (i == 0) {
            residual0 = residual;
        } else {
            NewtonIteration it;
            it.iteration = i;
            it.force_ratio = residual.norm() / std::max(residual0.norm(), 1e-300);
            it.energy_ratio = std::abs(step.dot(residual)) / std::max(energy0, 1e-300);
            it.displacement_ratio = step.norm() / std::max(increment.norm(), 1e-300);
            it.residual_norm = residual.norm();
            report.log.push_back(it);
            if ((settings.force_tolerance <= 0.0 || it.force_ratio <= settings.force_tolerance) &&
                (settings.energy_tolerance <= 0.0 ||
                 it.energy_ratio <= settings.energy_tolerance)) {
                break;
            }
        }
        if (residual0.norm() == 0.0 || i == settings.max_iterations) {
            if (i == settings.max_iterations) {
                analysis_->revert_to_committed();
                return report;
            }
            break;
        }
        // Effective tangent K + c0 M (M lumped: diagonal).
        for (std::size_t d = 0; d < eq.size(); ++d) {
            if (eq[d] >= 0) {
                k.coeffRef(eq[d], eq[d]) += c0 * mass_(static_cast<Eigen::Index>(d));
            }
        }
        solver_.factorize(k);
        report.solver = SparseSolver::name(solver_.method());
        step = solver_.solve(residual);
        if (i == 0) {
            energy0 = std::abs(step.dot(residual0));
        }
        Eigen::VectorXd delta = i == 0 ? prescribed : Eigen::VectorXd::Zero(mass_.size());
        for (std::size_t d = 0; d < eq.size(); ++d) {
            if (eq[d] >= 0) {
                delta(static_cast<Eigen::Index>(d)) = step(eq[d]);
            }
        }
        increment += delta;
        analysis_->update_state(delta);
    }
    const Eigen::VectorXd a1 = new_acceleration();
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
    return 0.5 * velocity_.dot(mass_.cwiseProduct(velocity_));
}

double NewmarkIntegrator::strain_energy() {
    Eigen::VectorXd internal;
    analysis_->assemble(nullptr, internal);
    analysis_->revert_to_committed();
    return 0.5 * analysis_->dofs().dot(internal);
}

} // namespace grainload::fem
