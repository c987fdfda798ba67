#pragma once
// A rigid grain's turning: its orientation turned by a rotation vector, and its angular velocity
// and angular momentum through its principal moments.

#include "io/types.hpp"

#include <Eigen/Geometry>

namespace grainload::dem {

/// omega = R I^-1 R^T L for a grain of principal moments `moments` turned by `turned`.
Vec3 spin_of(const Eigen::Quaterniond& turned, const Vec3& moments, const Vec3& momentum);

/// L = R I R^T omega.
Vec3 momentum_of(const Eigen::Quaterniond& turned, const Vec3& moments, const Vec3& spin);

/// `turned` rotated by the angle |turn| about turn / |turn|: the quaternion (cos(a/2),
/// sin(a/2) turn/|turn|), normalised.
Eigen::Quaterniond rotated(const Eigen::Quaterniond& turned, const Vec3& turn);

} // namespace grainload::dem
