// Symmetry planes ([[sph.symmetry]]): a half (2D) and a quarter (3D) model against the full
// model they cut. The reference is the full model itself: for a scene symmetric about the
// plane, every neighbour a particle of the cut model misses is the mirror image of one it has,
// so the cut model computes the same sums as the full one, in another order.
#include "io/case_table.hpp"
#include "sph/sph_model.hpp"
#include "support/sph_scene.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <string>

namespace grainload::sph {
namespace {

/// For each material particle of `cut`, the particle of `full` that started at its place.
std::vector<Index> match(const ParticleSet& cut, const ParticleSet& full, double spacing) {
    std::vector<Index> partner;
    for (Index i = 0; i < cut.size(); ++i) {
        if (cut.is_wall(i)) {
            continue;
        }
        Index found = -1;
        for (Index j = 0; j < full.size(); ++j) {
            if (!full.is_wall(j) && (full.position[j] - cut.position[i]).norm() < 1e-6 * spacing) {
                found = j;
            }
        }
        EXPECT_GE(found, 0) << "particle " << i << " of the cut model has no partner";
        partner.push_back(found);
    }
    return partner;
}

double largest_gap(const ParticleSet& cut, const ParticleSet& full,
                   const std::vector<Index>& partner) {
    double gap = 0.0;
    for (std::size_t k = 0; k < partner.size(); ++k) {
        gap =
            std::max(gap, (cut.position[static_cast<Index>(k)] - full.position[partner[k]]).norm());
    }
    return gap;
}

// 2D: a Drucker-Prager column 200 mm wide and 100 mm high centred on x = 0 collapsing both ways
// on a rough floor (the material of cases/column_collapse_2d), and its right half with a plane
// x = 0. The floor extends past the plane in both.
const char* kColumn2d = R"(
[case]
dimension = 2
end_time = "1 s"
gravity = "0 -9.81 m/s^2"
[[material]]
name = "bars"
model = "drucker_prager"
density = "2040 kg/m^3"
youngs_modulus = "5.84 MPa"
poisson_ratio = 0.3
friction_angle = "21.9 deg"
cohesion = "0 Pa"
dilatancy_angle = "0 deg"
cone_fit = "plane_strain"
[sph]
kernel_gradient_correction = true
[sph.artificial_viscosity]
alpha = 0.1
beta = 0.1
[sph.contact]
stiffness = "5.84 MPa"
damping_ratio = 0.5
[[sph.body]]
name = "column"
material = "bars"
spacing = "10 mm"
[sph.body.shape]
type = "box"
max = "100 118.5 mm"
[[sph.wall]]
name = "floor"
type = "plane"
spacing = "5 mm"
origin = "-400 0 mm"
edge_u = "800 0 mm"
normal = "0 1"
[[sph.friction]]
body = "column"
wall = "floor"
mu_static = 0.402
mu_kinetic = 0.402
)";

/// The scene `text` with its body's box starting at `min` (the line after `max_line`, the box's
/// upper corner) and the symmetry planes `planes` appended (empty for the full model): full and
/// cut models differ only there.
std::string boxed(std::string text, const std::string& max_line, const std::string& min,
                  const std::string& planes) {
    text.replace(text.find(max_line), max_line.size(), max_line + "\nmin = \"" + min + "\"");
    return text + planes;
}

// The symmetry plane x = 0 of the half column.
const char* kHalfPlane = "[[sph.symmetry]]\naxis = \"x\"\nat = \"0 m\"\n";

std::string column(bool half) {
    return boxed(kColumn2d, "max = \"100 118.5 mm\"", half ? "0 18.5 mm" : "-100 18.5 mm",
                 half ? kHalfPlane : "");
}

// The positions differ only by the order of the neighbour sums (and of the eigen-solves of the
// yield surface's return on mirrored stresses), about 1e-16 of each term; over 50 steps that
// round-off stays below 1e-12 m (measured 1e-16 to 1e-15 m), a ten-billionth of the spacing.
constexpr double kRoundOffGap = 1e-12;
// After 0.4 s of plastic flow, which could amplify round-off (a yield-or-not decision that
// flips), the positions still agree to 1e-14 m (measured); 1e-9 m, a ten-millionth of the
// spacing, leaves room for another compiler's rounding and still fails on any physical
// difference (a missing image moves the particles near the plane by millimetres).
constexpr double kLateGap = 1e-9;
// The floor loads of half and full: the half carries the reactions of its own particles, exactly
// half of the full's for a symmetric motion; 1e-9 relative over the first steps (round-off).
constexpr double kEarlyLoadRatio = 1e-9;
// Averaged over the last 0.05 s of the run: the same round-off argument as kLateGap.
constexpr double kLateLoadRatio = 1e-9;

/// The floor of `text` cut at the plane x = 0 (or x = 0 and y = 0): the cut model's floor is
/// then mirrored there (Wall::mirror_planes) instead of running on past the plane.
std::string cut_floor(std::string text, const std::string& whole, const std::string& cut) {
    text.replace(text.find(whole), whole.size(), cut);
    return text;
}

/// A floor of wall particles at a quarter of the bodies' spacing (2.5 mm, the first layer
/// 0.625 mm below the floor plane): the grains of the first row, which rest about 2h above the
/// first layer, then reach the floor's particles on the other side of the plane.
std::string fine_floor(std::string text) {
    const std::string from = "spacing = \"5 mm\"";
    text.replace(text.find(from), from.size(), "spacing = \"2.5 mm\"");
    return text;
}

std::string column_on_cut_floor() {
    return cut_floor(fine_floor(column(true)), "origin = \"-400 0 mm\"\nedge_u = \"800 0 mm\"",
                     "origin = \"0 0 mm\"\nedge_u = \"400 0 mm\"");
}

void expect_half_column_is_the_full_column(const std::string& full_text,
                                           const std::string& half_text) {
    const testing::SphScene full(full_text, "symmetry.toml");
    const testing::SphScene half(half_text, "symmetry.toml");
    const double spacing = 0.01;
    const auto partner = match(half.model->particles(), full.model->particles(), spacing);
    ASSERT_EQ(partner.size(), 100U);
    const double dt = 4e-5;
    double t = 0.0;
    double worst_early_load = 0.0;
    for (int step = 0; step < 50; ++step, t += dt) {
        full.model->advance(t, dt);
        half.model->advance(t, dt);
        const double full_load = full.model->solver()->walls()[0].force.y();
        const double half_load = half.model->solver()->walls()[0].force.y();
        if (std::abs(full_load) > 0.0) {
            worst_early_load =
                std::max(worst_early_load, std::abs(2.0 * half_load / full_load - 1.0));
        }
    }
    const double early_gap = largest_gap(half.model->particles(), full.model->particles(), partner);
    std::cout << "after 50 steps: largest position gap " << early_gap
              << " m, largest floor-load mismatch " << worst_early_load << '\n';
    EXPECT_LT(early_gap, kRoundOffGap);
    EXPECT_LT(worst_early_load, kEarlyLoadRatio);

    const int steps = 10000; // to 0.4 s: the heap has come to rest (cases/column_collapse_2d)
    double full_sum = 0.0;
    double half_sum = 0.0;
    for (int step = 50; step < steps; ++step, t += dt) {
        full.model->advance(t, dt);
        half.model->advance(t, dt);
        if (step >= steps - 1250) {
            full_sum += full.model->solver()->walls()[0].force.y();
            half_sum += half.model->solver()->walls()[0].force.y();
        }
    }
    double full_runout = 0.0;
    double half_runout = 0.0;
    const ParticleSet& f = full.model->particles();
    const ParticleSet& h = half.model->particles();
    for (Index j = 0; j < f.size(); ++j) {
        full_runout =
            f.is_wall(j) ? full_runout : std::max(full_runout, std::abs(f.position[j].x()));
    }
    for (Index i = 0; i < h.size(); ++i) {
        half_runout = h.is_wall(i) ? half_runout : std::max(half_runout, h.position[i].x());
    }
    std::cout << "at " << t << " s: runout full " << full_runout << " m, half " << half_runout
              << " m; floor load full " << full_sum / 1250 << " N/m, half " << half_sum / 1250
              << " N/m; largest position gap " << largest_gap(h, f, partner) << " m\n";
    EXPECT_GT(full_runout, 0.15); // it did collapse (from 0.1 m)
    EXPECT_LT(largest_gap(h, f, partner), kLateGap);
    EXPECT_NEAR(half_runout, full_runout, kLateGap);
    EXPECT_NEAR(2.0 * half_sum / full_sum, 1.0, kLateLoadRatio);
}

TEST(SymmetryModel, HalfColumnCollapseReproducesTheFullColumn) {
    expect_half_column_is_the_full_column(column(false), column(true));
}

// The floor ends at the plane and is mirrored: the grains near the plane see the floor's
// images, and the floor's real particles carry, folded back, the loads on its images (the
// contact, the dashpot and the friction of the grains' images in the full model).
TEST(SymmetryModel, HalfColumnOnAFloorCutAtThePlaneReproducesTheFullColumn) {
    expect_half_column_is_the_full_column(fine_floor(column(false)), column_on_cut_floor());
}

const char* kRightSink = R"(
[[sph.sink]]
name = "right"
type = "plane"
point = "150 0 mm"
normal = "1 0"
)";

