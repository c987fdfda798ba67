#pragma once
// The [[material]] tables of a case, each built once and referred to by name.

#include "materials/material.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace grainload::materials {

/// The [[material]] tables of a case, each built once and referred to by name.
class MaterialLibrary {
  public:
    /// Add a material under `name` (unique), with the grain size it declares (none: a
    /// continuum); materials/material_case_reader.hpp builds the library of a case.
    void add(std::string name, std::unique_ptr<Material> material,
             std::optional<double> grain_size) {
        names_.push_back(std::move(name));
        materials_.push_back(std::move(material));
        grain_sizes_.push_back(grain_size);
    }
    const Material& operator[](int index) const {
        return *materials_[static_cast<std::size_t>(index)];
    }
    const std::string& name(int index) const { return names_[static_cast<std::size_t>(index)]; }
    const std::vector<std::string>& names() const { return names_; }
    /// The material's grain size d (`grain_size`, the mean grain diameter), where it declares
    /// one: Beverloo's discharge law reduces an outlet by k d (particles/sink.hpp).
    std::optional<double> grain_size(int index) const {
        return grain_sizes_[static_cast<std::size_t>(index)];
    }
    int size() const { return static_cast<int>(materials_.size()); }

  private:
    std::vector<std::string> names_;
    std::vector<std::unique_ptr<Material>> materials_;
    std::vector<std::optional<double>> grain_sizes_;
};

} // namespace grainload::materials
