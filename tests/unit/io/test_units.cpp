#include "io/units.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace {

using namespace grainload::io;
namespace dim = grainload::io::dimension;

// Conversions are products of exact decimal factors; 1e-14 relative covers the rounding of
// one or two double multiplications.
constexpr double kRoundOff = 1e-14;

Quantity parsed(const std::string& text) {
    std::string error;
    const auto q = parse_quantity(text, &error);
    EXPECT_TRUE(q.has_value()) << text << ": " << error;
    return q.value_or(Quantity{});
}

void expect_quantity(const std::string& text, double si, Dimension d) {
    const Quantity q = parsed(text);
    EXPECT_NEAR(q.value, si, kRoundOff * std::abs(si)) << text;
    EXPECT_EQ(q.dimension, d) << text;
}

TEST(Units, AcceptsEveryDocumentedForm) {
    expect_quantity("72 mm", 0.072, dim::kLength);
    expect_quantity("72mm", 0.072, dim::kLength);
    expect_quantity("1.5 cm", 0.015, dim::kLength);
    expect_quantity("2 km", 2000.0, dim::kLength);
    expect_quantity("30.62 GPa", 30.62e9, dim::kPressure);
    expect_quantity("1.65e5 MPa", 1.65e11, dim::kPressure);
    expect_quantity("200 kPa", 2e5, dim::kPressure);
    expect_quantity("2 bar", 2e5, dim::kPressure);
    expect_quantity("2099 kg/m^3", 2099.0, dim::kDensity);
    expect_quantity("2.099 g/cm^3", 2099.0, dim::kDensity);
    expect_quantity("2.099 t/m^3", 2099.0, dim::kDensity);
    expect_quantity("10 m/s", 10.0, dim::kVelocity);
    expect_quantity("-9.81 m/s^2", -9.81, dim::kAcceleration);
    expect_quantity("9.81 m*s^-2", 9.81, dim::kAcceleration);
    expect_quantity("1.5 s", 1.5, dim::kTime);
    expect_quantity("20 ms", 0.02, dim::kTime);
    expect_quantity("5 us", 5e-6, dim::kTime);
    expect_quantity("2 min", 120.0, dim::kTime);
    expect_quantity("35 deg", 35.0 * M_PI / 180.0, dim::kAngle);
    expect_quantity("0.5 rad", 0.5, dim::kAngle);
    expect_quantity("90 deg/s", M_PI / 2.0, dim::kAngularVelocity);
    expect_quantity("9.0 1/MPa", 9.0e-6, dim::kInversePressure);
    expect_quantity("9.0 MPa^-1", 9.0e-6, dim::kInversePressure);
    expect_quantity("3 kN", 3000.0, dim::kForce);
    expect_quantity("3 N/m", 3.0, dim::kForcePerLength);
    expect_quantity("4 N*m", 4.0, dim::kMoment);
    expect_quantity("4 N m", 4.0, dim::kMoment);
    expect_quantity("50 Hz", 50.0, dim::kFrequency);
    expect_quantity("0.3", 0.3, dim::kNone);
    expect_quantity("+1e-3 m", 1e-3, dim::kLength);
}

