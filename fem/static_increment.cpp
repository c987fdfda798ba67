#include "fem/static_increment.hpp"

namespace grainload::fem {

namespace {

/// The in-balance test's fraction of the total force when the force criterion is switched
/// off: far below any useful eps_F, and above the round-off of a balanced step's residual.
constexpr double kBalanceFractionWithoutForceCriterion = 1e-10;

} // namespace

StaticIncrement::StaticIncrement(StaticSystem& analysis, double from, double to,
                                 const NewtonSettings& settings)
    : analysis_(analysis), equation_(analysis.equation_numbers()),
      force_tolerance_(settings.force_tolerance > 0.0 ? settings.force_tolerance
                                                      : kBalanceFractionWithoutForceCriterion),
      prescribed_increment_(analysis.prescribed_at(to) - analysis.prescribed_at(from)) {
    analysis.set_assembly_load_factor(to);
    applied_ = analysis.applied_forces(to);
    applied_norm_ = free_part(equation_, analysis.free_dof_count(), applied_).norm();
}

Eigen::VectorXd StaticIncrement::residual(int iteration, SparseSolver::Matrix* tangent) {
    analysis_.assemble(tangent, internal_, iteration == 0 ? &prescribed_increment_ : nullptr,
                       &coupling_);
    const Index free = analysis_.free_dof_count();
    Eigen::VectorXd residual = free_part(equation_, free, applied_ - internal_);
    if (iteration == 0) {
        residual -= free_part(equation_, free, coupling_);
    }
    return residual;
}

bool StaticIncrement::in_balance(const Eigen::VectorXd& residual) const {
    // Out of balance within the force tolerance of the total force (e.g. a step in which no
    // load changes, leaving the last solve's round-off; or one in which only the lagged
    // coupling load moved a little): the ratios of eqs. 5.2.8-5.2.9 would measure noise
    // against noise and might never be met.
    const double internal_norm = free_part(equation_, analysis_.free_dof_count(), internal_).norm();
    return residual.norm() <= force_tolerance_ * (applied_norm_ + internal_norm);
}

void StaticIncrement::factorize(SparseSolver::Matrix& tangent, SparseSolver& solver) const {
    solver.factorize(tangent, analysis_.tangent_symmetric());
}

void StaticIncrement::correct(int iteration, const Eigen::VectorXd& step) {
    Eigen::VectorXd full =
        iteration == 0 ? prescribed_increment_ : Eigen::VectorXd::Zero(analysis_.dofs().size());
    scatter_free(equation_, step, full);
    analysis_.update_state(full);
}

void StaticIncrement::settle() {
    analysis_.update_state(prescribed_increment_);
}

double StaticIncrement::displacement_norm() const {
    return analysis_.dofs().norm();
}

bool StaticIncrement::constant_tangent() const {
    return analysis_.constant_tangent();
}

bool StaticIncrement::first_iteration_needs_tangent() const {
    // A stored stiffness gives K_fp dU_p without assembling the tangent.
    return !prescribed_increment_.isZero(0.0) && !analysis_.uses_stored_stiffness();
}

} // namespace grainload::fem
