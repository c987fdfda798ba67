#include "fem/stored_stiffness.hpp"

namespace grainload::fem {

StoredStiffness::StoredStiffness(Index dofs, const Triplets& material, const Triplets& drilling)
    : material_(dofs, dofs), drilling_(dofs, dofs) {
    material_.setFromTriplets(material.begin(), material.end());
    drilling_.setFromTriplets(drilling.begin(), drilling.end());
}

Eigen::VectorXd StoredStiffness::internal_force(const Eigen::VectorXd& u) const {
    return material_ * u;
}

Eigen::VectorXd StoredStiffness::tangent_times(const Eigen::VectorXd& v) const {
    return material_ * v + drilling_ * v;
}

SparseSolver::Matrix StoredStiffness::free_tangent(const std::vector<Index>& equation_numbers,
                                                   Index free_count) const {
    Triplets triplets;
    triplets.reserve(static_cast<std::size_t>(material_.nonZeros() + drilling_.nonZeros()));
    for (const RowMatrix* m : {&material_, &drilling_}) {
        for (Eigen::Index row = 0; row < m->outerSize(); ++row) {
            const Index r = equation_numbers[static_cast<std::size_t>(row)];
            for (RowMatrix::InnerIterator it(*m, row); it && r >= 0; ++it) {
                const Index c = equation_numbers[static_cast<std::size_t>(it.col())];
                if (c >= 0) {
                    triplets.emplace_back(r, c, it.value());
                }
            }
        }
    }
    SparseSolver::Matrix k(free_count, free_count);
    k.setFromTriplets(triplets.begin(), triplets.end());
    return k;
}

} // namespace grainload::fem
