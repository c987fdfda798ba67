// A sink's declared outlet: Beverloo's rate for k d = 0 against hand values, and the keys it
// refuses.

#include "io/case_error.hpp"
#include "io/case_table.hpp"
#include "sph/sink.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

TEST(SinkOutlet, BeverloosRateForASlotACircleAndAPlaneStrainSlot) {
    const double root_g = std::sqrt(9.81);
    // Plane strain, B = 0.2 m, 1500 kg/m^3: 1.03 * 1500 * 3.1321 * 0.2^1.5 = 432.8 kg/m/s, the
    // slot silo's figure (docs/validation/silo.md).
    const Outlet slot_2d{0.2, 0.0, 1500.0};
    EXPECT_NEAR(slot_2d.rate(9.81, 2), 1.03 * 1500.0 * root_g * 0.2 * std::sqrt(0.2), 1e-12);
    EXPECT_NEAR(slot_2d.rate(9.81, 2), 432.8, 0.05);
    // A circle of D = 0.1 m, 1600 kg/m^3: 0.58 * 1600 * 3.1321 * 0.1^2.5 = 9.19 kg/s, four times
    // the quarter silo's reference of 2.298 kg/s (cases/silo_hopper/silo_hopper.toml).
    const Outlet circle{0.1, 0.0, 1600.0};
    EXPECT_NEAR(circle.rate(9.81, 3) / 4.0, 2.298, 5e-4);
    // A 3D slot 0.4 m across and 0.4 m long, 300 kg/m^3: 1.03 * 300 * 3.1321 * 0.4 * 0.4^1.5.
    const Outlet slot_3d{0.4, 0.4, 300.0};
    EXPECT_NEAR(slot_3d.rate(9.81, 3), 1.03 * 300.0 * root_g * 0.4 * std::pow(0.4, 1.5), 1e-12);
}

std::string sink_case(const std::string& extra) {
    return "[sph]\n[[sph.sink]]\nname = \"below\"\ntype = \"plane\"\npoint = \"0 -1 m\"\n"
           "normal = \"0 -1\"\n" +
           extra;
}

std::string error_of(const std::string& text, int dimension) {
    auto document = io::CaseDocument::from_string(text, "sink.toml");
    document->spatial_dimension = dimension;
    try {
        SinkSet sinks(document->root().table("sph"), {}, dimension, 9.81);
    } catch (const io::CaseError& e) {
        return e.what();
    }
    return "";
}

TEST(SinkOutlet, RefusesAnOutletHalfDeclared) {
    EXPECT_EQ(error_of(sink_case("outlet_width = \"0.2 m\"\nbulk_density = \"1500 kg/m^3\"\n"), 2),
              "");
    EXPECT_NE(error_of(sink_case("bulk_density = \"1500 kg/m^3\"\n"), 2).find("needs outlet_width"),
              std::string::npos);
    EXPECT_NE(error_of(sink_case("outlet_width = \"0.2 m\"\n"), 2).find("bulk_density"),
              std::string::npos);
    EXPECT_NE(error_of(sink_case("outlet_width = \"0.2 m\"\nbulk_density = \"1500 kg/m^3\"\n"
                                 "outlet_length = \"1 m\"\n"),
                       2)
                  .find("plane strain: the outlet is a slot per metre of depth"),
              std::string::npos);
    EXPECT_NE(error_of(sink_case("outlet_width = \"-0.2 m\"\nbulk_density = \"1500 kg/m^3\"\n"), 2)
                  .find("outlet_width"),
              std::string::npos);
}

} // namespace
} // namespace grainload::sph
