#pragma once
// A case file turned into models: the [case] settings, the materials, one stepper per module.

#include "io/case_table.hpp"
#include "io/figure_reference.hpp"
#include "io/reporter.hpp"
#include "io/scene_settings.hpp"
#include "io/stepper.hpp"
#include "materials/material_library.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace grainload::app {

/// A case file turned into models: the [case] settings, the materials, and one stepper per
/// physics module present ([sph], [fem]). Loading validates everything, unknown keys included,
/// so `grainload check` and `grainload run` refuse exactly the same files.
struct Scene {
    std::unique_ptr<io::CaseDocument> document;
    io::SceneSettings settings;
    materials::MaterialLibrary materials;
    /// The physics modules as the time loop steps them, in the order they step.
    std::vector<std::unique_ptr<io::Stepper>> steppers;
    /// The same modules as the output reads them (each steppers[k] is reporters[k]).
    std::vector<io::Reporter*> reporters;
    /// [[case.reference]]: the independent references the case states for its figures.
    std::vector<io::FigureReference> references;

    /// Throws io::CaseError on any bad input.
    static std::unique_ptr<Scene> load(const std::string& file,
                                       const std::vector<std::string>& overrides);
    /// load() after the file is read and the overrides applied: `name` is the case's default
    /// name (load(): the file's stem); a scene whose SPH particles would need more than
    /// `memory` bytes is refused before any is made (load(): available_memory(); the fuzz
    /// harness gives a small budget, so that it builds only small scenes).
    static std::unique_ptr<Scene> from_document(std::unique_ptr<io::CaseDocument> document,
                                                const std::string& name,
                                                std::optional<double> memory);
    Index point_count() const;
    /// The SPH body particles (point_count() less the wall particles and the shell nodes):
    /// what particle-steps per second count.
    Index material_point_count() const;
    /// The shells' nodes, coupled or alone: what shell node-steps per second count.
    Index shell_node_count() const;
    /// The steppers' inner steps so far (io::Stepper::inner_steps).
    long long inner_steps() const;

    /// Append a module that both steps and reports, in both lists.
    template <class Module> void add(std::unique_ptr<Module> module) {
        reporters.push_back(module.get());
        steppers.push_back(std::move(module));
    }
};

} // namespace grainload::app
