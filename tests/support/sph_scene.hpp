#pragma once
// An SPH model built from a case text as the CLI builds it.

#include "io/case_table.hpp"
#include "io/scene_settings.hpp"
#include "materials/material_case_reader.hpp"
#include "materials/material_library.hpp"
#include "sph/sph_model_reader.hpp"

#include <filesystem>
#include <memory>
#include <string>

namespace grainload::testing {

/// An SPH model built from a case text as the CLI builds it from a case file, with what it was
/// built from: the model points to the materials, so the scene is neither copied nor moved.
struct SphScene {
    /// `file` names the document (its meshes are found beside it); its stem is the case name.
    SphScene(const std::string& text, const std::string& file)
        : document(io::CaseDocument::from_string(text, file)),
          settings(io::read_scene_settings(*document, std::filesystem::path(file).stem())),
          materials(materials::read_material_library(document->root())),
          model(sph::read_sph_model(document->root(), settings, materials)) {}
    SphScene(const SphScene&) = delete;
    SphScene& operator=(const SphScene&) = delete;

    std::unique_ptr<io::CaseDocument> document;
    io::SceneSettings settings;
    materials::MaterialLibrary materials;
    std::unique_ptr<sph::SphModel> model;
};

} // namespace grainload::testing
