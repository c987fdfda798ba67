#include "particles/mass_audit.hpp"
#include "particles/sink.hpp"
#include "sph/particle_removal.hpp"

#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

/// Five body particles with 2 or 3 state values each (two materials sharing the state array),
/// then a wall of three particles with normals and angular velocities, then a second wall of
/// two: every field of particle i holds a value made from i, so a moved particle is seen.
struct Scene {
    ParticleSet particles;
    std::vector<Wall> walls;
};

Scene make_scene() {
    Scene scene;
    ParticleSet& p = scene.particles;
    for (int i = 0; i < 5; ++i) {
        const int state_size = i % 2 == 0 ? 2 : 3;
        // Masses are binary fractions, so the audit's sums are exact in any order.
        p.add(Vec3(i, 0, 0), Vec3(0, i, 0), 0.25 * (i + 1), 1000.0 + i, 0, i % 2, state_size);
        p.internal_energy.back() = 10.0 * i;
        p.stress.back().setConstant(-i);
        p.plastic_strain.back() = 0.01 * i;
        p.clamped.back() = i == 3 ? 1 : 0;
        for (int k = 0; k < state_size; ++k) {
            p.state[static_cast<std::size_t>(p.state_offset.back() + k)] = 100.0 * i + k;
        }
    }
    for (int w = 0; w < 2; ++w) {
        std::vector<Vec3> points;
        for (int k = 0; k < 3 - w; ++k) {
            points.emplace_back(k, 5.0 + w, 0.0);
        }
        Wall wall = add_wall(p, w == 0 ? "floor" : "gate", w, 1 + w, points, 0.5, 1.0, 3);
        for (int k = 0; k < 3 - w; ++k) {
            wall.normals.emplace_back(0, 0, k + 1);
            wall.angular_velocities.emplace_back(k + 1, 0, 0);
        }
        scene.walls.push_back(std::move(wall));
    }
    return scene;
}

// Removing body particles 1 and 4 and the floor's middle particle keeps every field of the
// others in order, each kept particle's state block (of its own length) with its offset, and
// both walls' ranges and per-particle arrays; the mass removed plus the mass kept is the mass
// before, exactly.
TEST(ParticleRemoval, CompactsEveryFieldTheStateAndTheWallRanges) {
    Scene scene = make_scene();
    const ParticleSet before = scene.particles;
    //                        bodies 0-4     floor 5-7  gate 8-9
    const std::vector<char> gone{0, 1, 0, 0, 1, 0, 1, 0, 0, 0};
    const auto new_index = remove_particles(scene.particles, gone, scene.walls);
    const ParticleSet& p = scene.particles;
    ASSERT_EQ(p.size(), 7);
    const std::vector<Index> expected_map{0, -1, 1, 2, -1, 3, -1, 4, 5, 6};
    EXPECT_EQ(new_index, expected_map);
    for (std::size_t old = 0; old < gone.size(); ++old) {
        const Index i = new_index[old];
        if (i < 0) {
            continue;
        }
        EXPECT_EQ(p.position[i], before.position[old]) << old;
        EXPECT_EQ(p.velocity[i], before.velocity[old]) << old;
        EXPECT_EQ(p.mass[i], before.mass[old]) << old;
        EXPECT_EQ(p.density[i], before.density[old]) << old;
        EXPECT_EQ(p.internal_energy[i], before.internal_energy[old]) << old;
        EXPECT_EQ(p.stress[i], before.stress[old]) << old;
        EXPECT_EQ(p.plastic_strain[i], before.plastic_strain[old]) << old;
        EXPECT_EQ(p.body_id[i], before.body_id[old]) << old;
        EXPECT_EQ(p.material_id[i], before.material_id[old]) << old;
        EXPECT_EQ(p.wall_id[i], before.wall_id[old]) << old;
        EXPECT_EQ(p.clamped[i], before.clamped[old]) << old;
        // The state block: as long as before and holding the same values.
        const auto end = [](const ParticleSet& set, std::size_t k) {
            return k + 1 < set.state_offset.size() ? set.state_offset[k + 1]
                                                   : static_cast<Index>(set.state.size());
        };
        const Index length = end(before, old) - before.state_offset[old];
        ASSERT_EQ(end(p, static_cast<std::size_t>(i)) - p.state_offset[i], length) << old;
        for (Index k = 0; k < length; ++k) {
            EXPECT_EQ(p.state[static_cast<std::size_t>(p.state_offset[i] + k)],
                      before.state[static_cast<std::size_t>(before.state_offset[old] + k)]);
        }
    }
    EXPECT_EQ(p.state.size(), 2u + 3u + 2u) << "bodies 0, 2 (2 values) and 3 (3 values)";
    EXPECT_EQ(scene.walls[0].first, 3);
    EXPECT_EQ(scene.walls[0].count, 2);
    EXPECT_EQ(scene.walls[0].normals, (std::vector<Vec3>{Vec3(0, 0, 1), Vec3(0, 0, 3)}));
    EXPECT_EQ(scene.walls[0].angular_velocities, (std::vector<Vec3>{Vec3(1, 0, 0), Vec3(3, 0, 0)}));
    EXPECT_EQ(scene.walls[1].first, 5);
    EXPECT_EQ(scene.walls[1].count, 2);
    for (const Wall& wall : scene.walls) {
        for (Index k = wall.first; k < wall.first + wall.count; ++k) {
            EXPECT_EQ(p.wall_id[k], &wall - scene.walls.data()) << wall.name << " " << k;
        }
    }
    double kept = 0.0;
    double removed = 0.0;
    for (std::size_t old = 0; old < gone.size(); ++old) {
        (gone[old] ? removed : kept) +=
            before.is_wall(static_cast<Index>(old)) ? 0.0 : before.mass[old];
    }
    double now = 0.0;
    for (Index i = 0; i < p.size(); ++i) {
        now += p.is_wall(i) ? 0.0 : p.mass[i];
    }
    EXPECT_EQ(now, kept);
    EXPECT_EQ(now + removed, 0.25 * (1 + 2 + 3 + 4 + 5));
}