const char* kLeftSink = R"(
[[sph.sink]]
name = "left"
type = "plane"
point = "-150 0 mm"
normal = "-1 0"
)";

double material_mass(const ParticleSet& p) {
    double sum = 0.0;
    for (Index i = 0; i < p.size(); ++i) {
        sum += p.is_wall(i) ? 0.0 : p.mass[i];
    }
    return sum;
}

// Particles leaving through sinks: the half loses its share of the full's, and the images,
// selected again at the neighbour-list build that follows each removal, keep the two runs the
// same to round-off (kLateGap, as above).
TEST(SymmetryModel, HalfColumnLosesHalfTheFullColumnsParticlesThroughSinks) {
    const testing::SphScene full(column(false) + kRightSink + kLeftSink, "symmetry.toml");
    const testing::SphScene half(column(true) + kRightSink, "symmetry.toml");
    const double dt = 4e-5;
    double t = 0.0;
    for (int step = 0; step < 10000; ++step, t += dt) {
        full.model->advance(t, dt);
        half.model->advance(t, dt);
    }
    const ParticleSet& f = full.model->particles();
    const ParticleSet& h = half.model->particles();
    const double full_mass = material_mass(f);
    const double half_mass = material_mass(h);
    double gap = 0.0;
    for (Index i = 0; i < h.size(); ++i) {
        if (h.is_wall(i)) {
            continue;
        }
        double nearest = std::numeric_limits<double>::infinity();
        for (Index j = 0; j < f.size(); ++j) {
            nearest =
                f.is_wall(j) ? nearest : std::min(nearest, (f.position[j] - h.position[i]).norm());
        }
        gap = std::max(gap, nearest);
    }
    std::cout << "with sinks at " << t << " s: material mass full " << full_mass << " kg/m, half "
              << half_mass << " kg/m (of " << 200 * 2040.0 * 1e-4 << " and " << 100 * 2040.0 * 1e-4
              << "); largest gap to the nearest full particle " << gap << " m\n";
    EXPECT_LT(full_mass, 200 * 2040.0 * 1e-4 * 0.99); // particles did leave
    EXPECT_DOUBLE_EQ(2.0 * half_mass, full_mass);
    EXPECT_LT(gap, kLateGap);
}

