#pragma once
// Basic numeric types shared by every module, and the conventions they carry.

#include <Eigen/Core>
#include <cstdint>

// Conventions (stated once, used everywhere; see docs/theory.md "Conventions"):
// - SI units inside the code; case files carry explicit units.
// - Stress is tension positive. Models written compression positive in their sources (the
//   generalized cap) convert at their own entry point.
// - Voigt order is xx, yy, zz, xy, yz, zx. Stress vectors hold tensor components; strain
//   vectors hold engineering shear strains (gamma_xy = 2 eps_xy) so that sigma = D eps.
namespace grainload {

using Real = double;
using Index = std::int64_t;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Voigt6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

} // namespace grainload
