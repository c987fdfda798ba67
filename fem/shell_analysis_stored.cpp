#include "fem/dof_index.hpp"
#include "fem/shell_analysis.hpp"

#include <array>

// The parts of ShellAnalysis that work from a stored stiffness (store_stiffness()): a linear
// shell's internal force as K u, and its element stresses evaluated only when read.

namespace grainload::fem {

void ShellAnalysis::build_stored_stiffness() {
    StoredStiffness::Triplets material;
    StoredStiffness::Triplets drilling;
    material.reserve(at(576 * mesh_.element_count()));
    drilling.reserve(at(36 * mesh_.element_count()));
    Vector24 force;
    Matrix24 k;
    Matrix24 spring;
    for (std::size_t e = 0; e < elements_.size(); ++e) {
        const ShellElement& element = mesh_.elements()[e];
        // Linear kinematics and a linear elastic material: the element stiffness does not depend
        // on the state, and the trial state this evaluation leaves is dropped again.
        elements_[e].keep_strain_operators();
        elements_[e].evaluate(element_nodes(e), element_dofs(element, dofs_), kinematics_, force,
                              &k, &spring);
        elements_[e].revert();
        std::array<Index, 24> global{};
        for (int a = 0; a < 24; ++a) {
            global[at(a)] = kDofs * element.nodes[at(a / kDofs)] + a % kDofs;
        }
        for (int a = 0; a < 24; ++a) {
            for (int b = 0; b < 24; ++b) {
                material.emplace_back(global[at(a)], global[at(b)], k(a, b));
            }
        }
        // The spring couples only the rotations of one corner.
        for (int corner = 0; corner < 4; ++corner) {
            for (int a = kDofs * corner + 3; a < kDofs * corner + kDofs; ++a) {
                for (int b = kDofs * corner + 3; b < kDofs * corner + kDofs; ++b) {
                    drilling.emplace_back(global[at(a)], global[at(b)], spring(a, b));
                }
            }
        }
    }
    stored_.emplace(dofs_.size(), material, drilling);
}

void ShellAnalysis::assemble_stored(SparseSolver::Matrix* tangent, Eigen::VectorXd& internal,
                                    const Eigen::VectorXd* prescribed, Eigen::VectorXd* coupling) {
    const std::vector<Index>& eq = equation_numbers();
    if (!stored_) {
        build_stored_stiffness();
    }
    // No follower or moment loads here: either would make the tangent state-dependent.
    internal = stored_->internal_force(dofs_);
    if (coupling != nullptr) {
        *coupling = prescribed != nullptr ? stored_->tangent_times(*prescribed)
                                          : Eigen::VectorXd::Zero(internal.size());
    }
    std::vector<Eigen::Triplet<double>> springs;
    add_node_springs(internal, tangent != nullptr ? &springs : nullptr, prescribed, coupling);
    if (tangent != nullptr) {
        *tangent = stored_->free_tangent(eq, free_count_);
        if (!springs.empty()) {
            SparseSolver::Matrix spring_matrix(free_count_, free_count_);
            spring_matrix.setFromTriplets(springs.begin(), springs.end());
            *tangent += spring_matrix;
        }
    }
}

void ShellAnalysis::refresh_stresses() const {
    if (!stresses_stale_) {
        return;
    }
    // Each element from its committed state to the committed DOFs, as the convergence check's
    // element loop would have done in the last increment.
    for (std::size_t e = 0; e < elements_.size(); ++e) {
        elements_[e].update_stresses(element_dofs(mesh_.elements()[e], committed_dofs_));
        elements_[e].commit();
    }
    stresses_stale_ = false;
}

const std::vector<Mitc4Shell>& ShellAnalysis::elements() const {
    refresh_stresses();
    return elements_;
}

} // namespace grainload::fem
