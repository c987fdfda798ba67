// The triaxial cell's servos against Hertz: a lattice of eight spheres squeezed by six walls
// held at a stress settles where Hertz's law puts the walls for that stress.

#include "support/dem_scene.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace {

using namespace grainload;
using grainload::testing::dem_model;
using grainload::testing::glass;
using grainload::testing::step_until;

constexpr double kRadius = 0.005;
constexpr double kStress = 1000.0;
constexpr double kYoung = 10e6;
constexpr double kPoisson = 0.3;

/// Eight glass spheres of radius 5 mm in a simple cubic lattice, touching each other and the
/// faces of the cell [0, 20 mm]^3, frictionless, damped (restitution 0.3), no gravity; the
/// cell's side walls held at 1 kPa, and its platen too until `shear_start` (the base stays).
std::unique_ptr<dem::DemModel> lattice_in_cell(const std::string& shear_start = "10 s") {
    std::string bodies;
    for (int k = 0; k < 8; ++k) {
        const double x = (k & 1 ? 15.0 : 5.0);
        const double y = (k & 2 ? 15.0 : 5.0);
        const double z = (k & 4 ? 15.0 : 5.0);
        bodies += "[[dem.body]]\nname = \"s" + std::to_string(k) +
                  "\"\nmaterial = \"glass\"\nradius = \"5 mm\"\ncentre = \"" + std::to_string(x) +
                  " " + std::to_string(y) + " " + std::to_string(z) + " mm\"\n";
    }
    return dem_model("[case]\nend_time = \"1 s\"\ngravity = \"0 0 0 m/s^2\"\n" + glass() +
                     "[dem]\n[dem.contact]\nlaw = \"hertz_mindlin\"\nrestitution = 0.3\n" + bodies +
                     "[dem.triaxial]\nmin = \"0 0 0 mm\"\nmax = \"20 20 20 mm\"\n"
                     "confining_stress = \"1 kPa\"\naxial_strain_rate = \"1 1/s\"\n"
                     "shear_start = \"" +
                     shear_start + "\"\n");
}

/// Hertz's overlap of a contact of effective modulus `young` and radius `radius` carrying
/// `force`: F = (4/3) E* sqrt(R*) delta^(3/2) (Johnson 1985, Contact Mechanics, eq. 4.23).
double hertz_overlap(double force, double young, double radius) {
    return std::pow(3.0 * force / (4.0 * young * std::sqrt(radius)), 2.0 / 3.0);
}

/// The cell's side for the stress: each of the four columns of two spheres along an axis
/// carries F = sigma L^2 / 4 through a sphere-sphere contact (E* = E / (2 (1 - nu^2)), R* =
/// R / 2) and two sphere-wall contacts (rigid walls: E* = E / (1 - nu^2), R* = R), so
/// L = 4 R - delta_ss - 2 delta_sw; solved by fixed-point iteration (the overlaps are 1e-3 of
/// L: it converges to round-off in a few passes).
double hertz_side() {
    const double e_wall = kYoung / (1.0 - kPoisson * kPoisson);
    double side = 4.0 * kRadius;
    for (int pass = 0; pass < 50; ++pass) {
        const double force = kStress * side * side / 4.0;
        side = 4.0 * kRadius - hertz_overlap(force, 0.5 * e_wall, 0.5 * kRadius) -
               2.0 * hertz_overlap(force, e_wall, kRadius);
    }
    return side;
}

/// The cell's extent along `axis` where its walls stand now.
double extent(const dem::DemModel& model, int axis) {
    const auto& walls = model.walls();
    const auto low = static_cast<std::size_t>(2 * axis);
    return (walls[low + 1].faces[0].point + walls[low + 1].displacement)[axis] -
           (walls[low].faces[0].point + walls[low].displacement)[axis];
}

// The servos close the cell on the lattice and hold each wall at 1 kPa over its area: at rest
// (0.1 s; the damped lattice settles within 30 ms) the cell's side along each axis is Hertz's,
// 4 R less the overlaps (84 um of 20 mm), measured to 5e-13 of the overlaps, and every wall
// carries 1 kPa. Bounds: 1e-6 of the overlaps and of the stress, a rest reached to round-off
// (the servo's fixed point is the walls' exact equilibrium).
TEST(TriaxialCell, ServosHoldALatticeOfSpheresWhereHertzPutsTheWalls) {
    auto model = lattice_in_cell();
    step_until(*model, 0.0, 0.1, [](double) {});
    const double expected = hertz_side();
    const double overlaps = 4.0 * kRadius - expected;
    for (int axis = 0; axis < 3; ++axis) {
        const double side = extent(*model, axis);
        std::cout << "axis " << axis << ": side off Hertz's by " << (side - expected) / overlaps
                  << " of the overlaps (" << overlaps << " m)\n";
        EXPECT_NEAR(side, expected, 1e-6 * overlaps);
    }
    for (std::size_t k = 0; k < 6; ++k) {
        const dem::PlaneWall& wall = model->walls()[k];
        const int axis = static_cast<int>(k / 2);
        const double area = extent(*model, (axis + 1) % 3) * extent(*model, (axis + 2) % 3);
        std::cout << wall.name << ": " << wall.normal_force / area << " Pa\n";
        EXPECT_NEAR(wall.normal_force / area, kStress, 1e-6 * kStress) << wall.name;
    }
}

// Shearing from 0.1 s, the platen moves towards the base at 1/s times the height it had, and
// the side walls keep their 1 kPa: at 0.101 s the height is 0.1 % less than at 0.1 s (bound
// 1e-9 m: the platen's motion is prescribed), and each side wall stays within 3e-3 of 1 kPa
// while the columns are squeezed by 20 um against their 84 um of overlaps (measured 7.7e-4:
// the grains answer the platen through their dashpots as the walls follow).
TEST(TriaxialCell, ThePlatenShearsAtItsRateWhileTheSidesHoldTheirStress) {
    auto model = lattice_in_cell("0.1 s");
    double t = step_until(*model, 0.0, 0.1, [](double) {});
    const double height = extent(*model, 2);
    double worst = 0.0;
    step_until(*model, t, 0.101, [&](double) {
        for (std::size_t k = 0; k < 4; ++k) {
            const int axis = static_cast<int>(k / 2);
            const double area = extent(*model, (axis + 1) % 3) * extent(*model, 2);
            worst =
                std::max(worst, std::abs(model->walls()[k].normal_force / area / kStress - 1.0));
        }
    });
    std::cout << "height " << height << " -> " << extent(*model, 2)
              << " m; side walls' stress off by at most " << worst << "\n";
    EXPECT_NEAR(extent(*model, 2), 0.999 * height, 1e-9);
    EXPECT_LT(worst, 3e-3);
}

} // namespace
