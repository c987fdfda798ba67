#include "app/scene.hpp"

#include "app/notices.hpp"
#include "app/resources/memory_guard.hpp"
#include "coupling/coupled_model.hpp"
#include "coupling/coupling_case_reader.hpp"
#include "coupling/dem_coupled_model.hpp"
#include "dem/dem_model.hpp"
#include "fem/shell_model_reader.hpp"
#include "io/deck_ledger.hpp"
#include "materials/material_case_reader.hpp"
#include "sph/sph_model_reader.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <utility>

namespace grainload::app {

namespace dim = io::dimension;

namespace {

/// A [dem] scene's grains touch its own walls and the coupled shells: SPH in the same file, or
/// shells with no [coupling], would be passed through unseen.
void refuse_beside_dem(const io::CaseTable& root) {
    if (!root.has("dem")) {
        return;
    }
    if (root.has("sph")) {
        root.fail("sph", "a [dem] scene's grains touch only its [[dem.wall]] walls and coupled "
                         "shells: expected no [sph] beside [dem]");
    }
    if (root.has("fem") && !root.has("coupling")) {
        root.fail("fem", "a [dem] scene's grains touch a shell through a [coupling] with its "
                         "[[coupling.interface]]: expected [coupling] beside [dem] and [fem]");
    }
}

} // namespace

std::unique_ptr<Scene> Scene::load(const std::string& file,
                                   const std::vector<std::string>& overrides) {
    auto document = io::CaseDocument::from_file(file);
    for (const auto& assignment : overrides) {
        document->set(assignment);
    }
    return from_document(std::move(document), std::filesystem::path(file).stem().string(),
                         available_memory());
}

std::unique_ptr<Scene> Scene::from_document(std::unique_ptr<io::CaseDocument> document,
                                            const std::string& name, std::optional<double> memory) {
    auto scene = std::make_unique<Scene>();
    scene->document = std::move(document);
    // A refused case still says what its readers warned about before the refusal.
    try {
        scene->settings = io::read_scene_settings(*scene->document, name);
        const io::CaseTable root = scene->document->root();
        scene->materials = materials::read_material_library(root);
        const std::optional<double> spare_particles =
            refuse_oversized_scene(root, scene->settings.dimension, scene->materials, memory);
        refuse_beside_dem(root);
        if (root.has("coupling") && root.has("dem")) {
            scene->add(coupling::read_dem_coupled_model(root, scene->settings, scene->materials));
        } else if (root.has("coupling")) {
            scene->add(coupling::read_coupled_model(root, scene->settings, scene->materials,
                                                    spare_particles));
        } else if (root.has("sph")) {
            scene->add(sph::read_sph_model(root, scene->settings, scene->materials));
        }
        if (root.has("dem") && !root.has("coupling")) {
            scene->add(std::make_unique<dem::DemModel>(
                dem::read_dem_settings(root, scene->materials, scene->settings), scene->settings,
                scene->materials));
        }
        if (root.has("fem") && !root.has("coupling")) {
            scene->add(fem::read_shell_model(root, scene->settings, scene->materials));
        }
        if (root.has("phase") && !root.has("sph") && !root.has("dem")) {
            root.fail("phase", "phases act on a particle scene's walls, sources and sinks: "
                               "expected an [sph] or a [dem] table");
        }
        if (scene->steppers.empty()) {
            root.fail("", "expected at least one physics module: an [sph] table with [[sph.body]], "
                          "a [dem] table with [[dem.body]] or an [fem] table with [[fem.shell]]");
        }
        // The readers' warnings in the order they came, then what no reader took of the decks.
        print_notices(scene->document->take_notices());
        // Once every reader has had its decks: what none of them took, once per deck.
        for (const std::string& warning : root.deck_ledger().warnings()) {
            std::cerr << "grainload: warning: " << warning << '\n';
        }
        // The figures at t = 0 name every figure the run reports, so a misspelt reference is
        // refused before the run, not after it.
        std::vector<io::ResultFigure> figures;
        for (const io::Reporter* reporter : scene->reporters) {
            reporter->append_results(0.0, figures);
        }
        scene->references = io::read_figure_references(root);
        io::check_figure_references(scene->references, figures);
        scene->document->reject_unknown_keys();
        return scene;
    } catch (...) {
        print_notices(scene->document->take_notices());
        throw;
    }
    return scene;
}

namespace {

/// Body particles of an SPH model: wall particles are the boundary, not material.
Index material_particles(const sph::SphModel& model) {
    const std::vector<int>& wall = model.particles().wall_id;
    return std::count_if(wall.begin(), wall.end(), [](int w) { return w < 0; });
}

} // namespace

long long Scene::inner_steps() const {
    long long sum = 0;
    for (const auto& stepper : steppers) {
        sum += stepper->inner_steps();
    }
    return sum;
}

Index Scene::material_point_count() const {
    // io::Stepper counts all its points; the SPH models' are looked into here. A shell's nodes
    // are not material particles: in a coupled scene they would count once per SPH sub-step
    // (a rigid wagon body's nodes were 94 % of such a rate), and they have a rate of their own.
    Index count = 0;
    for (const auto& stepper : steppers) {
        if (const auto* model = dynamic_cast<const sph::SphModel*>(stepper.get())) {
            count += material_particles(*model);
        } else if (const auto* coupled =
                       dynamic_cast<const coupling::CoupledModel*>(stepper.get())) {
            count += material_particles(coupled->sph());
        } else if (const auto* dem = dynamic_cast<const dem::DemModel*>(stepper.get())) {
            count += dem->point_count();
        } else if (const auto* grains =
                       dynamic_cast<const coupling::DemCoupledModel*>(stepper.get())) {
            count += grains->dem().point_count();
        }
    }
    return count;
}

Index Scene::shell_node_count() const {
    Index count = 0;
    for (const auto& stepper : steppers) {
        if (const auto* shell = dynamic_cast<const fem::ShellModel*>(stepper.get())) {
            count += shell->point_count();
        } else if (const auto* coupled =
                       dynamic_cast<const coupling::CoupledModel*>(stepper.get())) {
            count += coupled->fem().point_count();
        } else if (const auto* grains =
                       dynamic_cast<const coupling::DemCoupledModel*>(stepper.get())) {
            count += grains->fem().point_count();
        }
    }
    return count;
}

Index Scene::point_count() const {
    Index count = 0;
    for (const auto& stepper : steppers) {
        count += stepper->point_count();
    }
    return count;
}

} // namespace grainload::app
