#include "coupling/added_mass.hpp"
#include "fem/shell_mesh_generators.hpp"

#include <gtest/gtest.h>
#include <numeric>

namespace grainload::coupling {
namespace {

// The added-mass springs of a flat plate (1 m x 0.5 m, 8 x 4 elements, normal +z) under sand of
// areal mass 100 kg/m^2, window 10 ms, beta 2: each node's spring acts along the normal only,
// and the springs add up to beta m_s A / dt^2 = 2 * 100 * 0.5 / 1e-4 = 1e6 N/m over the plate
// (the lumped areas a / 4 per corner sum to the plate's area). Round-off only: 1e-12.
TEST(AddedMass, TheSpringsCarryTheSandsAreaMassAlongTheNormal) {
    const fem::ShellMesh mesh = fem::make_plate(1.0, 0.5, 8, 4, 0.01);
    CoupledPart part;
    part.elements.resize(static_cast<std::size_t>(mesh.element_count()));
    std::iota(part.elements.begin(), part.elements.end(), 0);
    part.side = ContactSide::positive;
    const auto springs = added_mass_springs(mesh, {part}, 100.0, 0.01, 2.0);
    ASSERT_EQ(springs.size(), static_cast<std::size_t>(mesh.node_count()));
    double total = 0.0;
    for (const auto& spring : springs) {
        total += spring.stiffness(2, 2);
        EXPECT_NEAR(spring.stiffness.trace(), spring.stiffness(2, 2), 1e-12 * total + 1e-9);
    }
    EXPECT_NEAR(total / 1e6, 1.0, 1e-12);
    // beta = 0: no springs, the shell as before.
    EXPECT_TRUE(added_mass_springs(mesh, {part}, 100.0, 0.01, 0.0).empty());
}

} // namespace
} // namespace grainload::coupling