// A wall whose particles all go keeps its place in the list with count 0 (its name, body id
// and friction pairs stay valid) and the wall after it moves down.
TEST(ParticleRemoval, AWallRemovedWholeKeepsItsPlaceWithNoParticles) {
    Scene scene = make_scene();
    const std::vector<char> gone{0, 0, 0, 0, 0, 1, 1, 1, 0, 0};
    remove_particles(scene.particles, gone, scene.walls);
    EXPECT_EQ(scene.walls[0].count, 0);
    EXPECT_EQ(scene.walls[0].first, 5);
    EXPECT_TRUE(scene.walls[0].normals.empty());
    EXPECT_EQ(scene.walls[1].first, 5);
    EXPECT_EQ(scene.walls[1].count, 2);
    EXPECT_EQ(scene.particles.wall_id[5], 1);
}

// A sink takes the material particles in its region and books their mass, the first sink in
// case order taking a particle two sinks hold; wall particles never leave through a sink, and
// a sink for one body leaves the others. The audit closes exactly (binary-fraction masses).
TEST(SinkSet, TakesMaterialParticlesInItsRegionAndBooksTheirMass) {
    Scene scene = make_scene();
    scene.particles.body_id[4] = 7;
    std::vector<particles::SinkSet::Sink> sinks(3);
    sinks[0] = {"right", io::Region::half_space(Vec3(2.5, 0, 0), Vec3(1, 0, 0), 3), -1, 0.0,
                std::nullopt};
    sinks[1] = {"box", io::Region::box(Vec3(-1, -1, -1), Vec3(3.5, 10, 1), 3), 0, 0.0,
                std::nullopt};
    sinks[2] = {"unused", io::Region::half_space(Vec3(0, -100, 0), Vec3(0, -1, 0), 3), -1, 0.0,
                std::nullopt};
    particles::SinkSet set(std::move(sinks), 3);
    std::vector<char> gone(static_cast<std::size_t>(scene.particles.size()), 0);
    // x = 3 and 4 are beyond x = 2.5 ("right" first); 0, 1, 2 in the box (body 0 only); the
    // walls at z = 0 lie in both regions and stay.
    EXPECT_EQ(set.collect_departures(scene.particles.view(), 0.0, gone), 5);
    EXPECT_EQ(set.sinks()[0].discharged, 0.25 * (4 + 5));
    EXPECT_EQ(set.sinks()[1].discharged, 0.25 * (1 + 2 + 3));
    EXPECT_EQ(set.sinks()[2].discharged, 0.0);
    for (Index i = 5; i < scene.particles.size(); ++i) {
        EXPECT_EQ(gone[static_cast<std::size_t>(i)], 0) << "wall particle " << i;
    }
    remove_particles(scene.particles, gone, scene.walls);
    const double initial = 0.25 * 15;
    const auto audit = [&set, initial](double in_scene, double created) {
        return particles::MassAudit::error(in_scene, set.discharged(), initial, created);
    };
    EXPECT_EQ(audit(0.0, 0.0), 0.0);
    EXPECT_EQ(audit(0.25, 0.0), 0.25 / 3.75);
    // 0.5 created: the scene holds it too when the audit closes.
    EXPECT_EQ(audit(0.5, 0.5), 0.0);
    EXPECT_EQ(audit(0.25, 0.5), -0.25 / 4.25);
}

// Half-space: strictly beyond the plane (a particle on it stays); box: faces included; in plane
// strain only x and y are tested.
TEST(Region, HalfSpaceAndBoxMembership) {
    const auto below = io::Region::half_space(Vec3(0, -0.2, 0), Vec3(0, -2, 0), 2);
    EXPECT_TRUE(below.contains(Vec3(5, -0.2001, 0)));
    EXPECT_FALSE(below.contains(Vec3(5, -0.2, 0)));
    EXPECT_FALSE(below.contains(Vec3(-5, 0.1, 0)));
    EXPECT_DOUBLE_EQ(below.normal.norm(), 1.0);
    const auto slanted = io::Region::half_space(Vec3(1, 1, 1), Vec3(1, 1, 1), 3);
    EXPECT_TRUE(slanted.contains(Vec3(2, 1, 1)));
    EXPECT_FALSE(slanted.contains(Vec3(0, 1, 1.5)));
    const auto box = io::Region::box(Vec3(0, 0, 0), Vec3(1, 2, 3), 3);
    EXPECT_TRUE(box.contains(Vec3(1, 2, 3)));
    EXPECT_TRUE(box.contains(Vec3(0.5, 1, 1.5)));
    EXPECT_FALSE(box.contains(Vec3(0.5, 1, 3.0001)));
    const auto flat = io::Region::box(Vec3(0, 0, 0), Vec3(1, 1, 0), 2);
    EXPECT_TRUE(flat.contains(Vec3(0.5, 0.5, 7)));
    EXPECT_THROW(io::Region::box(Vec3(0, 0, 0), Vec3(1, 0, 1), 3), std::invalid_argument);
    EXPECT_THROW(io::Region::half_space(Vec3::Zero(), Vec3::Zero(), 3), std::invalid_argument);
}

} // namespace
} // namespace grainload::sph
