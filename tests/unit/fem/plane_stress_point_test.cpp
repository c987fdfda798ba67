#include "fem/plane_stress_point.hpp"
#include "materials/linear_elastic.hpp"

#include <gtest/gtest.h>

namespace grainload::fem {
namespace {

// For an isotropic elastic material the generic reduction must give the textbook plane-stress
// matrix E/(1-nu^2) [[1, nu, 0], [nu, 1, 0], [0, 0, (1-nu)/2]] (Bathe FEP Table 4.3) and k G
// for transverse shear; agreement to round-off.
TEST(PlaneStressPoint, LinearElasticGivesPlaneStressMatrix) {
    const double e = 2.1e11;
    const double nu = 0.3;
    const materials::LinearElastic steel(materials::ElasticConstants::from_young(7850, e, nu));
    MaterialPoint committed;
    MaterialPoint point;
    ShellVector strain;
    strain << 1e-3, -2e-4, 5e-4, 1e-4, -3e-4;
    ShellMatrix tangent;
    const ShellVector stress = plane_stress_update(steel, strain, committed, point, &tangent);
    ShellMatrix expected = ShellMatrix::Zero();
    const double c = e / (1.0 - nu * nu);
    expected.topLeftCorner<2, 2>() << c, c * nu, c * nu, c;
    expected(2, 2) = c * (1.0 - nu) / 2.0;
    expected(3, 3) = expected(4, 4) = kShearCorrection * e / (2.0 * (1.0 + nu));
    EXPECT_LT((tangent - expected).norm(), 1e-12 * expected.norm());
    EXPECT_LT((stress - expected * strain).norm(), 1e-12 * stress.norm());
    EXPECT_NEAR(point.stress(2), 0.0, 1e-12 * stress.norm());
    EXPECT_NEAR(point.strain(2), -nu / (1.0 - nu) * (strain(0) + strain(1)), 1e-15);
}

TEST(PlaneStressPoint, IncrementalUpdateStartsFromCommittedState) {
    const materials::LinearElastic mat(materials::ElasticConstants::from_young(1.0, 1e9, 0.25));
    MaterialPoint committed;
    MaterialPoint half;
    ShellVector strain;
    strain << 1e-3, 2e-3, 0.0, 0.0, 0.0;
    plane_stress_update(mat, 0.5 * strain, committed, half, nullptr);
    MaterialPoint full;
    const ShellVector in_two = plane_stress_update(mat, strain, half, full, nullptr);
    MaterialPoint direct;
    const ShellVector in_one = plane_stress_update(mat, strain, committed, direct, nullptr);
    EXPECT_LT((in_two - in_one).norm(), 1e-12 * in_one.norm());
}

} // namespace
} // namespace grainload::fem