// Two bodies stacked across the plane: the contact potential of pairs of a particle and the
// image of a particle of the other body is half the cut model's (the full model holds each such
// pair once for both halves), so the half's contact energy is half the full's, at the start
// (the upper block's first row 20 mm above the lower's last row, so that pairs across the plane,
// 22 mm apart, lie inside the 26 mm support: counted whole, the half would hold 55.86 J/m, not
// 55.00) and as the blocks push apart. Round-off only: 1e-9 relative (measured 1e-15 to 3e-12).
constexpr double kContactEnergyRatio = 1e-9;

std::string stacked(bool half) {
    std::string text = column(half);
    const std::string lower = "max = \"100 118.5 mm\"";
    text.replace(text.find(lower), lower.size(), "max = \"100 58.5 mm\"");
    text += std::string(R"(
[[sph.body]]
name = "upper"
material = "bars"
spacing = "10 mm"
[sph.body.shape]
type = "box"
max = "100 108.5 mm"
)") + (half ? "min = \"0 68.5 mm\"\n" : "min = \"-100 68.5 mm\"\n");
    return text;
}

TEST(SymmetryModel, HalfHoldsHalfTheContactEnergyBetweenBodies) {
    const testing::SphScene full(stacked(false), "symmetry.toml");
    const testing::SphScene half(stacked(true), "symmetry.toml");
    const double dt = 4e-5;
    double t = 0.0;
    for (int step = 0; step <= 500; ++step, t += dt) {
        if (step % 250 == 0) {
            const double e_full = full.model->solver()->contact_energy();
            const double e_half = half.model->solver()->contact_energy();
            std::cout << "contact energy at " << t << " s: full " << e_full << " J/m, half "
                      << e_half << " J/m\n";
            ASSERT_GT(e_full, 0.0);
            EXPECT_NEAR(2.0 * e_half / e_full, 1.0, kContactEnergyRatio);
        }
        full.model->advance(t, dt);
        half.model->advance(t, dt);
    }
}

