#include "fem/dof_index.hpp"
#include "fem/shell_analysis.hpp"

#include <utility>

// Springs on nodes' translations towards their committed values (ShellAnalysis::NodeSpring):
// the coupling's added mass (coupling/added_mass.hpp).

namespace grainload::fem {

void ShellAnalysis::set_node_springs(std::vector<NodeSpring> springs) {
    node_springs_ = std::move(springs);
}

void ShellAnalysis::add_node_springs(Eigen::VectorXd& internal,
                                     std::vector<Eigen::Triplet<double>>* triplets,
                                     const Eigen::VectorXd* prescribed,
                                     Eigen::VectorXd* coupling) const {
    for (const NodeSpring& spring : node_springs_) {
        const Index first = kDofs * spring.node;
        const Vec3 stretch = dofs_.segment<3>(first) - committed_dofs_.segment<3>(first);
        internal.segment<3>(first) += spring.stiffness * stretch;
        if (prescribed != nullptr && coupling != nullptr) {
            coupling->segment<3>(first) += spring.stiffness * prescribed->segment<3>(first);
        }
        if (triplets == nullptr) {
            continue;
        }
        for (int a = 0; a < 3; ++a) {
            const Index row = equation_[at(first + a)];
            for (int b = 0; b < 3 && row >= 0; ++b) {
                const Index col = equation_[at(first + b)];
                if (col >= 0) {
                    triplets->emplace_back(row, col, spring.stiffness(a, b));
                }
            }
        }
    }
}

} // namespace grainload::fem
