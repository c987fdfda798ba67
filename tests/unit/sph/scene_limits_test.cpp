// The impact warning of sph/scene_limits.hpp: rho v^2 of the fastest particle against the
// contact stiffness (the gravity-strain refusals are end-to-end bad cases in tests/data); bodies
// and sources inside walls; sinks holding whole bodies at the start.
#include "io/case_table.hpp"
#include "particles/particles_case_reader.hpp"
#include "sph/rigid_wall.hpp"
#include "sph/scene_limits.hpp"
#include "sph/sph_case_reader.hpp"
#include "support/case_refusal.hpp"

#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

// 2000 kg/m^3 at 50 m/s is rho v^2 = 5e6 Pa: warned against a 1 MPa contact, with the stiffness
// that would stop it, and silent against 10 MPa; wall particles (which the walls' drivers move)
// never count.
TEST(SceneLimits, ImpactFasterThanTheContactCanStopIsWarned) {
    ParticleSet p;
    p.add(Vec3::Zero(), Vec3(0.0, 0.0, -50.0), 1.0, 2000.0, 0, 0, 0);
    p.add(Vec3(0.0, 0.0, 0.01), Vec3(0.0, 0.0, -1.0), 1.0, 2000.0, 0, 0, 0);
    p.add_wall_particle(Vec3(0.0, 0.0, -0.01), Vec3(0.0, 0.0, 500.0), 1.0, 2000.0, 1, 0);
    const std::vector<std::string> names{"sand", "floor"};
    const std::string warning = impact_warning(p, names, 1e6);
    EXPECT_NE(warning.find("body \"sand\" starts at 50 m/s: rho v^2 = 5e+06 Pa"), std::string::npos)
        << warning;
    EXPECT_NE(warning.find("at least 5e+06 Pa"), std::string::npos) << warning;
    EXPECT_EQ(impact_warning(p, names, 1e7), "");
    EXPECT_EQ(impact_warning(p, names, 0.0), ""); // no contact potential, nothing to pass
}

using grainload::testing::refusal;

// A 2D floor of three layers at 10 mm (y = -5, -15, -25 mm, x = 0 .. 100 mm) under a body of
// 10 mm particles. The body's rows at y = 5 mm (flush with the floor's face: its particles 10 mm
// from the first layer, their cells touching the wall particles' cells) pass; drawn 20 mm lower,
// its rows at y = -15 and -5 mm lie on the layers: 2 rows x 11 columns inside. A source whose
// sites reach 30 mm into the floor is refused at its min, a site at the centre of a lattice cell
// of the layers (7.07 mm from four wall particles, inside the bound 0.9 x 10 mm) too.
TEST(SceneLimits, BodiesAndSourcesInsideAWallAreRefusedAtTheirKeys) {
    const auto document = io::CaseDocument::from_string(R"([sph]
[[sph.body]]
name = "fill"
[sph.body.shape]
type = "box"
min = "0 0 mm"
[[sph.source]]
name = "top"
min = "0 0 mm"
)",
                                                        "scene.toml");
    const ScenePlaces places = read_scene_places(document->root());
    auto scene = [](double lowest_row, const std::vector<Vec3>& sites) {
        ParticleSet p;
        for (int row = 0; row < 4; ++row) {
            for (int column = 0; column <= 10; ++column) {
                p.add(Vec3(10e-3 * column, lowest_row + 10e-3 * row, 0.0), Vec3::Zero(), 1.0,
                      1500.0, 0, 0, 0);
            }
        }
        std::vector<Wall> walls;
        walls.push_back(add_wall(p, "floor", 0, 1,
                                 plane_wall_points(Vec3::Zero(), Vec3(0.1, 0.0, 0.0), Vec3::Zero(),
                                                   Vec3::UnitY(), 10e-3, 3, 2),
                                 10e-3, 1.0, 2));
        SourceSet::Source source;
        source.name = "top";
        source.sites = sites;
        std::vector<SourceSet::Source> list{source};
        return std::make_tuple(std::move(p), std::move(walls), SourceSet(list, 10e-3));
    };
    const std::vector<std::string> names{"fill"};
    auto check = [&](double lowest_row, const std::vector<Vec3>& sites) {
        const auto [p, walls, sources] = scene(lowest_row, sites);
        return refusal(
            [&] { check_wall_overlaps(places, p, walls, sources, names, 10e-3, 2, 26e-3); });
    };
    EXPECT_EQ(check(5e-3, {Vec3(0.05, 0.2, 0.0)}), "");
    const std::string body = check(-15e-3, {Vec3(0.05, 0.2, 0.0)});
    EXPECT_NE(body.find("scene.toml:6:7: key 'sph.body[0].shape.min': body \"fill\" overlaps "
                        "wall \"floor\": 22 of its 44 particles lie inside"),
              std::string::npos)
        << body;
    const std::string deep = check(5e-3, {Vec3(0.05, 0.2, 0.0), Vec3(0.05, -0.025, 0.0)});
    EXPECT_NE(deep.find("scene.toml:9:7: key 'sph.source[0].min': source \"top\" overlaps wall "
                        "\"floor\": 1 of its 2 sites"),
              std::string::npos)
        << deep;
    const std::string centre = check(5e-3, {Vec3(0.055, -0.01, 0.0)});
    EXPECT_NE(centre.find("source \"top\" overlaps wall \"floor\""), std::string::npos) << centre;
}