// US customary units, against their definitions (1 in = 0.0254 m, 1 lbf = 0.45359237 kg x
// 9.80665 m/s^2: 1 psi = 6894.757293168361 Pa, NIST SP 811 appendix B), and the stress, mass
// and density units of the consistent unit systems LS-DYNA decks are written in.
TEST(Units, AcceptsUsCustomaryAndLsDynaDeckUnits) {
    const double psi = 6894.757293168361;
    expect_quantity("2 in", 0.0508, dim::kLength);
    expect_quantity("3 ft", 0.9144, dim::kLength);
    expect_quantity("1 lbf", 4.4482216152605, dim::kForce);
    expect_quantity("2 kip", 8896.443230521, dim::kForce);
    expect_quantity("1 lb", 0.45359237, dim::kMass);
    expect_quantity("1 slug", 14.593902937206364, dim::kMass);
    expect_quantity("300 psi", 300.0 * psi, dim::kPressure);
    expect_quantity("1 lbf/in^2", psi, dim::kPressure);
    expect_quantity("0.25 ksi", 250.0 * psi, dim::kPressure);
    expect_quantity("0.67 1/ksi", 0.67 / (1e3 * psi), dim::kInversePressure);
    expect_quantity("2.5e-6 psi^-1", 2.5e-6 / psi, dim::kInversePressure);
    expect_quantity("1 psf", 47.88025898033584, dim::kPressure);
    expect_quantity("1 lbf/ft^2", 47.88025898033584, dim::kPressure);
    // lbf-s-in system: density in lbf s^2 / in^4 (steel 7.33e-4).
    expect_quantity("7.33e-4 lbf*s^2/in^4", 7.33e-4 * 4.4482216152605 / std::pow(0.0254, 4),
                    dim::kDensity);
    // g-cm-us system: stress in Mbar, force in 10 MN.
    expect_quantity("0.0206 Mbar", 2.06e9, dim::kPressure);
    expect_quantity("1 g*cm/us^2", 1e7, dim::kForce);
    expect_quantity("1 kbar", 1e8, dim::kPressure);
    // kg-mm-ms: GPa; t-mm-s: MPa; density of sand in t/mm^3 and kg/mm^3.
    expect_quantity("1 kg*mm/ms^2", 1e3, dim::kForce);
    expect_quantity("2.099e-9 t/mm^3", 2099.0, dim::kDensity);
    expect_quantity("2.099e-6 kg/mm^3", 2099.0, dim::kDensity);
    expect_quantity("1 dyn/cm^2", 0.1, dim::kPressure);
    // "min" is still the minute, "mbar" the millibar.
    expect_quantity("2 min", 120.0, dim::kTime);
    expect_quantity("5 mbar", 500.0, dim::kPressure);
}

TEST(Units, ListsShareOneUnit) {
    std::string error;
    const auto list = parse_quantity_list("0, 0, -9.81 m/s^2", &error);
    ASSERT_TRUE(list) << error;
    ASSERT_EQ(list->size(), 3u);
    EXPECT_EQ((*list)[2].value, -9.81);
    EXPECT_EQ((*list)[0].dimension, dim::kAcceleration);
    const auto spaced = parse_quantity_list("10 20 30 mm", &error);
    ASSERT_TRUE(spaced) << error;
    EXPECT_NEAR((*spaced)[1].value, 0.02, kRoundOff);
}

TEST(Units, RejectsMalformedText) {
    for (const char* bad : {"", "mm", "72 furlongs", "72 mm^", "72 mm^0", "72 m/", "nan m",
                            "inf Pa", "72 cs", "72 cPa", "1,2", "72 m^x", "abc"}) {
        std::string error;
        EXPECT_FALSE(parse_quantity(bad, &error).has_value()) << "accepted '" << bad << "'";
        EXPECT_FALSE(error.empty()) << bad;
    }
}

TEST(Units, DimensionsAreDistinguished) {
    EXPECT_NE(parsed("72 mm").dimension, parsed("72 MPa").dimension);
    EXPECT_NE(parsed("35 deg").dimension, parsed("0.6").dimension);
    EXPECT_EQ(parsed("1 N/m^2").dimension, parsed("1 Pa").dimension);
    EXPECT_EQ(parsed("1 J").dimension, parsed("1 N*m").dimension);
    EXPECT_NEAR(parsed("1 N/m^2").value, parsed("1 Pa").value, kRoundOff);
}

TEST(Units, DescriptionsNameTheQuantity) {
    EXPECT_EQ(describe(dim::kLength), "a length (e.g. \"72 mm\")");
    EXPECT_NE(describe(dim::kPressure).find("pressure"), std::string::npos);
}

} // namespace
