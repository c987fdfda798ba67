#include "fem/newton_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace grainload::fem {

namespace {

/// The norm ratios of thesis eqs. 5.2.7-5.2.9 after iteration `iteration` (its correction
/// `step`, the new residual, and the first iteration's residual and energy).
NewtonIteration ratios(int iteration, const Eigen::VectorXd& step, const Eigen::VectorXd& residual,
                       const Eigen::VectorXd& residual0, double energy0, double displacement_norm) {
    // The 1e-300 floors keep a zero denominator (a first residual or state of exactly zero)
    // from dividing by zero; any real norm is far above them.
    NewtonIteration it;
    it.iteration = iteration;
    it.displacement_ratio = step.norm() / std::max(displacement_norm, 1e-300);
    it.force_ratio = residual.norm() / std::max(residual0.norm(), 1e-300);
    it.energy_ratio = std::abs(step.dot(residual)) / std::max(energy0, 1e-300);
    it.residual_norm = residual.norm();
    return it;
}

bool converged(const NewtonIteration& it, const NewtonSettings& settings) {
    const auto met = [](double ratio, double tolerance) {
        return tolerance <= 0.0 || ratio <= tolerance;
    };
    return met(it.displacement_ratio, settings.displacement_tolerance) &&
           met(it.force_ratio, settings.force_tolerance) &&
           met(it.energy_ratio, settings.energy_tolerance);
}

} // namespace

void record_worst_dof(const std::vector<Index>& equation_numbers, const Eigen::VectorXd& residual,
                      StepReport& report) {
    report.worst_dof = -1;
    report.worst_residual = 0.0;
    for (std::size_t d = 0; d < equation_numbers.size(); ++d) {
        const Index row = equation_numbers[d];
        if (row < 0) {
            continue;
        }
        const double r = residual(row);
        const bool worse = !std::isfinite(r) ? std::isfinite(report.worst_residual)
                                             : std::abs(r) > std::abs(report.worst_residual);
        if (report.worst_dof < 0 || worse) {
            report.worst_dof = static_cast<Index>(d);
            report.worst_residual = r;
        }
    }
}

std::string dof_name(Index dof) {
    static constexpr std::array<const char*, 6> kComponents{"ux", "uy", "uz", "rx", "ry", "rz"};
    return "node " + std::to_string(dof / 6) + " " + kComponents[static_cast<std::size_t>(dof % 6)];
}

Eigen::VectorXd free_part(const std::vector<Index>& equation_numbers, Index free_count,
                          const Eigen::VectorXd& full) {
    Eigen::VectorXd out(free_count);
    for (std::size_t d = 0; d < equation_numbers.size(); ++d) {
        if (equation_numbers[d] >= 0) {
            out(equation_numbers[d]) = full(static_cast<Eigen::Index>(d));
        }
    }
    return out;
}

void scatter_free(const std::vector<Index>& equation_numbers, const Eigen::VectorXd& free,
                  Eigen::VectorXd& full) {
    for (std::size_t d = 0; d < equation_numbers.size(); ++d) {
        if (equation_numbers[d] >= 0) {
            full(static_cast<Eigen::Index>(d)) = free(equation_numbers[d]);
        }
    }
}

bool NewtonSolver::holds_factorization(const NewtonOperator& op) const {
    return kept_ && op.constant_tangent() && kept_key_ == op.tangent_key() &&
           solver_.method() != SparseSolver::Method::none;
}

bool NewtonSolver::solve(NewtonOperator& op, const NewtonSettings& settings,
                         std::vector<NewtonIteration>& log, StepReport& report) {
    // Only a factorisation that solved its problem to convergence is kept for the next ones:
    // a singular tangent's is not.
    try {
        const bool converged = iterate(op, settings, log, report);
        kept_ = kept_ && converged;
        return converged;
    } catch (...) {
        kept_ = false;
        throw;
    }
}

bool NewtonSolver::iterate(NewtonOperator& op, const NewtonSettings& settings,
                           std::vector<NewtonIteration>& log, StepReport& report) {
    // A kept factorisation solves every iteration, so the element loop need only form the
    // internal forces (the tangent's formation and assembly were most of a coupled window's
    // shell cost), unless the first iteration needs K_fp.
    const bool assemble = !holds_factorization(op) || op.first_iteration_needs_tangent();
    SparseSolver::Matrix k;
    Eigen::VectorXd residual0;
    Eigen::VectorXd step;
    double energy0 = 0.0;
    for (int i = 0;; ++i) {
        const Eigen::VectorXd residual = op.residual(i, assemble ? &k : nullptr);
        if (!residual.allFinite()) {
            record_worst_dof(op.equation_numbers(), residual, report);
            return false;
        }
        if (i == 0) {
            residual0 = residual;
            if (op.in_balance(residual0)) {
                op.settle();
                return true;
            }
        } else {
            log.push_back(ratios(i, step, residual, residual0, energy0, op.displacement_norm()));
            if (converged(log.back(), settings) || op.in_balance(residual)) {
                return true;
            }
        }
        if (i == settings.max_iterations) {
            record_worst_dof(op.equation_numbers(), residual, report);
            return false;
        }
        // A constant tangent's factorisation, once made, solves every later iteration and
        // solve exactly (the coupling's many short windows would otherwise refactorise the
        // same matrix every window); a failed factorisation leaves none to reuse.
        if (!holds_factorization(op)) {
            kept_ = false;
            op.factorize(k, solver_);
            ++report.factorisations;
            // UMFPACK's solve reads the factorised matrix again (iterative refinement): it
            // lives on in factorized_, at the same addresses (swap moves no entries).
            factorized_.swap(k);
            kept_ = op.constant_tangent();
            kept_key_ = op.tangent_key();
        }
        report.solver = SparseSolver::name(solver_.method());
        step = solver_.solve(residual);
        ++report.back_substitutions;
        if (i == 0) {
            energy0 = std::abs(step.dot(residual0));
        }
        op.correct(i, step);
    }
}

} // namespace grainload::fem
