#include "app/scene.hpp"

#include "fem/shell_model.hpp"
#include "sph/sph_model.hpp"

#include <filesystem>

namespace grainload::app {

namespace dim = io::dimension;

std::unique_ptr<Scene> Scene::load(const std::string& file,
                                   const std::vector<std::string>& overrides) {
    auto scene = std::make_unique<Scene>();
    scene->document = io::CaseDocument::from_file(file);
    for (const auto& assignment : overrides) {
        scene->document->set(assignment);
    }
    const io::CaseTable root = scene->document->root();
    const io::CaseTable settings = root.table("case");
    scene->case_name = settings.string_or("name", std::filesystem::path(file).stem().string());
    const auto dimension = settings.integer_or("dimension", 3);
    if (dimension != 2 && dimension != 3) {
        settings.fail("dimension", "expected 2 (plane strain) or 3");
    }
    scene->dimension = static_cast<int>(dimension);
    scene->document->spatial_dimension = scene->dimension;
    scene->end_time = settings.positive_quantity("end_time", dim::kTime);
    scene->output_interval =
        settings.positive_quantity_or("output_interval", dim::kTime, scene->end_time / 20.0);
    scene->materials = materials::MaterialLibrary::from_case(root);
    if (root.has("sph")) {
        scene->steppers.push_back(sph::SphModel::from_case(root, scene->materials));
    }
    if (root.has("fem")) {
        scene->steppers.push_back(fem::ShellModel::from_case(root, scene->materials));
    }
    if (scene->steppers.empty()) {
        root.fail("", "expected at least one physics module: an [sph] table with [[sph.body]] "
                      "or an [fem] table with [[fem.shell]]");
    }
    scene->document->reject_unknown_keys();
    return scene;
}

Index Scene::point_count() const {
    Index count = 0;
    for (const auto& stepper : steppers) {
        count += stepper->point_count();
    }
    return count;
}

} // namespace grainload::app