// Two bodies of 3 particles above y = 0; a plane sink takes y < 0.5 m (its normal points into
// the scene by mistake). When it holds the lower body alone, the upper one remains: a warning at
// the sink's normal. When the sink takes y < 2 m, it holds both and nothing would be left after
// the first step: refused there. A source of the held body with a site outside the sink keeps
// the scene going: neither.
TEST(SceneLimits, ASinkHoldingEveryBodyAtTheStartIsRefused) {
    auto run = [](double plane, bool fed) {
        const std::string text = "[sph]\n[[sph.sink]]\nname = \"drain\"\ntype = \"plane\"\n"
                                 "point = \"0 " +
                                 std::to_string(plane) + " 0 m\"\nnormal = \"0 -1 0\"\n";
        const auto document = io::CaseDocument::from_string(text, "sinks.toml");
        const io::CaseTable sph = document->root().table("sph");
        const ScenePlaces places = read_scene_places(document->root());
        const std::vector<std::string> names{"low", "high"};
        ParticleSet p;
        for (int k = 0; k < 3; ++k) {
            p.add(Vec3(0.1 * k, 0.25, 0.0), Vec3::Zero(), 1.0, 1500.0, 0, 0, 0);
            p.add(Vec3(0.1 * k, 1.5, 0.0), Vec3::Zero(), 1.0, 1500.0, 1, 0, 0);
        }
        const particles::SinkSet sinks =
            particles::read_sinks(sph, {"[[sph.body]]", names}, 3, 9.81);
        std::vector<SourceSet::Source> list;
        if (fed) {
            SourceSet::Source source;
            source.name = "refill";
            source.body = 0;
            source.sites = {Vec3(0.0, 2.5, 0.0)};
            list.push_back(source);
        }
        std::vector<std::string> warnings;
        const std::string error = refusal([&] {
            warnings = check_sinks_hold_bodies(places, p, sinks, SourceSet(list, 0.1), names);
        });
        return std::make_pair(error, warnings);
    };
    const auto [none, quiet] = run(0.1, false);
    EXPECT_EQ(none, "");
    EXPECT_TRUE(quiet.empty());
    const auto [kept, warned] = run(0.5, false);
    EXPECT_EQ(kept, "");
    ASSERT_EQ(warned.size(), 1u);
    EXPECT_EQ(warned[0], "sinks.toml:6:10: key 'sph.sink[0].normal': sink \"drain\" holds all 3 "
                         "particles of body \"low\" at t = 0, so they leave in the first step");
    const auto [refused, unsaid] = run(2.0, false);
    EXPECT_NE(refused.find("sinks.toml:6:10: key 'sph.sink[0].normal': sink \"drain\" holds all 3 "
                           "particles of body \"low\" at t = 0, so they leave in the first step "
                           "and the run has nothing left to do"),
              std::string::npos)
        << refused;
    const auto [fed, fed_warnings] = run(2.0, true);
    EXPECT_EQ(fed, "");
    ASSERT_EQ(fed_warnings.size(), 1u); // the upper body still leaves whole
    EXPECT_NE(fed_warnings[0].find("body \"high\""), std::string::npos) << fed_warnings[0];
}

} // namespace
} // namespace grainload::sph
