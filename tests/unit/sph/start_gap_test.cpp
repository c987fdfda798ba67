// The start gap of sph/start_gap.hpp: the contact energy a body's particles or a source's sites
// store with the walls at t = 0, and the refusal and warning that compare it with the weight.
#include "io/case_table.hpp"
#include "sph/rigid_wall.hpp"
#include "sph/sph_case_reader.hpp"
#include "sph/start_gap.hpp"
#include "support/case_refusal.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

// Plane strain, spacing s = 10 mm, cubic spline with h = 13 mm (support 2h = 26 mm): a point of
// volume s^2 at (0, 20) mm above two wall particles of volume s^2 at (0, 0) and (10, 0) mm. By
// hand, with alpha = 15 / (7 pi h^2) = 4036.05 m^-2 and thesis eq. (5.3.12) integrated,
// U = K V_i V_j W(dp) u^n / n with u = W(r) / W(dp):
//   r1 = 20 mm, q = 1.53846: W = alpha (2 - q)^3 / 6 = 66.1347 m^-2;
//   r2 = 22.3607 mm, q = 1.72005: W = 14.7583 m^-2; W(dp): q = 0.76923, W = 1221.04 m^-2;
//   n = 1: U = K V^2 (W1 + W2) = 5e6 x 1e-8 x 80.8930 = 4.04465 J/m;
//   n = 2: U = K V^2 W(dp) (u1^2 + u2^2) / 2 = 0.0940099 J/m.
// The gap is the nearer particle's 20 mm, and the wall pushes the point up (+y) and away from
// the second particle (-x). Tolerance 1e-5 relative: the hand values carry six digits.
TEST(StartGap, ContactEnergyAndGapMatchTheHandComputedPair) {
    ParticleSet p;
    std::vector<Wall> walls(1);
    walls[0].name = "floor";
    walls[0].body_id = 1;
    walls[0].first = 0;
    walls[0].count = 2;
    p.add_wall_particle(Vec3::Zero(), Vec3::Zero(), 0.1, 1000.0, 1, 0);
    p.add_wall_particle(Vec3(0.01, 0.0, 0.0), Vec3::Zero(), 0.1, 1000.0, 1, 0);
    const SmoothingKernel kernel(KernelType::cubic_spline, 0.013, 2);
    const WallParticleIndex index(p, walls, kernel.support_radius(), 2);
    ContactPotential potential;
    potential.stiffness = 5e6;
    const std::vector<Vec3> point{Vec3(0.0, 0.02, 0.0)};
    const StartContact one = index.contact(point, 1e-4, 0, kernel, potential, 0.01);
    EXPECT_NEAR(one.energy, 4.04465, 1e-5 * 4.04465);
    EXPECT_NEAR(one.walls[0].energy, one.energy, 1e-12);
    EXPECT_NEAR(one.walls[0].gap, 0.02, 1e-12);
    EXPECT_GT(one.walls[0].force.y(), 0.0);
    EXPECT_LT(one.walls[0].force.x(), 0.0);
    EXPECT_EQ(one.main_wall(), 0);
    potential.exponent = 2.0;
    EXPECT_NEAR(index.contact(point, 1e-4, 0, kernel, potential, 0.01).energy, 0.0940099,
                1e-5 * 0.0940099);
    // 2h away from both, the pair stores nothing: no wall is in reach.
    const StartContact clear =
        index.contact({Vec3(0.0, 0.026, 0.0)}, 1e-4, 0, kernel, potential, 0.01);
    EXPECT_EQ(clear.energy, 0.0);
    EXPECT_EQ(clear.main_wall(), -1);
    // A wall that acts on another body only is not there for this one.
    walls[0].bodies = {3};
    EXPECT_EQ(index.contact(point, 1e-4, 0, kernel, potential, 0.01).energy, 0.0);
}

using grainload::testing::refusal;