// A source pouring grains next to the plane onto the half column: the new particles get
// images at the list build that follows their creation, and none crosses the plane (in the full
// model the grains from the two halves meet at x = 0 and, by symmetry, none crosses it).
TEST(SymmetryModel, GrainsFromASourceStayOnTheirSideOfThePlane) {
    const testing::SphScene half(column(true) + R"(
[[sph.source]]
name = "pour"
body = "column"
min = "0 160 mm"
max = "60 200 mm"
mass_rate = "40 kg/m/s"
velocity = "0 -1 m/s"
)",
                                 "symmetry.toml");
    const double dt = 4e-5;
    double t = 0.0;
    for (int step = 0; step < 6000; ++step, t += dt) {
        half.model->advance(t, dt);
    }
    const ParticleSet& p = half.model->particles();
    double nearest = std::numeric_limits<double>::infinity();
    double mass = 0.0;
    for (Index i = 0; i < p.size(); ++i) {
        if (!p.is_wall(i)) {
            nearest = std::min(nearest, p.position[i].x());
            mass += p.mass[i];
        }
    }
    std::cout << "with a source at " << t << " s: material mass " << mass
              << " kg/m, nearest particle to the plane at x = " << nearest << " m\n";
    EXPECT_GT(mass, 100 * 2040.0 * 1e-4 + 40.0 * 0.2); // created at least 0.2 s of the rate
    EXPECT_GT(nearest, 0.0);
}

// 3D: an elastic block 60 x 60 x 40 mm at rest (geostatic stress) on a floor, and its quarter
// x > 0, y > 0 with the planes x = 0 and y = 0, whose particles near the edge x = y = 0 see
// three images each (the image of the image included).
const char* kBlock3d = R"(
[case]
dimension = 3
end_time = "1 s"
gravity = "0 0 -9.81 m/s^2"
[[material]]
name = "grain"
model = "linear_elastic"
density = "1600 kg/m^3"
youngs_modulus = "2 MPa"
poisson_ratio = 0.3
[sph]
[sph.artificial_viscosity]
alpha = 0.2
beta = 0.2
[sph.contact]
stiffness = "2 MPa"
damping_ratio = 0.5
[[sph.body]]
name = "block"
material = "grain"
spacing = "10 mm"
[sph.body.shape]
type = "box"
max = "30 30 58.5 mm"
[sph.body.initial_stress]
type = "geostatic"
lateral_ratio = 0.43
[[sph.wall]]
name = "floor"
type = "plane"
spacing = "5 mm"
origin = "-50 -50 0 mm"
edge_u = "100 0 0 mm"
edge_v = "0 100 0 mm"
normal = "0 0 1"
)";

