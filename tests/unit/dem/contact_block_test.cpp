// The frames' contacts block (`contact_forces = true`): one line per contact, between the two
// centres (a wall's to its contact point), carrying the force the contact pass applied.

#include "support/dem_scene.hpp"

#include <gtest/gtest.h>

namespace {

using namespace grainload;
using grainload::testing::dem_model;
using grainload::testing::glass;
using grainload::testing::step_until;

// Forty beads settling in a box for 0.5 s (friction, damping, Hertz): the block's lines are
// the pass's contacts, counted as the books count them; a pair's line joins two centres
// r_a + r_b - overlap apart and presses them apart (normal force >= 0 less the pull of a
// dashpot that parts them); the lines drawn to the walls carry, summed, the walls' own
// loads with the sign turned (the same forces in another order: 1e-12 of the total).
TEST(ContactBlock, DrawsEveryContactWithThePassesForce) {
    auto model = dem_model(
        "[case]\nend_time = \"1 s\"\n" + glass() +
        "[dem]\ncontact_forces = true\n[dem.contact]\nlaw = \"hertz_mindlin\"\n"
        "gamma_n = \"200 1/s\"\ngamma_t = \"50 1/s\"\nfriction = 0.5\n"
        "[[dem.body]]\nname = \"beads\"\nmaterial = \"glass\"\nradius_min = \"4 mm\"\n"
        "radius_max = \"5 mm\"\ncount = 40\nmin = \"0 0 0 m\"\nmax = \"0.05 0.05 0.1 m\"\n"
        "[[dem.wall]]\nname = \"box\"\ntype = \"box\"\nmin = \"0 0 0 m\"\nmax = \"0.05 0.05 "
        "0.2 m\"\n");
    step_until(*model, 0.0, 0.5, [](double) {});
    io::Frame frame;
    model->append_blocks(frame);
    ASSERT_EQ(frame.blocks.size(), 2u);
    const io::Block& lines = frame.blocks[1];
    ASSERT_EQ(lines.name, "contacts");
    ASSERT_EQ(lines.kind, io::Block::Kind::lines);
    const auto field = [&lines](const std::string& name) {
        for (const io::FieldArray& array : lines.cell_arrays) {
            if (array.name == name) {
                return array.values;
            }
        }
        ADD_FAILURE() << name << " missing";
        return std::vector<double>{};
    };
    const auto force = field("force");
    const auto overlap = field("overlap");
    const auto wall = field("wall");
    const auto normal = field("normal_force");
    ASSERT_EQ(lines.points.size(), 2 * lines.cells.size());
    Index pairs = 0;
    Vec3 on_walls = Vec3::Zero();
    double largest = 0.0;
    for (std::size_t c = 0; c < lines.cells.size(); ++c) {
        const Vec3& from = lines.points[2 * c];
        const Vec3& to = lines.points[2 * c + 1];
        const Vec3 f(force[3 * c], force[3 * c + 1], force[3 * c + 2]);
        largest = std::max(largest, f.norm());
        EXPECT_GT(overlap[c], 0.0) << "line " << c;
        if (wall[c] == 0.0) {
            ++pairs;
            EXPECT_GE((from - to).norm(), 2 * 0.004 - overlap[c] - 1e-12);
            EXPECT_LE((from - to).norm(), 2 * 0.005 - overlap[c] + 1e-12);
        } else {
            on_walls += f;
        }
    }
    EXPECT_EQ(pairs, model->books().pair_contacts);
    EXPECT_EQ(static_cast<Index>(lines.cells.size()) - pairs, model->books().wall_contacts);
    EXPECT_GT(pairs, 20) << "the beads must have settled onto each other";
    EXPECT_LT((on_walls + model->walls()[0].force).norm(), 1e-12 * on_walls.norm());
    EXPECT_GT(largest, 0.0);
    for (const double f : normal) {
        EXPECT_GT(f, -0.1 * largest);
    }
}

} // namespace