// A 2D floor of three layers at 10 mm (y = -5, -15, -25 mm, x = 0 .. 100 mm) under a block of
// 11 x 4 particles of sand (1500 kg/m^3) at 10 mm, columns over the wall particles, K = 5 MPa,
// n = 1, g = 9.81 m/s^2: M g s = 44 x 0.15 kg/m x 9.81 x 0.01 m = 0.64746 J/m. The energies are
// from an independent sum over the same pairs (a Python loop over the 44 x 33 pairs with the
// kernel written out):
// - lowest row at 21 mm, gap 26 mm = 2h: nothing stored, nothing said;
// - at 18 mm, gap 23 mm: E0 = 4.78527 J/m, 7.39 M g s: a warning at the body's min; the block
//   stores M g s when moved up 1.43 mm, to a gap of 24.4 mm (bisection of the same sum);
// - at 5 mm, gap 10 mm (the rows flush with the floor's face): 1297.6 J/m, 2004 M g s: refused
//   there, expecting the same 24.4 mm, a move of 14.4 mm;
// - without gravity there is no weight to judge against: nothing;
// - a source whose one site is 10 mm over the floor's first layer (with the particle under it
//   alone its particle stores K V^2 W(10 mm) = 61 J/m, against M g s = 0.0147 J/m): refused at
//   the source's min.
TEST(StartGap, ABodyOrSourceThrownOffByTheWallIsRefusedOrWarnedAtItsKey) {
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
                                                        "gap.toml");
    const ScenePlaces places = read_scene_places(document->root());
    const std::vector<std::string> names{"fill"};
    const SmoothingKernel kernel(KernelType::cubic_spline, 0.013, 2);
    ContactPotential potential;
    potential.stiffness = 5e6;
    auto check = [&](double lowest_row, double gravity, const std::vector<Vec3>& sites,
                     std::vector<std::string>& warnings) {
        ParticleSet p;
        for (int row = 0; row < 4; ++row) {
            for (int column = 0; column <= 10; ++column) {
                p.add(Vec3(10e-3 * column, lowest_row + 10e-3 * row, 0.0), Vec3::Zero(), 0.15,
                      1500.0, 0, 0, 0);
            }
        }
        std::vector<Wall> walls;
        walls.push_back(add_wall(p, "floor", 0, 1,
                                 plane_wall_points(Vec3::Zero(), Vec3(0.1, 0.0, 0.0), Vec3::Zero(),
                                                   Vec3::UnitY(), 10e-3, 3, 2),
                                 10e-3, 1500.0, 2));
        std::vector<SourceSet::Source> list;
        if (!sites.empty()) {
            SourceSet::Source source;
            source.name = "top";
            source.sites = sites;
            source.particle_mass = 0.15;
            list.push_back(source);
        }
        return refusal([&] {
            warnings = check_start_gaps(places, p, walls, SourceSet(list, 10e-3), names, kernel,
                                        potential, gravity, 10e-3, 2);
        });
    };
    std::vector<std::string> warnings;
    EXPECT_EQ(check(21e-3, 9.81, {}, warnings), "");
    EXPECT_TRUE(warnings.empty());

    EXPECT_EQ(check(18e-3, 9.81, {}, warnings), "");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("gap.toml:6:7: key 'sph.body[0].shape.min': body \"fill\" starts "
                               "23 mm from the particles of wall \"floor\" (0.885 of the contact "
                               "reach 2h = 26 mm): the contact potential stores 4.79 J/m at t = "
                               "0, 7.39 times its weight times one spacing (M g s = 0.647 J/m)"),
              std::string::npos)
        << warnings[0];
    EXPECT_NE(warnings[0].find("move it 1.43 mm away from the wall, to a gap of 24.4 mm"),
              std::string::npos)
        << warnings[0];

    const std::string flush = check(5e-3, 9.81, {}, warnings);
    EXPECT_NE(flush.find("gap.toml:6:7: key 'sph.body[0].shape.min': body \"fill\" starts 10 mm "
                         "from the particles of wall \"floor\""),
              std::string::npos)
        << flush;
    EXPECT_NE(flush.find("1.3e+03 J/m at t = 0, 2e+03 times its weight"), std::string::npos)
        << flush;
    EXPECT_NE(flush.find("expected a gap of at least 24.4 mm: move it 14.4 mm away"),
              std::string::npos)
        << flush;

    EXPECT_EQ(check(5e-3, 0.0, {}, warnings), "");
    EXPECT_TRUE(warnings.empty());

    const std::string source = check(21e-3, 9.81, {Vec3(0.05, 0.005, 0.0)}, warnings);
    EXPECT_NE(source.find("gap.toml:9:7: key 'sph.source[0].min': source \"top\" starts 10 mm "
                          "from the particles of wall \"floor\""),
              std::string::npos)
        << source;
}

} // namespace
} // namespace grainload::sph
