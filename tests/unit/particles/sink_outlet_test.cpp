// A sink's declared outlet: Beverloo's rate for k d = 0 and with a material's grain size
// against hand values, the form it states, and the keys it refuses.

#include "io/case_error.hpp"
#include "io/case_table.hpp"
#include "particles/particles_case_reader.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>

namespace grainload::particles {
namespace {

TEST(SinkOutlet, BeverloosRateForASlotACircleAndAPlaneStrainSlot) {
    const double root_g = std::sqrt(9.81);
    // Plane strain, B = 0.2 m, 1500 kg/m^3: 1.03 * 1500 * 3.1321 * 0.2^1.5 = 432.8 kg/m/s, the
    // slot silo's figure (docs/validation/silo.md).
    const Outlet slot_2d{0.2, 0.0, 1500.0, 0.0, ""};
    EXPECT_NEAR(slot_2d.rate(9.81, 2), 1.03 * 1500.0 * root_g * 0.2 * std::sqrt(0.2), 1e-12);
    EXPECT_NEAR(slot_2d.rate(9.81, 2), 432.8, 0.05);
    // A circle of D = 0.1 m, 1600 kg/m^3: 0.58 * 1600 * 3.1321 * 0.1^2.5 = 9.19 kg/s, four times
    // the quarter silo's reference of 2.298 kg/s (cases/silo_hopper/silo_hopper.toml).
    const Outlet circle{0.1, 0.0, 1600.0, 0.0, ""};
    EXPECT_NEAR(circle.rate(9.81, 3) / 4.0, 2.298, 5e-4);
    // A 3D slot 0.4 m across and 0.4 m long, 300 kg/m^3: 1.03 * 300 * 3.1321 * 0.4 * 0.4^1.5.
    const Outlet slot_3d{0.4, 0.4, 300.0, 0.0, ""};
    EXPECT_NEAR(slot_3d.rate(9.81, 3), 1.03 * 300.0 * root_g * 0.4 * std::pow(0.4, 1.5), 1e-12);
}

/// The results of `sinks` in a scene that holds 1 kg and created nothing.
std::vector<io::ResultFigure> results_of(const SinkSet& sinks) {
    std::vector<io::ResultFigure> results;
    sinks.append_results(results);
    return results;
}

const io::ResultFigure& figure(const std::vector<io::ResultFigure>& results,
                               const std::string& name) {
    for (const io::ResultFigure& f : results) {
        if (f.name == name) {
            return f;
        }
    }
    throw std::runtime_error("no figure " + name);
}

// A circle of D = 0.1 m draining a material of 5 mm grains: Beverloo's reference takes
// k d = 1.5 x 5 mm off the diameter, 0.58 * 1600 * sqrt(9.81) * 0.0925^2.5 = 7.564 kg/s, and
// its statement names the form and the k d; a body of a continuum (no grain_size) beside it
// changes nothing. Without a grain size the reference is the k d = 0 form and says so. A 3D
// slot takes k d off its length too; plane strain per metre of depth.
TEST(SinkOutlet, BeverloosReferenceTakesTheMaterialsGrainSizeAndSaysWhichForm) {
    const std::string circle = "[sph]\n[[sph.sink]]\nname = \"below\"\ntype = \"plane\"\n"
                               "point = \"0 0 -1 m\"\nnormal = \"0 0 -1\"\n"
                               "outlet_width = \"0.1 m\"\nbulk_density = \"1600 kg/m^3\"\n";
    auto document = io::CaseDocument::from_string(circle, "sink.toml");
    const std::vector<SinkSet::BodyGrain> grains{{"sand", 0.005}, {"steel", std::nullopt}};
    const SinkSet with_grain = read_sinks(
        document->root().table("sph"), {"[[sph.body]]", {"sand", "plate"}}, 3, 9.81, 1.0, grains);
    const double expected = 0.58 * 1600.0 * std::sqrt(9.81) * std::pow(0.1 - 1.5 * 0.005, 2.5);
    ASSERT_TRUE(with_grain.outlet_rate(0).has_value());
    EXPECT_NEAR(*with_grain.outlet_rate(0), expected, 1e-12 * expected);
    EXPECT_NEAR(*with_grain.outlet_rate(0), 7.564, 5e-4);
    const io::ResultFigure& rate = figure(results_of(with_grain), "sink_below_steady_rate");
    EXPECT_EQ(rate.reference, with_grain.outlet_rate(0));
    EXPECT_NE(rate.source.find("(D - k d)^2.5"), std::string::npos) << rate.source;
    EXPECT_NE(rate.source.find("k d = 1.5 x 0.005 m (grain_size of material 'sand')"),
              std::string::npos)
        << rate.source;

    const SinkSet continuum =
        read_sinks(document->root().table("sph"), {"[[sph.body]]", {"sand"}}, 3, 9.81);
    EXPECT_NEAR(*continuum.outlet_rate(0), 0.58 * 1600.0 * std::sqrt(9.81) * std::pow(0.1, 2.5),
                1e-12);
    EXPECT_NE(figure(results_of(continuum), "sink_below_steady_rate")
                  .source.find("k d = 0 (no grain_size in the material)"),
              std::string::npos);

    const Outlet slot_3d{0.4, 0.4, 300.0, 0.065, "spheres"};
    EXPECT_NEAR(slot_3d.rate(9.81, 3),
                1.03 * 300.0 * std::sqrt(9.81) * (0.4 - 0.0975) * std::pow(0.4 - 0.0975, 1.5),
                1e-12);
    // The plane-wedge hopper's slot per metre with the paper's 65 mm spheres: 161 kg/m/s
    // (docs/validation/hopper_discharge.md, "Beverloo", k = 1.5).
    EXPECT_NEAR(slot_3d.rate(9.81, 2), 161.0, 0.5);
}

// Bodies of two grain sizes through one sink leave k d undefined unless the sink names its
// body; an outlet no wider than k d passes nothing in Beverloo's law and is refused.
TEST(SinkOutlet, RefusesAnUndefinedOrTooLargeGrain) {
    auto error = [](const std::string& extra, const std::vector<SinkSet::BodyGrain>& grains) {
        auto document = io::CaseDocument::from_string(
            "[sph]\n[[sph.sink]]\nname = \"below\"\ntype = \"plane\"\npoint = \"0 -1 m\"\n"
            "normal = \"0 -1\"\nbulk_density = \"1500 kg/m^3\"\n" +
                extra,
            "sink.toml");
        document->spatial_dimension = 2;
        try {
            SinkSet sinks = read_sinks(document->root().table("sph"),
                                       {"[[sph.body]]", {"fine", "coarse"}}, 2, 9.81, 1.0, grains);
        } catch (const io::CaseError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    const std::vector<SinkSet::BodyGrain> two{{"fine", 0.001}, {"coarse", 0.01}};
    EXPECT_NE(error("outlet_width = \"0.2 m\"\n", two).find("declare different grain sizes"),
              std::string::npos);
    EXPECT_EQ(error("outlet_width = \"0.2 m\"\nbody = \"coarse\"\n", two), "");
    EXPECT_NE(error("outlet_width = \"12 mm\"\nbody = \"coarse\"\n", two)
                  .find("expected an outlet wider than k d"),
              std::string::npos);
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
        SinkSet sinks =
            read_sinks(document->root().table("sph"), {"[[sph.body]]", {}}, dimension, 9.81);
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
} // namespace grainload::particles
