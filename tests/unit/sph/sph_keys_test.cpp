// The declared defaults of [sph] and its solver tables against SphOptions' own.

#include "io/case_table.hpp"
#include "sph/kernels.hpp"
#include "sph/sph_case_reader.hpp"

#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

// A case without the keys gets the declared defaults, and code that builds SphOptions without a
// case file (the tests, the benches) gets the same: the two cannot drift apart. Exact: the
// defaults are the same literals.
TEST(SphKeys, ACaseWithoutTheKeysGetsTheOptionsOwnDefaults) {
    const auto document = io::CaseDocument::from_string(
        "[sph]\n[sph.artificial_viscosity]\n[sph.artificial_stress]\n[sph.contact]\n"
        "stiffness = \"1 MPa\"\n",
        "defaults.toml");
    const SphOptions read =
        read_sph_options(document->root().table("sph"), 3, 0.01, Vec3(0.0, 0.0, -9.81));
    const SphOptions own;
    EXPECT_EQ(read.kernel, own.kernel);
    EXPECT_EQ(kernel_name(read.kernel), io::default_text(kSphKeys, "kernel"));
    EXPECT_EQ(read.smoothing_length_ratio, own.smoothing_length_ratio);
    EXPECT_EQ(read.cfl_safety, own.cfl_safety);
    EXPECT_EQ(read.verlet_skin_factor, own.verlet_skin_factor);
    EXPECT_EQ(read.kernel_gradient_correction, own.kernel_gradient_correction);
    EXPECT_EQ(read.formulation, own.formulation);
    EXPECT_EQ(read.fluidity_interval, own.fluidity_interval);
    EXPECT_EQ(read.viscosity.alpha, own.viscosity.alpha);
    EXPECT_EQ(read.viscosity.beta, own.viscosity.beta);
    EXPECT_EQ(read.viscosity.sound_speed, own.viscosity.sound_speed);
    EXPECT_EQ(read.artificial_stress.epsilon, own.artificial_stress.epsilon);
    EXPECT_EQ(read.artificial_stress.exponent, own.artificial_stress.exponent);
    EXPECT_EQ(read.contact.exponent, own.contact.exponent);
    EXPECT_EQ(read.contact.damping_ratio, own.contact.damping_ratio);
}

} // namespace
} // namespace grainload::sph
