#include "materials/linear_elastic.hpp"

namespace grainload::materials {

std::unique_ptr<LinearElastic> LinearElastic::from_case(const io::CaseTable& table) {
    return std::make_unique<LinearElastic>(ElasticConstants::from_case(table));
}

PlasticRegion LinearElastic::update(const Voigt6& strain_increment, Voigt6& stress,
                                    std::span<double>, Matrix6* tangent) const {
    const Matrix6 d = elastic_.stiffness();
    stress += d * strain_increment;
    if (tangent != nullptr) {
        *tangent = d;
    }
    return PlasticRegion::elastic;
}

} // namespace grainload::materials
