#include "particles/wall_map.hpp"
#include "support/csv_rows.hpp"
#include "support/test_folder.hpp"

#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <numbers>

namespace grainload::particles {
namespace {

constexpr double kPi = std::numbers::pi;
// Every figure below is a sum of a few dozen products divided by an area: round-off.
constexpr double kRoundOff = 1e-12;

// Two rings of 36 wall loads on a cylinder of radius 0.5 m about z, at z = 0.25 and 0.75 m,
// at angles (k + 1/2) 10 deg (none on a bin's edge), each pushing the wall outward by `radial`
// and along the axis by `axial` (the force of the sand on the wall), normals inward.
struct Rings {
    std::vector<WallLoad> loads;
    /// The loads as a method gives them, all on wall 0.
    WallLoads given() const {
        return [this](int wall, std::vector<WallLoad>& out) {
            EXPECT_EQ(wall, 0);
            out = loads;
        };
    }
};

Rings two_rings() {
    Rings r;
    for (const double z : {0.25, 0.75}) {
        for (int k = 0; k < 36; ++k) {
            const double angle = (k + 0.5) * kPi / 18.0;
            const Vec3 x(0.5 * std::cos(angle), 0.5 * std::sin(angle), z);
            r.loads.push_back({x, -Vec3(x.x(), x.y(), 0.0).normalized(), Vec3::Zero()});
        }
    }
    return r;
}

void push(Rings& r, double radial, double axial) {
    for (WallLoad& load : r.loads) {
        load.force = radial * Vec3(load.at.x(), load.at.y(), 0.0).normalized() + Vec3(0, 0, axial);
    }
}

WallMapSet::Map cylinder_map(double window_start, double window_end) {
    WallMapSet::Map map;
    map.name = "silo";
    map.walls = {0};
    map.half_spacing = {0.025}; // the rings' wall spacing, 0.05 m
    map.cylinder = true;
    map.axis = Vec3::UnitZ();
    map.reference = Vec3::UnitX();
    map.radius = 0.5;
    map.length = 1.0;
    map.angle_end = 2.0 * kPi;
    map.bins_1 = 2;
    map.bins_2 = 4;
    map.reach = std::numeric_limits<double>::infinity();
    map.window_start = window_start;
    map.window_end = window_end;
    return map;
}

std::string fresh_directory(const std::string& name) {
    const std::string dir = grainload::testing::process_folder() + "grainload_wall_map_" + name;
    std::filesystem::remove_all(dir);
    return dir;
}

// Each cell holds 9 loads of one ring: its loads are 9 f / A with A = R (pi / 2) (L / 2),
// the mean over an interval of steps of different lengths under one force is that force's.
TEST(WallMap, UnrolledCylinderGivesEachCellItsForceOverItsArea) {
    Rings r = two_rings();
    push(r, 2.0, -0.5);
    WallMapSet maps({cylinder_map(0.0, 1.0)});
    const std::string dir = fresh_directory("cylinder");
    maps.record(0.0, dir);
    maps.accumulate(0.0, 0.01, r.given());
    maps.accumulate(0.01, 0.03, r.given());
    maps.record(0.04, dir);
    const double area = 0.5 * (kPi / 2.0) * 0.5;
    const auto rows = testing::numeric_csv_rows(dir + "/wall_maps/silo_000001.csv");
    ASSERT_EQ(rows.size(), 8u);
    for (std::size_t cell = 0; cell < rows.size(); ++cell) {
        EXPECT_NEAR(rows[cell][0], 0.04, kRoundOff);                   // time
        EXPECT_NEAR(rows[cell][1], 0.04, kRoundOff);                   // interval
        EXPECT_NEAR(rows[cell][2], cell < 4 ? 0.25 : 0.75, kRoundOff); // axial centre
        EXPECT_NEAR(rows[cell][3], 45.0 + 90.0 * static_cast<double>(cell % 4), 1e-9); // angle
        EXPECT_NEAR(rows[cell][4], 9 * 2.0 / area, kRoundOff * 100);                   // pressure
        EXPECT_NEAR(rows[cell][5], 9 * -0.5 / area, kRoundOff * 100); // axial traction
        EXPECT_NEAR(rows[cell][6], 0.0, kRoundOff * 100);             // circumferential
    }
    // The first instant has no interval: zeros.
    const auto first = testing::numeric_csv_rows(dir + "/wall_maps/silo_000000.csv");
    EXPECT_EQ(first[0][4], 0.0);
}

// The window's mean is the impulse inside it over its length; its maximum the largest mean of
// the intervals that end inside it. Loads 1 N then 3 N radial for 0.1 s each, window
// [0.05, 0.2] s: mean (0.05 x 1 + 0.1 x 3) / 0.15 = 7/3 N per particle, maximum 3 N.
TEST(WallMap, WindowMeanAndMaximumFollowTheLoadHistory) {
    Rings r = two_rings();
    WallMapSet maps({cylinder_map(0.05, 0.2)});
    const std::string dir = fresh_directory("window");
    maps.record(0.0, dir);
    push(r, 1.0, 0.0);
    maps.accumulate(0.0, 0.1, r.given());
    maps.record(0.1, dir);
    push(r, 3.0, 0.0);
    maps.accumulate(0.1, 0.1, r.given());
    maps.record(0.2, dir);
    const double area = 0.5 * (kPi / 2.0) * 0.5;
    const auto rows = testing::numeric_csv_rows(dir + "/wall_maps/silo_window.csv");
    ASSERT_EQ(rows.size(), 8u);
    EXPECT_NEAR(rows[3][4], 9 * (7.0 / 3.0) / area, 1e-10);
    EXPECT_NEAR(rows[3][5], 9 * 3.0 / area, 1e-10);
    std::vector<io::ResultFigure> results;
    maps.append_results(results);
    auto figure = [&](const std::string& name) {
        for (const auto& f : results) {
            if (f.name == name) {
                return f.value;
            }
        }
        ADD_FAILURE() << "no figure " << name;
        return 0.0;
    };
    // The resultant of the mean: 72 particles x 7/3 N.
    EXPECT_NEAR(figure("wall_map_silo_normal_force"), 72 * 7.0 / 3.0, 1e-10);
    EXPECT_NEAR(figure("wall_map_silo_peak_max_pressure"), 9 * 3.0 / area, 1e-10);
    // A checkpoint's state restores the sums: the same window file again.
    WallMapSet restored({cylinder_map(0.05, 0.2)});
    restored.set_state(maps.state());
    EXPECT_EQ(restored.state(), maps.state());
}

/// Plane strain: loads at `points` on a floor (spacing 0.1 m, material above: normal +y), each
/// `force` (N/m) for 0.5 s, standing for patches `half` either side, mapped in two cells of
/// 0.5 m over x in [0, 1] m within `reach` of the line. Returns the rows of the interval's map.
std::vector<std::vector<double>> map_floor(const std::vector<Vec3>& points, const Vec3& force,
                                           double reach, const std::string& name,
                                           double half = 0.05) {
    Rings floor;
    for (const Vec3& x : points) {
        floor.loads.push_back({x, Vec3::UnitY(), force});
    }
    WallMapSet::Map map;
    map.name = "floor";
    map.walls = {0};
    map.half_spacing = {half};
    map.cylinder = false;
    map.edge_u = Vec3(1.0, 0.0, 0.0);
    map.bins_1 = 2;
    map.reach = reach;
    map.window_end = 1.0;
    WallMapSet maps({map});
    const std::string dir = fresh_directory(name);
    maps.record(0.0, dir);
    maps.accumulate(0.0, 0.5, floor.given());
    maps.record(0.5, dir);
    return testing::numeric_csv_rows(dir + "/wall_maps/floor_000001.csv");
}

// Plane strain: 10 particles on [0, 1) m pushed down by 4 N/m and along x by 1 N/m; two cells
// of 0.5 m by 1 m of depth. A particle beyond `reach` of the line (0.2 m off it) counts nowhere.
TEST(WallMap, PlaneStrainLineGivesPressurePerMetreOfDepth) {
    std::vector<Vec3> points;
    for (int k = 0; k < 10; ++k) {
        points.emplace_back(0.05 + 0.1 * k, 0.0, 0.0);
    }
    points.emplace_back(0.3, -0.2, 0.0);
    const auto rows = map_floor(points, Vec3(1.0, -4.0, 0.0), 0.1, "plane");
    ASSERT_EQ(rows.size(), 2u);
    for (const auto& row : rows) {
        EXPECT_NEAR(row[4], 5 * 4.0 / 0.5, kRoundOff * 100);
        EXPECT_NEAR(row[5], 5 * 1.0 / 0.5, kRoundOff * 100);
        EXPECT_EQ(row[6], 0.0);
    }
}

// A uniformly loaded wall gives a uniform map, also when particles lie on the cells' borders
// and on the grid's edges: 11 particles at 0, 0.1, ..., 1 m (spacing 0.1 m), 2 N/m each, two
// cells of 0.5 m. The particle at 0.5 m is shared half and half; the end particles' patches
// reach past the grid and give it their whole load: each cell holds 5.5 particles' load, and
// the two together all 11.
TEST(WallMap, ParticlesOnBordersAreSharedAndEdgesKeepTheirLoad) {
    std::vector<Vec3> points;
    for (int k = 0; k <= 10; ++k) {
        points.emplace_back(0.1 * k, 0.0, 0.0);
    }
    const auto rows =
        map_floor(points, Vec3(0.0, -2.0, 0.0), std::numeric_limits<double>::infinity(), "borders");
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_NEAR(rows[0][4], 5.5 * 2.0 / 0.5, kRoundOff * 100);
    EXPECT_NEAR(rows[1][4], 5.5 * 2.0 / 0.5, kRoundOff * 100);
}

// Point loads (a DEM contact's, patch width 0) go whole to the cell that holds them: 0.2 and
// 0.4 m to the first cell, 0.5 m (the border) and 1.0 m (the grid's far edge) to the second,
// one at 1.2 m and one 0.2 m off the line (beyond reach) nowhere; 3 N/m each.
TEST(WallMap, PointLoadsGoWholeToTheCellThatHoldsThem) {
    const std::vector<Vec3> points = {Vec3(0.2, 0, 0), Vec3(0.4, 0, 0), Vec3(0.5, 0, 0),
                                      Vec3(1.0, 0, 0), Vec3(1.2, 0, 0), Vec3(0.3, -0.2, 0)};
    const auto rows = map_floor(points, Vec3(0.0, -3.0, 0.0), 0.1, "points", 0.0);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_NEAR(rows[0][4], 2 * 3.0 / 0.5, kRoundOff * 100);
    EXPECT_NEAR(rows[1][4], 2 * 3.0 / 0.5, kRoundOff * 100);
}

} // namespace
} // namespace grainload::particles
