#include "io/scene_settings.hpp"

#include "io/case_table.hpp"

#include <sstream>
#include <string>

namespace grainload::io {

namespace {

std::string interval_message(double end_time) {
    std::ostringstream message;
    message.precision(3);
    message << "expected at most 1e6 output intervals up to end_time (a frame and a checkpoint "
               "are written at each): an interval of at least "
            << end_time / kMostOutputIntervals << " s";
    return message.str();
}

} // namespace

SceneSettings read_scene_settings(CaseDocument& document, const std::string& file_stem) {
    const CaseTable settings = document.root().table("case");
    SceneSettings scene;
    scene.name = settings.string_or("name", file_stem);
    const auto spatial = settings.integer_or(
        "dimension", static_cast<std::int64_t>(io::default_value(kCaseKeys, "dimension")));
    if (spatial != 2 && spatial != 3) {
        settings.fail("dimension", "expected 2 (plane strain) or 3");
    }
    scene.dimension = static_cast<int>(spatial);
    document.spatial_dimension = scene.dimension;
    scene.end_time = settings.positive_quantity("end_time", dimension::kTime);
    scene.output_interval =
        settings.positive_quantity_or("output_interval", dimension::kTime, scene.end_time / 20.0);
    if (!(scene.end_time / scene.output_interval <= kMostOutputIntervals)) {
        settings.fail("output_interval", interval_message(scene.end_time));
    }
    Vec3 gravity = Vec3::Zero();
    gravity[scene.up_axis()] = -kDefaultGravity;
    scene.gravity = settings.vector_or("gravity", dimension::kAcceleration, gravity);
    return scene;
}

} // namespace grainload::io