// The symmetry planes x = 0 and y = 0 of the quarter block.
const char* kQuarterPlanes =
    "[[sph.symmetry]]\naxis = \"x\"\n[[sph.symmetry]]\naxis = \"y\"\nside = \"+\"\n";

std::string block(bool quarter) {
    return boxed(kBlock3d, "max = \"30 30 58.5 mm\"", quarter ? "0 0 18.5 mm" : "-30 -30 18.5 mm",
                 quarter ? kQuarterPlanes : "");
}

// The floor loads of quarter and full over the whole run: round-off only (measured 1e-15).
constexpr double kQuarterLoadRatio = 1e-9;
// The full block's floor carries its weight once it has settled: averaged over the last 0.03 s
// of 0.15 s, the ringing of the first contact (damped by the contact dashpot and the viscosity)
// is within 2 % of the mean.
constexpr double kWeightTolerance = 0.02;

void expect_quarter_block_carries_a_quarter(const std::string& full_text,
                                            const std::string& quarter_text) {
    const testing::SphScene full(full_text, "symmetry.toml");
    const testing::SphScene quarter(quarter_text, "symmetry.toml");
    const auto partner = match(quarter.model->particles(), full.model->particles(), 0.01);
    ASSERT_EQ(partner.size(), 36U);
    const double dt = 5e-5;
    const int steps = 3000;
    const int averaged = 600;
    double worst = 0.0;
    double full_sum = 0.0;
    double quarter_sum = 0.0;
    double t = 0.0;
    for (int step = 0; step < steps; ++step, t += dt) {
        full.model->advance(t, dt);
        quarter.model->advance(t, dt);
        const double full_load = -full.model->solver()->walls()[0].force.z();
        const double quarter_load = -quarter.model->solver()->walls()[0].force.z();
        if (full_load > 0.0) {
            worst = std::max(worst, std::abs(4.0 * quarter_load / full_load - 1.0));
        }
        if (step >= steps - averaged) {
            full_sum += full_load / averaged;
            quarter_sum += quarter_load / averaged;
        }
    }
    const double weight = 1600.0 * 144 * 1e-6 * 9.81;
    const double gap = largest_gap(quarter.model->particles(), full.model->particles(), partner);
    std::cout << "at " << t << " s: floor load quarter " << quarter_sum << " N, full " << full_sum
              << " N (weight " << weight << " N); largest mismatch " << worst << ", position gap "
              << gap << " m\n";
    EXPECT_LT(worst, kQuarterLoadRatio);
    EXPECT_LT(gap, kLateGap);
    EXPECT_NEAR(4.0 * quarter_sum / full_sum, 1.0, kQuarterLoadRatio);
    EXPECT_NEAR(full_sum / weight, 1.0, kWeightTolerance);
}

TEST(SymmetryModel, QuarterBlockCarriesAQuarterOfTheFloorLoad) {
    expect_quarter_block_carries_a_quarter(block(false), block(true));
}

// The floor cut at both planes (at the fine spacing, see fine_floor): its particles near the
// edge x = y = 0 have three images each.
TEST(SymmetryModel, QuarterBlockOnAFloorCutAtBothPlanesCarriesAQuarter) {
    expect_quarter_block_carries_a_quarter(
        fine_floor(block(false)),
        cut_floor(fine_floor(block(true)),
                  "origin = \"-50 -50 0 mm\"\nedge_u = \"100 0 0 mm\"\nedge_v = \"0 100 0 mm\"",
                  "origin = \"0 0 0 mm\"\nedge_u = \"50 0 0 mm\"\nedge_v = \"0 50 0 mm\""));
}

} // namespace
} // namespace grainload::sph
