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
        Eigen::VectorXd rhs(analysis_->free_dof_count());
        for (std::size_t d = 0; d < eq.size(); ++d) {
            if (eq[d] >= 0) {
                rhs(eq[d]) = force(static_cast<Eigen::Index>(d));
            }
        }
        SparseSolver mass_solver;
        mass_solver.factorize(mass_free_);
        const Eigen::VectorXd a = mass_solver.solve(rhs);
        for (std::size_t d = 0; d < eq.size(); ++d) {
            if (eq[d] >= 0) {
                acceleration_(static_cast<Eigen::Index>(d)) = a(eq[d]);
            }
        }
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

StepReport NewmarkIntegrator::step(double dt, double load_factor, const NewtonSettings& settings) {
    const std::vector<Index>& eq = analysis_->equation_numbers();
    const Index free = analysis_->free_dof_count();
    const double c0 = 1.0 / (beta_ * dt * dt);
    const Eigen::VectorXd applied = analysis_->applied_forces(load_factor);
    // HHT-alpha: the out-of-balance force of the converged state n (its follower loads at
    // t(n)), weighted by -alpha.
    Eigen::VectorXd previous = Eigen::VectorXd::Zero(mass_.size());
    if (alpha_ != 0.0) {
        Eigen::VectorXd internal_n;
        analysis_->set_assembly_load_factor(analysis_->load_factor());
        analysis_->assemble(nullptr, internal_n);
        analysis_->revert_to_committed();
        previous = analysis_->applied_forces(analysis_->load_factor()) - internal_n;
    }
    analysis_->set_assembly_load_factor(load_factor);
    // Prescribed values follow their histories; they enter the first iteration through
    // -K_fp dU_p. A lumped M does not couple them to the free DOFs; a consistent M does, and
    // that coupling enters through the residual from the second iteration on.
    const Eigen::VectorXd prescribed =
        analysis_->prescribed_at(load_factor) - analysis_->prescribed_at(analysis_->load_factor());
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
    // A reused factorisation (below) needs no tangent: the element loop then forms the internal
    // forces only, unless prescribed increments need K_fp.
    const bool known_reuse = analysis_->constant_tangent() && factorized_step_ == dt &&
                             solver_.method() != SparseSolver::Method::none &&
                             prescribed.isZero(0.0);
    for (int i = 0;; ++i) {
        analysis_->assemble(known_reuse ? nullptr : &k, internal, i == 0 ? &prescribed : nullptr,
                            &coupling);
        Eigen::VectorXd full =
            (1.0 + alpha_) * (applied - internal) - alpha_ * previous - inertia(new_acceleration());
        if (i == 0) {
            full -= (1.0 + alpha_) * coupling;
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
                record_worst_dof(eq, residual, report);
                analysis_->revert_to_committed();
                return report;
            }
            break;
        }
        // A linear shell's effective tangent does not change while dt does not: its
        // factorisation from an earlier step solves this one exactly (the coupling's many
        // short windows would otherwise refactorise the same matrix every window).
        const bool reuse = analysis_->constant_tangent() && factorized_step_ == dt &&
                           solver_.method() != SparseSolver::Method::none;
        if (!reuse) {
            // Effective tangent (1 + alpha) K + c0 M. The consistent M couples only DOFs that
            // K couples too, so the sum keeps the pattern (and the reused symbolic analysis).
            k *= 1.0 + alpha_;
            if (consistent_) {
                k += c0 * mass_free_;
            }
            for (std::size_t d = 0; d < eq.size() && !consistent_; ++d) {
                if (eq[d] >= 0) {
                    k.coeffRef(eq[d], eq[d]) += c0 * mass_(static_cast<Eigen::Index>(d));
                }
            }
            solver_.factorize(k, analysis_->tangent_symmetric());
            factorized_step_ = dt;
        }
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
