// Periodic axes ([[sph.periodic]]): a layer flowing down an inclined plane with a period of L
// against the same layer with a period of 2 L. The reference is the longer model itself: a
// motion of period L is one of period 2 L, and each of its particles sees, as real particles
// or as images, the same neighbours at the same places as its partner in the shorter model,
// so the two compute the same sums in another order and must agree to round-off.
#include "io/case_table.hpp"
#include "sph/sph_model.hpp"
#include "support/sph_scene.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <string>

namespace grainload::sph {
namespace {

// The layer of cases/inclined_plane/bagnold_mu_i_small.toml (mu(I) glass beads, 2 mm spacing,
// 25 deg, rough base) with the period `length_mm` and its body and base drawn across it.
std::string layer(int length_mm) {
    const std::string l = std::to_string(length_mm);
    const std::string wall = std::to_string(length_mm - 1);
    return R"(
[case]
dimension = 2
end_time = "1 s"
gravity = "4.14588 -8.89093 m/s^2"
[[material]]
name = "beads"
model = "mu_i"
density = "1470 kg/m^3"
youngs_modulus = "2 MPa"
poisson_ratio = 0.3
angle_s = "20.9 deg"
angle_2 = "32.76 deg"
i0 = 0.279
grain_size = "0.5 mm"
grain_density = "2450 kg/m^3"
[sph]
kernel_gradient_correction = false
[sph.artificial_viscosity]
alpha = 0.1
beta = 0.1
[sph.contact]
stiffness = "2 MPa"
damping_ratio = 0.5
[[sph.periodic]]
axis = "x"
min = "0 mm"
max = ")" + l +
           R"( mm"
[[sph.body]]
name = "layer"
material = "beads"
spacing = "2 mm"
[sph.body.shape]
type = "box"
min = "0 3.7 mm"
max = ")" + l +
           R"( 23.7 mm"
[[sph.wall]]
name = "base"
type = "plane"
spacing = "1 mm"
origin = "0.5 0 mm"
edge_u = ")" +
           wall + R"( 0 mm"
normal = "0 1"
[[sph.friction]]
body = "layer"
wall = "base"
mu_static = 1.0
mu_kinetic = 1.0
)";
}

// 4000 steps of 15 us (0.06 s: the layer has started to shear, 0.045 m/s at its surface, and
// the particles of its upper rows have moved by about a millimetre, those of the last column
// across the seam). The two models sum each particle's neighbours in another order: each step
// differs by round-off, about 1e-16 of each term, which the flow carries on; measured 4e-16 m
// after 4000 steps, allowed 1e-12 m (1e-9 of the spacing).
constexpr double kRoundOff = 1e-12;

TEST(PeriodicRepeat, ALayerOfOnePeriodMovesAsTheSameLayerOfTwo) {
    const testing::SphScene one(layer(20), "periodic_one.toml");
    const testing::SphScene two(layer(40), "periodic_two.toml");
    const ParticleSet& a = one.model->particles();
    const ParticleSet& b = two.model->particles();
    // Partners: the particle of the long model that starts where a particle of the short one
    // does, and the one a period further.
    std::vector<std::pair<Index, Index>> partners;
    std::vector<double> start;
    for (Index i = 0; i < a.size(); ++i) {
        if (a.is_wall(i)) {
            continue;
        }
        for (Index j = 0; j < b.size(); ++j) {
            const Vec3 d = b.position[j] - a.position[i];
            if (!b.is_wall(j) && std::abs(d.y()) < 1e-9 &&
                (std::abs(d.x()) < 1e-9 || std::abs(d.x() - 0.02) < 1e-9)) {
                partners.emplace_back(i, j);
                start.push_back(a.position[i].x());
            }
        }
    }
    ASSERT_EQ(partners.size(), 200U); // 100 particles, two partners each
    const std::array<PeriodicAxis, 1> period{PeriodicAxis{0, 0.0, 0.02}};
    double t = 0.0;
    const double dt = 1.5e-5;
    for (int step = 0; step < 4000; ++step, t += dt) {
        one.model->advance(t, dt);
        two.model->advance(t, dt);
    }
    double gap = 0.0, fastest = 0.0;
    int wrapped = 0; // particles of the short model that crossed its seam and came back at 0
    for (std::size_t k = 0; k < partners.size(); ++k) {
        const auto [i, j] = partners[k];
        gap = std::max(gap, nearest_image(b.position[j] - a.position[i], period).norm());
        fastest = std::max(fastest, a.velocity[i].x());
        wrapped += a.position[i].x() < start[k] - 0.01;
    }
    std::cout << "after 4000 steps: largest position gap " << gap << " m, fastest particle "
              << fastest << " m/s, " << wrapped / 2 << " particles wrapped\n";
    EXPECT_LT(gap, kRoundOff);
    EXPECT_GT(fastest, 0.02); // the layer flows: the comparison is of a shear flow
    EXPECT_GT(wrapped, 0);    // and across the seam
}

} // namespace
} // namespace grainload::sph
