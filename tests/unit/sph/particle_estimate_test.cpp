// The particle estimate (sph/particle_estimate.hpp) against the particles the builders make.

#include "io/case_table.hpp"
#include "materials/material_case_reader.hpp"
#include "sph/particle_estimate_reader.hpp"
#include "sph/sph_model.hpp"
#include "sph/sph_model_reader.hpp"
#include "support/case_refusal.hpp"
#include "support/sph_scene.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>

namespace grainload::sph {
namespace {

// Curved shapes and walls are estimated from their exact volume or area; the lattice counts
// whole cells, and the wall generators put a row on both edges, so at 10 to 20 spacings across
// the counts differ by a few percent (BodyGenerator measures about 1 % for a disc of R/dx = 20,
// and a plane wall's (n + 1)^2 rows against n^2 are 10 % off at n = 20). The estimate only has
// to tell a scene that fits from one that is orders of magnitude too large, and to give a cost
// report its particle count to a few percent: 12 % is the bound, and the ratios are printed.
constexpr double kEstimateTolerance = 0.12;

constexpr const char* kScene = R"(
[case]
name = "estimate"
dimension = 3
end_time = "1 s"

[[material]]
name = "sand"
model = "linear_elastic"
density = "1600 kg/m^3"
youngs_modulus = "10 MPa"
poisson_ratio = 0.3

[sph]
[[sph.body]]
name = "box"
material = "sand"
spacing = "50 mm"
[sph.body.shape]
type = "box"
min = "0 0 0 m"
max = "0.5 0.5 0.52 m"

[[sph.body]]
name = "cylinder"
material = "sand"
spacing = "50 mm"
[sph.body.shape]
type = "cylinder"
base = "2 0 0 m"
axis = "0 0 1"
radius = "0.5 m"
height = "0.5 m"

[[sph.body]]
name = "cone"
material = "sand"
spacing = "50 mm"
[sph.body.shape]
type = "cone"
base = "4 0 0 m"
axis = "1 0 0"
base_radius = "0.5 m"
top_radius = "0.25 m"
height = "1 m"

[[sph.body]]
name = "mesh"
material = "sand"
spacing = "50 mm"
[sph.body.shape]
type = "mesh"
file = "cube_ascii.stl"
offset = "6 0 0 m"

[[sph.wall]]
name = "floor"
type = "plane"
origin = "0 0 -0.2 m"
edge_u = "1 0 0 m"
edge_v = "0 1 0 m"
normal = "0 0 1"

[[sph.wall]]
name = "bin"
type = "box"
min = "10 0 0 m"
max = "11 1 1 m"
spacing = "25 mm"

[[sph.wall]]
name = "mesh_wall"
type = "mesh"
file = "cube_quads.msh"
offset = "13 0 0 m"
layers = 2
)";

struct Built {
    std::vector<double> bodies;
    std::vector<double> walls;
};

/// The particles the model built, per body and per wall.
Built built_counts(const SphModel& model) {
    Built built;
    const auto& p = model.particles();
    for (Index i = 0; i < p.size(); ++i) {
        if (p.is_wall(i)) {
            continue;
        }
        const auto body = static_cast<std::size_t>(p.body_id[i]);
        built.bodies.resize(std::max(built.bodies.size(), body + 1));
        built.bodies[body] += 1.0;
    }
    for (const Wall& wall : model.solver()->walls()) {
        built.walls.push_back(static_cast<double>(wall.count));
    }
    return built;
}

TEST(ParticleEstimate, CountsMatchTheBuiltBodiesAndWalls) {
    const testing::SphScene scene(kScene, std::string(GRAINLOAD_SOURCE_DIR) +
                                              "/tests/data/meshes/estimate.toml");
    const ParticleEstimate estimate =
        estimate_particles(scene.document->root(), 3, scene.materials);
    const Built built = built_counts(*scene.model);
    ASSERT_EQ(estimate.bodies.size(), built.bodies.size());
    ASSERT_EQ(estimate.walls.size(), built.walls.size());
    // The box is 10 x 10 x round(10.4) cells, exactly as fill_box rounds it.
    EXPECT_EQ(estimate.bodies[0].particles, 1000.0);
    EXPECT_EQ(built.bodies[0], 1000.0);
    for (std::size_t b = 0; b < built.bodies.size(); ++b) {
        const double ratio = estimate.bodies[b].particles / built.bodies[b];
        std::cout << estimate.bodies[b].table << " " << estimate.bodies[b].name << ": estimate "
                  << estimate.bodies[b].particles << ", built " << built.bodies[b] << " (ratio "
                  << ratio << ", " << estimate.bodies[b].basis << ")\n";
        EXPECT_NEAR(ratio, 1.0, kEstimateTolerance) << estimate.bodies[b].name;
        EXPECT_EQ(estimate.bodies[b].spacing_key, estimate.bodies[b].table + ".spacing");
    }
    for (std::size_t w = 0; w < built.walls.size(); ++w) {
        const double ratio = estimate.walls[w].particles / built.walls[w];
        std::cout << estimate.walls[w].table << " " << estimate.walls[w].name << ": estimate "
                  << estimate.walls[w].particles << ", built " << built.walls[w] << " (ratio "
                  << ratio << ", " << estimate.walls[w].basis << ")\n";
        EXPECT_NEAR(ratio, 1.0, kEstimateTolerance) << estimate.walls[w].name;
    }
    EXPECT_EQ(estimate.walls[1].spacing_key, "sph.wall[1].spacing");
    EXPECT_TRUE(estimate.walls[0].spacing_key.empty()); // it takes the bodies' spacing
    double total = 0.0;
    for (const auto* list : {&built.bodies, &built.walls}) {
        for (const double n : *list) {
            total += n;
        }
    }
    EXPECT_NEAR(estimate.total() / total, 1.0, kEstimateTolerance);
    EXPECT_EQ(estimate.largest()->name, "bin");
    EXPECT_EQ(estimate.bytes(), estimate.total() * kSolverBytesPerParticle);
}

// The estimate is a few multiplications: a spacing that would make 1e24 particles is counted,
// not generated (the test would run out of memory or time otherwise).
TEST(ParticleEstimate, AHugeSceneIsCountedWithoutBuildingIt) {
    auto document = io::CaseDocument::from_string(kScene, std::string(GRAINLOAD_SOURCE_DIR) +
                                                              "/tests/data/meshes/estimate.toml");
    for (int b = 0; b < 4; ++b) {
        document->set("sph.body[" + std::to_string(b) + "].spacing=\"1e-9 m\"");
    }
    document->set("sph.wall[1].spacing=\"1e-9 m\"");
    const ParticleEstimate estimate =
        estimate_particles(document->root(), 3, materials::read_material_library(document->root()));
    // The box alone: 0.5 x 0.5 x 0.52 m / (1e-9 m)^3 = 1.3e26.
    EXPECT_NEAR(estimate.bodies[0].particles / 1.3e26, 1.0, 1e-9);
    EXPECT_GT(estimate.bytes(), 1e28);
}

// A source's sites are counted like a body's lattice (sph/source.cpp fills its box at the bodies'
// spacing), so a mistyped source box is refused before its sites are made: a 1 km cube at 50 mm
// is (1000 / 0.05)^3 = 8e12 sites, which SourceSet would have tried to allocate (192 TB) before
// the memory guard counted sources. A 0.2 x 0.2 x 0.1 m box is 4 x 4 x 2 = 32 sites.
TEST(ParticleEstimate, SourcesAreCountedByTheirSites) {
    const std::string scene = R"(
[case]
end_time = "1 s"
[[material]]
name = "sand"
model = "linear_elastic"
density = "1600 kg/m^3"
youngs_modulus = "10 MPa"
poisson_ratio = 0.3
[sph]
interactions = false
[[sph.body]]
name = "box"
material = "sand"
spacing = "50 mm"
[sph.body.shape]
type = "box"
min = "0 0 0 m"
max = "0.5 0.5 0.5 m"
[[sph.source]]
name = "small"
body = "box"
min = "0 0 1 m"
max = "0.2 0.2 1.1 m"
mass_rate = "1 kg/s"
[[sph.source]]
name = "huge"
body = "box"
min = "0 0 0 m"
max = "1000 1000 1000 m"
mass_rate = "1 kg/s"
)";
    auto document = io::CaseDocument::from_string(scene, "sources.toml");
    const ParticleEstimate estimate =
        estimate_particles(document->root(), 3, materials::read_material_library(document->root()));
    ASSERT_EQ(estimate.sources.size(), 2u);
    EXPECT_EQ(estimate.sources[0].particles, 32.0);
    EXPECT_EQ(estimate.sources[1].particles, 8e12);
    EXPECT_EQ(estimate.largest()->table, "sph.source[1]");
    EXPECT_EQ(estimate.total(), 1000.0 + 32.0 + 8e12);
}

// The estimate reads walls and shapes through the run's own readers: a wall coarser than the
// bodies (which would let particles through), too many wall layers and a cone with a negative
// top radius are refused by the estimate with the message, file, line and key the run gives.
TEST(ParticleEstimate, RefusesWhatTheRunRefusesWithItsMessage) {
    const std::string file = std::string(GRAINLOAD_SOURCE_DIR) + "/tests/data/meshes/estimate.toml";
    for (const char* change : {"sph.wall[1].spacing=\"0.1 m\"", "sph.wall[2].layers=21",
                               "sph.body[2].shape.top_radius=\"-0.1 m\""}) {
        auto document = io::CaseDocument::from_string(kScene, file);
        document->set(change);
        const io::SceneSettings settings = io::read_scene_settings(*document, "estimate");
        const auto materials = materials::read_material_library(document->root());
        const std::string by_estimate =
            testing::refusal([&] { estimate_particles(document->root(), 3, materials); });
        const std::string by_run =
            testing::refusal([&] { read_sph_model(document->root(), settings, materials); });
        EXPECT_FALSE(by_run.empty()) << change;
        EXPECT_EQ(by_estimate, by_run) << change;
    }
}

} // namespace
} // namespace grainload::sph
