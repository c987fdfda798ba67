#include "sph/source.hpp"

#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

// The lattice of a 0.4 x 0.1 box at 0.1 spacing in plane strain: 4 x 1 sites, half a spacing
// in from the faces, z = 0.
TEST(SourceSet, LatticeIsHalfASpacingInFromTheFaces) {
    const auto box = io::Region::box(Vec3(0, 1, 5), Vec3(0.4, 1.1, 9), 2);
    const auto sites = SourceSet::lattice(box, 0.1, 2);
    ASSERT_EQ(sites.size(), 4u);
    for (std::size_t k = 0; k < sites.size(); ++k) {
        EXPECT_NEAR(sites[k].x(), 0.05 + 0.1 * static_cast<double>(k), 1e-15);
        EXPECT_NEAR(sites[k].y(), 1.05, 1e-15);
        EXPECT_EQ(sites[k].z(), 0.0);
    }
}

SourceSet::Source line_source(double rate) {
    SourceSet::Source s;
    s.name = "top";
    s.region = io::Region::box(Vec3(0, 0, 0), Vec3(0.4, 0.1, 0), 2);
    s.sites = SourceSet::lattice(s.region, 0.1, 2);
    s.particle_mass = 0.5; // binary fraction: the books below are exact
    s.mass_rate = rate;
    s.start = 1.0;
    s.end = 2.0;
    s.velocity = Vec3(0, -1, 0);
    return s;
}

// Mass rate 2 kg/s, particles of 0.5 kg: a step of 0.5 s that starts before `start` owes only
// its part inside [start, end) (0.25 s, 0.5 kg: one particle); the next 0.5 s owes 1 kg, two
// particles, taken round-robin after the first site; a site with a particle nearer than
// kMinimumGap spacings is skipped; nothing is owed after `end`.
TEST(SourceSet, CreatesWholeParticlesAtTheRateOnFreeSitesOnly) {
    std::vector<SourceSet::Source> list{line_source(2.0)};
    SourceSet set(std::move(list), 0.1);
    ParticleSet p;
    p.add(Vec3(0.15, 0.05 + 0.09, 0), Vec3::Zero(), 1.0, 1.0, 0, 0, 0); // 0.09 above site 1
    auto a = set.collect(p.view(), 0.75, 0.5);
    ASSERT_EQ(a.size(), 1u);
    EXPECT_EQ(a[0].position, Vec3(0.05, 0.05, 0));
    EXPECT_EQ(a[0].velocity, Vec3(0, -1, 0));
    EXPECT_EQ(a[0].mass, 0.5) << "an arrival is whole: the source's particle mass";
    a = set.collect(p.view(), 1.25, 0.5);
    ASSERT_EQ(a.size(), 2u);
    EXPECT_NEAR(a[0].position.x(), 0.25, 1e-15) << "site 1 is blocked, site 2 next";
    EXPECT_NEAR(a[1].position.x(), 0.35, 1e-15);
    EXPECT_EQ(set.created(), 1.5);
    EXPECT_EQ(set.collect(p.view(), 2.0, 0.5).size(), 0u);
    EXPECT_EQ(set.created(), 1.5);
}

// A checkpoint's state restores what is owed, created and where the round-robin stands.
TEST(SourceSet, StateRoundTrips) {
    std::vector<SourceSet::Source> list{line_source(3.0)};
    SourceSet set(std::move(list), 0.1);
    ParticleSet p;
    set.collect(p.view(), 1.0, 0.3);
    SourceSet copy(std::vector<SourceSet::Source>{line_source(3.0)}, 0.1);
    copy.set_state(set.state());
    EXPECT_EQ(copy.created(), set.created());
    EXPECT_EQ(copy.collect(p.view(), 1.3, 0.3).front().position,
              set.collect(p.view(), 1.3, 0.3).front().position);
    EXPECT_THROW(copy.set_state({1.0}), std::runtime_error);
}

} // namespace
} // namespace grainload::sph
