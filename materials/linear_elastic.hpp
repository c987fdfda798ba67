#pragma once
// Isotropic linear elasticity in rate form.

#include "materials/material.hpp"

#include <memory>

namespace grainload::materials {

/// Isotropic linear elasticity in rate form: stress += D : strain_increment.
class LinearElastic final : public Material {
  public:
    explicit LinearElastic(ElasticConstants elastic) : Material(elastic) {}

    std::string_view model() const override { return "linear_elastic"; }
    PlasticRegion update(const Voigt6& strain_increment, Voigt6& stress, std::span<double> state,
                         Matrix6* tangent) const override;
};

} // namespace grainload::materials
