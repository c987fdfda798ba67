#pragma once
// Physical dimensions as integer exponents of mass, length, time and plane angle.

#include <string>

namespace grainload::io {

/// Physical dimension as integer exponents of mass, length, time and plane angle. Angle is kept
/// as its own base dimension so that "35 mm" is refused where a friction angle is expected.
struct Dimension {
    int mass = 0;
    int length = 0;
    int time = 0;
    int angle = 0;

    friend constexpr bool operator==(const Dimension&, const Dimension&) = default;
    constexpr Dimension operator*(const Dimension& o) const {
        return {mass + o.mass, length + o.length, time + o.time, angle + o.angle};
    }
    constexpr Dimension power(int p) const { return {mass * p, length * p, time * p, angle * p}; }
};

namespace dimension {
inline constexpr Dimension kNone{};
inline constexpr Dimension kMass{1, 0, 0, 0};
inline constexpr Dimension kLength{0, 1, 0, 0};
inline constexpr Dimension kTime{0, 0, 1, 0};
inline constexpr Dimension kAngle{0, 0, 0, 1};
inline constexpr Dimension kArea{0, 2, 0, 0};
inline constexpr Dimension kVelocity{0, 1, -1, 0};
inline constexpr Dimension kAcceleration{0, 1, -2, 0};
inline constexpr Dimension kAngularVelocity{0, 0, -1, 1};
inline constexpr Dimension kFrequency{0, 0, -1, 0};
inline constexpr Dimension kDensity{1, -3, 0, 0};
inline constexpr Dimension kForce{1, 1, -2, 0};
inline constexpr Dimension kPressure{1, -1, -2, 0};
inline constexpr Dimension kInversePressure{-1, 1, 2, 0};
inline constexpr Dimension kEnergy{1, 2, -2, 0};
inline constexpr Dimension kForcePerLength{1, 0, -2, 0};
inline constexpr Dimension kMoment{1, 2, -2, 0};
} // namespace dimension

/// Human description used in error messages: "a pressure (e.g. \"30.62 GPa\")".
std::string describe(const Dimension& d);

} // namespace grainload::io
