#include "materials/material.hpp"

#include <algorithm>

namespace grainload::materials {

void Material::initialise_state(std::span<double> state) const {
    std::fill(state.begin(), state.end(), 0.0);
}

double Material::equivalent_plastic_strain(std::span<const double>) const {
    return 0.0;
}

} // namespace grainload::materials
