#include "support/case_runner.hpp"
#include "support/frame_reader.hpp"
#include "support/gold_summary.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <iostream>
#include <map>
#include <vector>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>

namespace grainload::testing {
namespace {

// The plane-wedge hopper's sheet as a coupled shell (cases/hopper_discharge/
// hopper_shell_small.toml, docs/validation/hopper_discharge.md "The sheets as coupled shells"):
// 8 mm steel, 1.8 m along the slope, pinned at the orifice and on a roller at the top, a strip
// whose long edges are symmetry lines, so it bends as a simply supported beam of the plate
// strip's stiffness D = E t^3 / (12 (1 - nu^2)) (cylindrical bending: Timoshenko &
// Woinowsky-Krieger 1959, section 1).
constexpr double kYoung = 210e9;
constexpr double kPoisson = 0.3;
constexpr double kThickness = 0.008;
constexpr double kSpan = 1.8;
constexpr double kOutput = 0.05; // s between frames

/// The sheet's node rows along the slope: slope coordinate s, mean outward sag w and mean
/// contact pressure p across the strip.
struct Profile {
    std::vector<double> s, w, p;
};

Profile sheet_profile(const std::string& vtm) {
    const auto sheet = read_named_block(vtm, "sheet");
    Profile out;
    if (sheet == nullptr) {
        return out;
    }
    const double a = 30.0 * std::acos(-1.0) / 180.0;
    const double slope[3] = {std::sin(a), 0.0, std::cos(a)};
    const double outward[3] = {std::cos(a), 0.0, -std::sin(a)};
    const double start[3] = {0.2 + 0.5 * kThickness * std::cos(a), 0.0,
                             -0.5 * kThickness * std::sin(a)};
    vtkDataArray* u = sheet->GetPointData()->GetArray("displacement");
    vtkDataArray* p = sheet->GetPointData()->GetArray("contact_pressure");
    std::map<long, std::array<double, 3>> rows; // s in micrometres -> sums of w, p, count
    for (vtkIdType i = 0; i < sheet->GetNumberOfPoints(); ++i) {
        const double* x = sheet->GetPoint(i);
        const double* d = u->GetTuple3(i);
        double s = 0.0;
        double w = 0.0;
        for (int c = 0; c < 3; ++c) {
            s += (x[c] - d[c] - start[c]) * slope[c];
            w += d[c] * outward[c];
        }
        auto& row = rows[std::lround(s * 1e6)];
        row[0] += w;
        row[1] += p->GetTuple1(i);
        row[2] += 1.0;
    }
    for (const auto& [key, row] : rows) {
        out.s.push_back(1e-6 * static_cast<double>(key));
        out.w.push_back(row[0] / row[2]);
        out.p.push_back(row[1] / row[2]);
    }
    return out;
}

/// Normal load per metre of the strip's depth, N/m: the pressure integrated along the slope.
double normal_load(const Profile& profile) {
    double sum = 0.0;
    for (std::size_t k = 1; k < profile.s.size(); ++k) {
        sum += 0.5 * (profile.p[k] + profile.p[k - 1]) * (profile.s[k] - profile.s[k - 1]);
    }
    return sum;
}

/// A simply supported beam (supports at the first and last row) under the profile's pressure,
/// linear between rows, of bending stiffness D: its largest sag and largest moment per unit
/// width, by statics and two integrations of w'' = -M / D (trapezoidal, 4000 intervals).
std::pair<double, double> beam(const Profile& profile, double stiffness) {
    constexpr int kIntervals = 4000;
    const double length = profile.s.back() - profile.s.front();
    const double ds = length / kIntervals;
    std::vector<double> q(kIntervals + 1);
    std::vector<double> s(kIntervals + 1);
    std::size_t row = 0;
    for (int k = 0; k <= kIntervals; ++k) {
        s[k] = profile.s.front() + k * ds;
        while (row + 2 < profile.s.size() && profile.s[row + 1] < s[k]) {
            ++row;
        }
        const double f =
            std::clamp((s[k] - profile.s[row]) / (profile.s[row + 1] - profile.s[row]), 0.0, 1.0);
        q[k] = profile.p[row] + f * (profile.p[row + 1] - profile.p[row]);
    }
    // Moments about the far support give the near reaction; M(s) = R s - int q (s - x) dx.
    std::vector<double> force(kIntervals + 1, 0.0);
    std::vector<double> first(kIntervals + 1, 0.0);
    for (int k = 1; k <= kIntervals; ++k) {
        force[k] = force[k - 1] + 0.5 * (q[k] + q[k - 1]) * ds;
        first[k] = first[k - 1] + 0.5 * (q[k] * (s[k] - s[0]) + q[k - 1] * (s[k - 1] - s[0])) * ds;
    }
    const double reaction = (force.back() * length - first.back()) / length;
    std::vector<double> moment(kIntervals + 1);
    double largest_moment = 0.0;
    for (int k = 0; k <= kIntervals; ++k) {
        moment[k] = reaction * (s[k] - s[0]) - ((s[k] - s[0]) * force[k] - first[k]);
        largest_moment = std::max(largest_moment, moment[k]);
    }
    std::vector<double> sag(kIntervals + 1, 0.0);
    double rotation = 0.0;
    for (int k = 1; k <= kIntervals; ++k) {
        const double next = rotation - 0.5 * (moment[k] + moment[k - 1]) * ds / stiffness;
        sag[k] = sag[k - 1] + 0.5 * (rotation + next) * ds;
        rotation = next;
    }
    double largest_sag = 0.0;
    for (int k = 0; k <= kIntervals; ++k) {
        largest_sag = std::max(largest_sag, sag[k] - sag.back() * k / kIntervals);
    }
    return {largest_sag, largest_moment};
}

std::string frame_at(const std::string& out, int index) {
    return frame_path(out, "hopper_shell_small", index);
}

// The fill deposited at rest, settled (the gate goes when it has), discharged:
//  - Books: the audit closes to round-off (at most 1000 particle masses: 1000 eps), the energy
//    books and the interface's energy within the CI bound (0.3 %; 1 % for the interface, whose
//    staggered exchange has a one-window lag).
//  - At rest (the last frame before the gate went) and at the discharge's largest load on the
//    sheet (the switch to flow at the orifice: measured 1.19 times the load at rest), the
//    sheet's largest sag against the beam under the pressure the run put on it: within 5 %
//    (measured 1.000 and 0.976: in the discharge the load changes from window to window and
//    the static shell answers each window's load a window late; the beam takes the pressure
//    linear between the 50 mm node rows, where the shell received it lumped at the nodes).
//  - The faces' von Mises stress the shell reports, at that frame, against the beam's bending
//    stress 6 M / t^2 in plane strain (sigma_22 = nu sigma_11: von Mises
//    sqrt(1 - nu + nu^2) 6 M / t^2): within 5 % (the elements report their centre's moment; the
//    beam's largest is the peak, 25 mm from the nearest centre on a flat top).
TEST(HopperShellSmall, TheSheetSagsAndIsStressedAsABeamUnderTheRunsPressure) {
    const CaseRun run =
        run_case_file("cases/hopper_discharge/hopper_shell_small.toml", "hopper_shell_small");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    expect_books_close(summary, 1000);
    constexpr double kInterfaceEnergy = 1e-2;
    EXPECT_LT(std::abs(result_value(summary, "coupling_energy_error")), kInterfaceEnergy);
    const double settled = result_value(summary, "settle_time");
    const int rest = static_cast<int>(std::floor(settled / kOutput));
    int peak = rest + 1;
    double peak_load = 0.0;
    const int last =
        static_cast<int>(std::lround(summary_number(summary, "simulated_time_s") / kOutput));
    for (int k = rest + 1; k <= last; ++k) {
        const double load = normal_load(sheet_profile(frame_at(run.out, k)));
        if (load > peak_load) {
            peak_load = load;
            peak = k;
        }
    }
    const double stiffness =
        kYoung * std::pow(kThickness, 3) / (12.0 * (1.0 - kPoisson * kPoisson));
    constexpr double kBeam = 0.05;
    for (const int k : {rest, peak}) {
        const Profile profile = sheet_profile(frame_at(run.out, k));
        ASSERT_GT(profile.s.size(), 30u);
        EXPECT_NEAR(profile.s.back() - profile.s.front(), kSpan, 1e-6);
        const auto [sag, moment] = beam(profile, stiffness);
        const double largest = *std::max_element(profile.w.begin(), profile.w.end());
        std::cout << "hopper sheet at " << k * kOutput << " s: load " << normal_load(profile)
                  << " N/m, sag " << largest * 1e3 << " mm, beam " << sag * 1e3 << " mm\n";
        EXPECT_NEAR(largest, sag, kBeam * sag) << "frame " << k;
        if (k == peak) {
            const auto sheet = read_named_block(frame_at(run.out, k), "sheet");
            vtkDataArray* top = sheet->GetCellData()->GetArray("von_mises_top");
            vtkDataArray* bottom = sheet->GetCellData()->GetArray("von_mises_bottom");
            double stress = 0.0;
            for (vtkIdType e = 0; e < sheet->GetNumberOfCells(); ++e) {
                stress = std::max({stress, top->GetTuple1(e), bottom->GetTuple1(e)});
            }
            const double expected = std::sqrt(1.0 - kPoisson + kPoisson * kPoisson) * 6.0 * moment /
                                    (kThickness * kThickness);
            std::cout << "  faces' von Mises " << stress * 1e-6 << " MPa, beam " << expected * 1e-6
                      << " MPa\n";
            EXPECT_NEAR(stress, expected, kBeam * expected);
        }
    }
    EXPECT_GT(peak_load, 0.0);

    // The run's own summary states the same comparison: the case's [[case.reference]] gives the
    // largest sag and face stress over the run the beam's figures at the discharge's peak
    // frame (17.51 mm, 45.8 MPa, from the pressure of this case's run,
    // docs/validation/hopper_discharge.md). The run's largest over all windows may exceed the
    // peak frame's by what a window between frames adds: within the same 5 % (measured -1.6 %
    // and -1.5 %).
    for (const char* figure : {"shell_largest_deflection", "shell_largest_von_mises"}) {
        const FigureReference beam = figure_reference(summary, figure);
        std::cout << figure << ": " << beam.value << " against the beam's " << beam.reference
                  << " (relative error " << beam.relative_error << ")\n";
        EXPECT_NE(beam.source.find("beam theory"), std::string::npos) << figure;
        EXPECT_LT(beam.relative_error, kBeam) << figure;
    }
    expect_matches_gold(run.out, "cases/hopper_discharge/hopper_shell_small.toml");
}

} // namespace
} // namespace grainload::testing
