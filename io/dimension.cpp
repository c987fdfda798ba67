#include "io/dimension.hpp"

#include <array>
#include <sstream>

namespace grainload::io {

namespace {

struct NamedDimension {
    Dimension dimension;
    const char* name;
    const char* example;
};

constexpr std::array kNamedDimensions{
    NamedDimension{dimension::kNone, "a plain number", "0.3"},
    NamedDimension{dimension::kMass, "a mass", "2.5 kg"},
    NamedDimension{dimension::kLength, "a length", "72 mm"},
    NamedDimension{dimension::kTime, "a time", "1.5 s"},
    NamedDimension{dimension::kAngle, "an angle", "35 deg"},
    NamedDimension{dimension::kArea, "an area", "1.2 m^2"},
    NamedDimension{dimension::kVelocity, "a velocity", "10 m/s"},
    NamedDimension{dimension::kAcceleration, "an acceleration", "9.81 m/s^2"},
    NamedDimension{dimension::kAngularVelocity, "an angular velocity", "10 deg/s"},
    NamedDimension{dimension::kFrequency, "a frequency", "50 Hz"},
    NamedDimension{dimension::kDensity, "a density", "2099 kg/m^3"},
    NamedDimension{dimension::kForce, "a force", "1.5 kN"},
    NamedDimension{dimension::kPressure, "a pressure or stress", "30.62 GPa"},
    NamedDimension{dimension::kInversePressure, "an inverse pressure", "9.0 1/MPa"},
    NamedDimension{dimension::kEnergy, "an energy or moment", "2 J"},
    NamedDimension{dimension::kForcePerLength, "a force per length", "3 N/m"},
};

} // namespace

std::string describe(const Dimension& d) {
    for (const auto& named : kNamedDimensions) {
        if (named.dimension == d) {
            return std::string(named.name) + " (e.g. \"" + named.example + "\")";
        }
    }
    std::ostringstream out;
    out << "a quantity of dimension kg^" << d.mass << " m^" << d.length << " s^" << d.time
        << " rad^" << d.angle;
    return out.str();
}

} // namespace grainload::io
