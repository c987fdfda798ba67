// The impact warning of sph/scene_limits.hpp: rho v^2 of the fastest particle against the
// contact stiffness (the gravity-strain refusals are end-to-end bad cases in tests/data).
#include "sph/scene_limits.hpp"

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

} // namespace
} // namespace grainload::sph
