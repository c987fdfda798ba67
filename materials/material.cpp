#include "materials/material.hpp"

#include <algorithm>

namespace grainload::materials {

void Material::initialise_state(std::span<double> state) const {
    std::fill(state.begin(), state.end(), 0.0);
}

PlasticRegion Material::update_over(const Voigt6& strain_increment, double, Voigt6& stress,
                                    std::span<double> state, Matrix6* tangent) const {
    return update(strain_increment, stress, state, tangent);
}

void Material::update_points(std::span<const Voigt6> strain_increments, double time_step,
                             std::span<Voigt6> stresses, std::span<double* const> states,
                             std::span<PlasticRegion> regions) const {
    const auto size = static_cast<std::size_t>(state_size());
    for (std::size_t k = 0; k < stresses.size(); ++k) {
        regions[k] =
            update_over(strain_increments[k], time_step, stresses[k], {states[k], size}, nullptr);
    }
}

double Material::equivalent_plastic_strain(std::span<const double>) const {
    return 0.0;
}

} // namespace grainload::materials
