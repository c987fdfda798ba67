#include "materials/linear_elastic.hpp"

namespace grainload::materials {

PlasticRegion LinearElastic::update(const Voigt6& strain_increment, Voigt6& stress,
                                    std::span<double>, Matrix6* tangent) const {
    stress += elastic_.stress_from_strain(strain_increment);
    if (tangent != nullptr) {
        *tangent = elastic_.stiffness();
    }
    return PlasticRegion::elastic;
}

} // namespace grainload::materials
