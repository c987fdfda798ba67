#include "coupling/shell_wall.hpp"
#include "fem/shell_mesh_generators.hpp"
#include "materials/linear_elastic.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <numeric>
#include <random>

namespace grainload::coupling {
namespace {

const materials::LinearElastic& steel() {
    static const materials::LinearElastic material(
        materials::ElasticConstants::from_young(7850.0, 210e9, 0.3));
    return material;
}

std::vector<Index> every_element(const fem::ShellAnalysis& analysis) {
    std::vector<Index> elements(static_cast<std::size_t>(analysis.mesh().element_count()));
    std::iota(elements.begin(), elements.end(), 0);
    return elements;
}

/// The wall's particles in an SPH particle set, as the SPH model holds them.
struct WallParticles {
    sph::ParticleSet particles;
    sph::Wall wall;
};

WallParticles particles_of(const ShellWall& shell_wall, double spacing) {
    WallParticles w;
    w.wall = sph::add_wall(w.particles, "plate", 0, 1, shell_wall.points(), spacing, 1.0, 3);
    w.wall.normals = shell_wall.normals();
    return w;
}

/// Random forces on the wall particles (as the force pass leaves them: m a), then the
/// accumulation of one sub-step of length `window` holding them: the impulse F * window.
void apply_forces(ShellWall& shell_wall, WallParticles& w, std::mt19937& generator, double window,
                  std::vector<Vec3>& forces) {
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    forces.clear();
    for (Index k = w.wall.first; k < w.wall.first + w.wall.count; ++k) {
        forces.emplace_back(value(generator), value(generator), value(generator));
        w.particles.acceleration[static_cast<std::size_t>(k)] =
            forces.back() / w.particles.mass[static_cast<std::size_t>(k)];
    }
    shell_wall.accumulate(w.particles, w.wall, 0.0); // the force at the sub-step's start
    shell_wall.accumulate(w.particles, w.wall, window);
}

// A 1 m plate of 4 x 4 elements, 10 mm thick, sand above it (+z): two layers of particles
// at 50 mm, the first half a spacing behind the contact face z = t/2, the second one spacing
// deeper, as a plane wall's layers; normals +z; 21 x 21 particles a layer.
TEST(ShellWall, LayersLieBehindTheContactFace) {
    fem::ShellAnalysis analysis(fem::make_plate(1.0, 1.0, 4, 4, 0.01), steel(),
                                fem::Kinematics::linear, 2);
    const ShellWall wall(analysis, every_element(analysis), {ContactSide::positive, 0.05, 2});
    ASSERT_EQ(wall.points().size(), 2u * 21u * 21u);
    for (std::size_t j = 0; j < wall.points().size(); ++j) {
        const int layer = wall.samples()[j].layer;
        EXPECT_NEAR(wall.points()[j].z(), 0.005 - (layer + 0.5) * 0.05, 1e-15);
        EXPECT_NEAR(wall.samples()[j].offset, 0.005 - (layer + 0.5) * 0.05, 1e-15);
        EXPECT_EQ(wall.normals()[j], Vec3(0.0, 0.0, 1.0));
    }
    const ShellWall below(analysis, every_element(analysis), {ContactSide::negative, 0.05, 1});
    for (std::size_t j = 0; j < below.points().size(); ++j) {
        EXPECT_NEAR(below.points()[j].z(), -0.005 + 0.025, 1e-15);
        EXPECT_EQ(below.normals()[j], Vec3(0.0, 0.0, -1.0));
    }
}

// Forces out are the transpose of kinematics in: for any nodal increment dU (translations and
// rotations) and any particle forces F_j, the work sum_j F_j . dx_j of the particles' motion
// equals the mapped nodal loads' work L . dU. Under linear kinematics x_j is linear in U, so
// the two agree to round-off; the forces also add up to the loads' forces.
TEST(ShellWall, MappedLoadsDoTheParticlesWork) {
    fem::ShellAnalysis analysis(fem::make_plate(1.0, 0.6, 5, 3, 0.02), steel(),
                                fem::Kinematics::linear, 2);
    ShellWall shell_wall(analysis, every_element(analysis), {ContactSide::positive, 0.04, 3});
    WallParticles w = particles_of(shell_wall, 0.04);
    const std::vector<Vec3> start = w.particles.position;
    std::mt19937 generator(7u);
    std::uniform_real_distribution<double> value(-1e-3, 1e-3);
    Eigen::VectorXd increment(analysis.dofs().size());
    for (Eigen::Index d = 0; d < increment.size(); ++d) {
        increment(d) = value(generator);
    }
    analysis.update_state(increment);
    shell_wall.begin_window(analysis, 0.0, 1.0);
    shell_wall.move(w.particles, w.wall, 0.0, 1.0);
    std::vector<Vec3> forces;
    apply_forces(shell_wall, w, generator, 1.0, forces);
    Eigen::VectorXd loads = Eigen::VectorXd::Zero(increment.size());
    shell_wall.add_nodal_loads(analysis, 1.0, loads);
    double particle_work = 0.0;
    double scale = 0.0;
    Vec3 force_sum = Vec3::Zero();
    for (std::size_t j = 0; j < forces.size(); ++j) {
        const Vec3 dx = w.particles.position[static_cast<std::size_t>(w.wall.first) + j] -
                        start[static_cast<std::size_t>(w.wall.first) + j];
        particle_work += forces[j].dot(dx);
        scale += forces[j].norm() * dx.norm();
        force_sum += forces[j];
    }
    EXPECT_NEAR(loads.dot(increment), particle_work, 1e-12 * scale);
    Vec3 load_sum = Vec3::Zero();
    for (Eigen::Index n = 0; n < loads.size(); n += 6) {
        load_sum += loads.segment<3>(n);
    }
    EXPECT_LT((load_sum - force_sum).norm(), 1e-12 * static_cast<double>(forces.size()));
}

// Under large rotations the loads' moment about any point is the particles' moment:
// sum_a (x_a x f_a + m_a) = sum_j x_j x F_j in the current configuration, here a plate turned
// rigidly by 1 rad about an oblique axis (the directors turn with it).
TEST(ShellWall, MappedLoadsKeepTheMomentUnderLargeRotations) {
    fem::ShellAnalysis analysis(fem::make_plate(0.8, 0.8, 4, 4, 0.02), steel(),
                                fem::Kinematics::total_lagrangian, 2);
    ShellWall shell_wall(analysis, every_element(analysis), {ContactSide::negative, 0.05, 2});
    WallParticles w = particles_of(shell_wall, 0.05);
    const Vec3 axis = Vec3(1.0, 2.0, 3.0).normalized();
    const Mat3 r = Eigen::AngleAxisd(1.0, axis).toRotationMatrix();
    const fem::ShellMesh& mesh = analysis.mesh();
    Eigen::VectorXd increment = Eigen::VectorXd::Zero(analysis.dofs().size());
    for (Index n = 0; n < mesh.node_count(); ++n) {
        increment.segment<3>(6 * n) = (r - Mat3::Identity()) * mesh.node(n);
        increment.segment<3>(6 * n + 3) = axis;
    }
    analysis.update_state(increment);
    shell_wall.begin_window(analysis, 0.0, 1.0);
    shell_wall.move(w.particles, w.wall, 0.0, 1.0);
    // The rigidly turned particles are the turned initial ones.
    for (std::size_t j = 0; j < shell_wall.points().size(); ++j) {
        const Vec3& x = w.particles.position[static_cast<std::size_t>(w.wall.first) + j];
        EXPECT_LT((x - r * shell_wall.points()[j]).norm(), 1e-14);
    }
    std::mt19937 generator(3u);
    std::vector<Vec3> forces;
    apply_forces(shell_wall, w, generator, 1.0, forces);
    Eigen::VectorXd loads = Eigen::VectorXd::Zero(increment.size());
    shell_wall.add_nodal_loads(analysis, 1.0, loads);
    Vec3 particle_moment = Vec3::Zero();
    for (std::size_t j = 0; j < forces.size(); ++j) {
        particle_moment +=
            w.particles.position[static_cast<std::size_t>(w.wall.first) + j].cross(forces[j]);
    }
    Vec3 load_moment = Vec3::Zero();
    for (Index n = 0; n < mesh.node_count(); ++n) {
        const Vec3 x = mesh.node(n) + analysis.displacement(n);
        load_moment += x.cross(Vec3(loads.segment<3>(6 * n))) + loads.segment<3>(6 * n + 3);
    }
    EXPECT_LT((load_moment - particle_moment).norm(), 1e-12 * static_cast<double>(forces.size()));
}

// Within a window the particles move at the constant velocity of the linear interpolation in
// time: sub-steps of any length add up to the window's displacement, and v dt is each
// sub-step's displacement.
TEST(ShellWall, SubStepsFollowTheWindowAtConstantVelocity) {
    fem::ShellAnalysis analysis(fem::make_plate(1.0, 1.0, 2, 2, 0.01), steel(),
                                fem::Kinematics::linear, 2);
    ShellWall shell_wall(analysis, every_element(analysis), {ContactSide::positive, 0.1, 2});
    WallParticles w = particles_of(shell_wall, 0.1);
    Eigen::VectorXd increment = Eigen::VectorXd::Zero(analysis.dofs().size());
    for (Index n = 0; n < analysis.mesh().node_count(); ++n) {
        increment(6 * n + 2) = 1e-3 * static_cast<double>(n); // a warped deflection
        increment(6 * n + 3) = 2e-3;
    }
    analysis.update_state(increment);
    shell_wall.begin_window(analysis, 1.0, 1.5);
    const std::vector<Vec3> start = w.particles.position;
    double t = 1.0;
    for (const double dt : {0.1, 0.25, 0.15}) {
        const std::vector<Vec3> before = w.particles.position;
        shell_wall.move(w.particles, w.wall, t, dt);
        t += dt;
        for (Index k = w.wall.first; k < w.wall.first + w.wall.count; ++k) {
            const auto i = static_cast<std::size_t>(k);
            EXPECT_LT((w.particles.position[i] - before[i] - dt * w.particles.velocity[i]).norm(),
                      1e-15);
        }
    }
    // At the window's end the particles are where the shell's current state puts them.
    ShellWall fresh(analysis, every_element(analysis), {ContactSide::positive, 0.1, 2});
    for (std::size_t j = 0; j < fresh.points().size(); ++j) {
        EXPECT_LT(
            (w.particles.position[static_cast<std::size_t>(w.wall.first) + j] - fresh.points()[j])
                .norm(),
            1e-15);
    }
}

} // namespace
} // namespace grainload::coupling
