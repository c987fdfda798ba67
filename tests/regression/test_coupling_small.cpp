#include "support/case_runner.hpp"
#include "support/coupling_figures.hpp"
#include "support/csv_rows.hpp"
#include "support/frame_reader.hpp"
#include "support/gold_summary.hpp"
#include "support/interrupted_run.hpp"

#include <cstdio>
#include <cstdlib>
#include <vector>
#include <vtkCellData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

namespace grainload::testing {
namespace {

constexpr double kGravity = 9.81;

// Verification 1 of the coupling: a 0.1 m sand layer (20 x 20 x 5 particles, 25.6 kg) at rest
// on a 0.4 m simply supported steel plate 2 mm thick, solved statically and coupled through
// its upper face, with windows of 10 ms relaxed by 0.5.
//  - The plate carries the weight: the interface load (its impulse over the last 0.15 s, after
//    the layer has settled at about 0.15 s, divided by the time: the mean load, free of the
//    soft layer's slow sloshing of about 0.4 %) with the side walls' vertical forces equals
//    M g to 0.1 %, the acceptance bound. The side walls are frictionless, but a lattice of wall
//    particles is corrugated: its repulsion has a small component along the wall, here
//    0.75 N (0.3 % of the weight) pushing the layer down onto the plate.
//  - It sags like a plate under q = M g / a^2: w = 0.00406 q a^4 / D (Timoshenko &
//    Woinowsky-Krieger, table 8). Bound 3 %: the layer's own bending stiffness is 1.1 % of the
//    plate's and takes that share (measured -0.9 %); the 8 x 8 MITC4 mesh is 0.3 % stiff; the
//    kernel spreads the load by 2h = 52 mm near the supports; the sloshing moves w by 0.4 %.
TEST(CouplingSmall, SandLayerOnAPlateWeighsOnItAndBendsItLikeAUniformLoad) {
    const CaseRun run =
        run_case_file("cases/sand_on_plate/sand_on_plate_small.toml", "sand_on_plate_small");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    const double mass = 2000 * 1600.0 * 0.02 * 0.02 * 0.02;
    const double weight = mass * kGravity;
    double time = 0.0;
    const double load = -mean_shell_load_z(run.out, 0.35, time);
    ASSERT_GT(time, 0.1);
    const double side_walls = walls_force_z(summary, {"x0", "x1", "y0", "y1"});
    EXPECT_NEAR(load - side_walls, weight, 1e-3 * weight);
    const double d = 210e9 * 0.002 * 0.002 * 0.002 / (12.0 * (1.0 - 0.09));
    const double q = weight / (0.4 * 0.4);
    const double navier = -0.00406 * q * std::pow(0.4, 4) / d;
    const double w = result_value(summary, "centre_deflection");
    std::cout << "sand on plate: mean interface load " << load << " N, side walls' vertical load "
              << side_walls << " N (weight " << weight << " N), centre deflection " << w
              << " m (plate under q: " << navier << " m)\n";
    EXPECT_NEAR(w, navier, 0.03 * std::abs(navier));
    // The largest deflection over the run (the after-run hint's figure) is at least the final
    // one, and the layer's landing on a static plate cannot push it past twice the static
    // deflection (the dynamic amplification of a suddenly applied load, Clough & Penzien 1993
    // section 4-6; the sand here is let down by one contact range, less than sudden).
    const double largest = result_value(summary, "shell_largest_deflection");
    EXPECT_GE(largest, std::abs(w));
    EXPECT_LT(largest, 2.0 * std::abs(navier));
    // ... which is 0.1 of the particle spacing: the hint says that the compliance matters.
    EXPECT_NE(summary.find("of the particle spacing 0.02 m: the wall's compliance matters"),
              std::string::npos)
        << summary;
    // The coupling did not go unstable on the way: the interface energy error stayed small
    // against the sand's energy throughput (the staggered scheme's lag, first order).
    EXPECT_LT(result_value(summary, "coupling_energy_error"), 0.1);
    // Particle-steps per second count the SPH sub-steps of every window, not the windows:
    // times the wall time they are the material points times the SPH steps (the particle
    // count is constant here), to the printed digits (12).
    const double point_steps = summary_number(summary, "particle_steps_per_second") *
                               summary_number(summary, "wall_time_s");
    const double expected =
        summary_number(summary, "material_points") * result_value(summary, "coupling_sph_steps");
    EXPECT_NEAR(point_steps, expected, 1e-9 * expected);
    expect_matches_gold(run.out, "cases/sand_on_plate/sand_on_plate_small.toml");
}

// Verification 1 in plane strain: the same layer on a strip 0.4 m long and 0.1 m wide
// (20 x 5 x 5 particles, 6.4 kg), simply supported at its ends, its long edges symmetry lines,
// the sand between frictionless walls: every cross-section bends alike (cylindrical bending).
//  - The strip carries the weight: mean interface load over 0.35-0.5 s less the side walls'
//    push (lattice corrugation, 0.14 N) equals M g to 0.1 %, the acceptance bound (measured
//    -0.03 %).
//  - The deflection is the same across the strip (the plane-strain condition), to 1e-6 of it:
//    the scene is symmetric about y = 0.05 m and the symmetry lines stop any twist (measured
//    equal in every printed digit).
//  - The shell alone under q = M g / (L b) (strip_under_load.toml, the same 16 x 2 mesh) is
//    the beam of the plate's stiffness, w = 5 q L^4 / (384 D) (Timoshenko & Woinowsky-Krieger,
//    section 1), to 1 %: MITC4 converges as h^2 in cylindrical bending (measured -10, -2.5,
//    -0.62, -0.15 % with 4, 8, 16, 32 elements along the span).
//  - The coupled strip sags less than the shell alone under q, by 2.5 % at most: the layer's
//    own bending stiffness (E' H^3 / 12, E' = 19.9 kPa in plane strain) is 1.1 % of the
//    strip's, and the kernel spreads the load by 2h = 52 mm near the supports (measured
//    -1.85 %; -1.7 % at 1 s on 32 elements, when the sloshing has decayed).
TEST(CouplingSmall, SandLayerOnAStripInPlaneStrainBendsItLikeABeam) {
    const CaseRun run =
        run_case_file("cases/sand_on_plate/sand_on_strip_small.toml", "sand_on_strip_small");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const CaseRun alone =
        run_case_file("cases/sand_on_plate/strip_under_load.toml", "strip_under_load");
    ASSERT_EQ(alone.cli.exit_code, 0) << alone.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    const double weight = 500 * 1600.0 * 0.02 * 0.02 * 0.02 * kGravity;
    double time = 0.0;
    const double load = -mean_shell_load_z(run.out, 0.35, time);
    ASSERT_GT(time, 0.1);
    const double side_walls = walls_force_z(summary, {"x0", "x1", "y0", "y1"});
    EXPECT_NEAR(load - side_walls, weight, 1e-3 * weight);
    const double w = result_value(summary, "midspan_deflection");
    EXPECT_NEAR(result_value(summary, "edge_midspan_deflection"), w, 1e-6 * std::abs(w));
    const double d = 210e9 * 0.002 * 0.002 * 0.002 / (12.0 * (1.0 - 0.09));
    const double q = weight / (0.4 * 0.1);
    const double beam = -5.0 * q * std::pow(0.4, 4) / (384.0 * d);
    const double shell = result_value(read_file(alone.out + "/summary.json"), "midspan_deflection");
    std::cout << "sand on strip: mean interface load " << load << " N, side walls " << side_walls
              << " N (weight " << weight << " N), midspan deflection " << w
              << " m, shell alone under q " << shell << " m, beam " << beam << " m\n";
    EXPECT_NEAR(shell, beam, 0.01 * std::abs(beam));
    EXPECT_NEAR(w, shell, 0.025 * std::abs(shell));
    expect_matches_gold(run.out, "cases/sand_on_plate/sand_on_strip_small.toml");
    expect_matches_gold(alone.out, "cases/sand_on_plate/strip_under_load.toml");
}

// The added mass (coupling.added_mass, coupling/added_mass.hpp) on the same strip with the plain
// staggered update (relaxation 1; at 0.5 the case's 10 ms window already runs unstable, energy
// error 0.58 by 0.32 s): springs of 4 m_s / dt^2 on the coupled nodes make the exchange stable,
// and since they carry nothing at rest the strip settles to the deflection of the shell alone
// under the layer's weight, within the 2.5 % of the test above (measured -1.71 % at 1 s, as
// the case without springs: -3.3220 against -3.3224 mm), with an interface energy error below
// the watchdog's 0.05 (measured 0.016; 0.17 for the case at relaxation 0.3 without the
// springs). Run to 1 s: the springs slow the shell's approach to its equilibrium (each window
// closes 1 / (1 + beta g) of the gap, g = 2.7 here), and at 0.5 s it still lagged by 1 %.
TEST(CouplingSmall, TheAddedMassHoldsAStripTheStaggeredExchangeCannotToItsDeflection) {
    const CaseRun run =
        run_case_file("cases/sand_on_plate/sand_on_strip_small.toml", "sand_on_strip_added_mass",
                      "--set coupling.relaxation=1 --set coupling.added_mass=4 "
                      "--set 'case.end_time=1 s'");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const CaseRun alone =
        run_case_file("cases/sand_on_plate/strip_under_load.toml", "strip_under_load_alone");
    ASSERT_EQ(alone.cli.exit_code, 0) << alone.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    const double shell = result_value(read_file(alone.out + "/summary.json"), "midspan_deflection");
    const double w = result_value(summary, "midspan_deflection");
    std::cout << "strip with the added mass: midspan deflection " << w << " m, shell alone "
              << shell << " m, energy error " << result_value(summary, "coupling_energy_error")
              << '\n';
    EXPECT_NEAR(w, shell, 0.025 * std::abs(shell));
    EXPECT_LT(result_value(summary, "coupling_energy_error"), 0.05);
}

// A coupled run stopped at 0.2 s and restarted from its checkpoint writes, at 0.4 s, the
// checkpoint state of the uninterrupted run byte for byte (the SPH particles, the shell's state
// with its committed DOFs, which anchor the added-mass springs, the interface load and the coupling
// monitor's sums; the wall-clock seconds are not in it, so the comparison is exact).
TEST(CouplingSmall, ARestartedCoupledRunWritesTheUninterruptedRunsCheckpoint) {
    const std::string options = "--threads 1 --set coupling.relaxation=1 "
                                "--set coupling.added_mass=4 --set 'case.end_time=0.4 s'";
    const CaseRun whole = run_case_file("cases/sand_on_plate/sand_on_strip_small.toml",
                                        "strip_restart_whole", options);
    ASSERT_EQ(whole.cli.exit_code, 0) << whole.cli.output;
    const CaseRun part =
        run_case_file("cases/sand_on_plate/sand_on_strip_small.toml", "strip_restart_part",
                      options + " --set 'case.end_time=0.2 s'");
    ASSERT_EQ(part.cli.exit_code, 0) << part.cli.output;
    // The later --set wins: the first run stopped half way.
    ASSERT_NE(read_file(part.out + "/summary.json").find("\"simulated_time_s\": 0.2,"),
              std::string::npos);
    const auto resumed = run_cli(
        "run '" + source_path("cases/sand_on_plate/sand_on_strip_small.toml") + "' --out '" +
            part.out + "' --restart '" + part.out + "/checkpoint.bin' " + options,
        part.out + ".resumed.log");
    ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
    // The state, not the streamed files' marks: the log's length depends on the wall clock.
    const std::string expected = checkpoint_state(read_file(whole.out + "/checkpoint.bin"));
    ASSERT_FALSE(expected.empty());
    EXPECT_TRUE(checkpoint_state(read_file(part.out + "/checkpoint.bin")) == expected);
}

// The same scene with the plate's interface rigid (one key): the layer rests on a rigid wall
// where the plate was built and the shell gets no load. The wall's vertical force at 0.5 s
// balances the weight within 0.5 % (the soft layer still sloshes: ±0.2 % measured on a rigid
// floor after 0.15 s), the plate does not move at all, and summary.json says what was modelled.
TEST(CouplingSmall, ARigidInterfaceCarriesTheLayerAndLeavesTheShellAlone) {
    const CaseRun run =
        run_case_file("cases/sand_on_plate/sand_on_plate_small.toml", "sand_on_rigid_plate",
                      "--set coupling.interface[0].rigid=true");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    const double weight = 2000 * 1600.0 * 0.02 * 0.02 * 0.02 * kGravity;
    double walls = 0.0;
    for (const char* wall : {"plate", "x0", "x1", "y0", "y1"}) {
        walls += result_value(summary, std::string("wall_") + wall + "_force_z");
    }
    EXPECT_NEAR(-walls, weight, 5e-3 * weight);
    EXPECT_EQ(result_value(summary, "centre_deflection"), 0.0);
    EXPECT_NE(summary.find("\"wall plate\": \"rigid\""), std::string::npos) << summary;
    // A shell no interface loads reports no stress or deflection as a result: the figures are
    // absent, the hint says the sand's load is not in it, and the frames carry its own loads'
    // arrays under a label (no von_mises_* or contact_pressure a picture would show as the
    // sand's).
    EXPECT_EQ(summary.find("shell_largest_von_mises"), std::string::npos) << summary;
    EXPECT_EQ(summary.find("shell_largest_deflection"), std::string::npos) << summary;
    EXPECT_NE(summary.find("shell (plate): rigid: self-weight only: every interface (plate) is a "
                           "rigid wall, so the sand's load is not in the shell's stresses"),
              std::string::npos)
        << summary;
    const auto plate = read_named_block(frame_path(run.out, "sand_on_plate_small", 5), "plate");
    ASSERT_NE(plate, nullptr);
    EXPECT_EQ(plate->GetCellData()->GetArray("von_mises_top"), nullptr);
    EXPECT_NE(plate->GetCellData()->GetArray("without_sand_von_mises_top"), nullptr);
    EXPECT_EQ(plate->GetPointData()->GetArray("displacement"), nullptr);
    EXPECT_EQ(plate->GetPointData()->GetArray("contact_pressure"), nullptr);

    // A very stiff plate (E x 1000, 1 um deflection: 5e-5 of the spacing) gives the rigid
    // wall's contact pressure ([[sph.wall_map]] "plate", 4 x 4 cells, mean over 0.4-0.5 s) cell
    // by cell: the two scenes differ by that deflection only, so 1e-3 (measured 1.9e-5).
    const CaseRun stiff =
        run_case_file("cases/sand_on_plate/sand_on_plate_small.toml", "sand_on_stiff_plate",
                      "--set 'material[1].youngs_modulus=\"210000 GPa\"'");
    ASSERT_EQ(stiff.cli.exit_code, 0) << stiff.cli.output;
    const auto rigid_map = numeric_csv_rows(run.out + "/wall_maps/plate_window.csv");
    const auto stiff_map = numeric_csv_rows(stiff.out + "/wall_maps/plate_window.csv");
    ASSERT_EQ(rigid_map.size(), 16u);
    ASSERT_EQ(stiff_map.size(), 16u);
    for (std::size_t cell = 0; cell < 16; ++cell) {
        EXPECT_NEAR(stiff_map[cell][4], rigid_map[cell][4], 1e-3 * rigid_map[cell][4])
            << "cell " << cell;
    }
}

// A plate coupled on both faces (`side = "both"`: one layer of wall particles on its
// mid-surface, each facing the particle it pushes) carries the layer on either face: laid on
// top under gravity -z, and mirrored (sand below, gravity +z, the side walls lowered), with the
// part's definition unchanged. The two scenes are mirror images and negation is exact in
// floating point, so the deflections, loads and energies are equal and opposite to round-off
// (1e-9; measured equal in every printed digit). On top, the plate and the side walls carry the
// weight (0.5 %: the layer still sloshes, ±0.2 %, on the rigid floor), and the deflection is
// Navier's within the 3 % of the one-sided plate above (measured -2.6 %).
TEST(CouplingSmall, APlateCoupledOnBothFacesCarriesSandOnEither) {
    const std::string both = "--set 'coupling.interface[0].side=\"both\"' ";
    const CaseRun up =
        run_case_file("cases/sand_on_plate/sand_on_plate_small.toml", "sand_above_two_sided_plate",
                      both + "--set 'sph.body[0].shape.min=\"0 0 42 mm\"' "
                             "--set 'sph.body[0].shape.max=\"400 400 142 mm\"'");
    ASSERT_EQ(up.cli.exit_code, 0) << up.cli.output;
    const CaseRun down =
        run_case_file("cases/sand_on_plate/sand_on_plate_small.toml", "sand_below_two_sided_plate",
                      both + "--set 'sph.body[0].shape.min=\"0 0 -142 mm\"' "
                             "--set 'sph.body[0].shape.max=\"400 400 -42 mm\"' "
                             "--set 'case.gravity=\"0 0 9.81 m/s^2\"' "
                             "--set 'sph.wall[0].origin=\"-32 -80 -160 mm\"' "
                             "--set 'sph.wall[1].origin=\"432 -80 -160 mm\"' "
                             "--set 'sph.wall[2].origin=\"-80 -32 -160 mm\"' "
                             "--set 'sph.wall[3].origin=\"-80 432 -160 mm\"'");
    ASSERT_EQ(down.cli.exit_code, 0) << down.cli.output;
    const std::string a = read_file(up.out + "/summary.json");
    const std::string b = read_file(down.out + "/summary.json");
    for (const char* figure :
         {"centre_deflection", "wall_plate_force_z", "support_reaction_z", "wall_x0_force_z"}) {
        const double value = result_value(a, figure);
        EXPECT_NEAR(result_value(b, figure), -value, 1e-9 * std::abs(value)) << figure;
    }
    EXPECT_NEAR(result_value(b, "kinetic_energy"), result_value(a, "kinetic_energy"),
                1e-9 * result_value(a, "kinetic_energy"));
    const double weight = 2000 * 1600.0 * 0.02 * 0.02 * 0.02 * kGravity;
    EXPECT_NEAR(-walls_force_z(a, {"plate", "x0", "x1", "y0", "y1"}), weight, 5e-3 * weight);
    const double d = 210e9 * 0.002 * 0.002 * 0.002 / (12.0 * (1.0 - 0.09));
    const double navier = -0.00406 * (weight / (0.4 * 0.4)) * std::pow(0.4, 4) / d;
    EXPECT_NEAR(result_value(a, "centre_deflection"), navier, 0.03 * std::abs(navier));
}

// Verification 4 of the coupling: a 0.8 kg block of Drucker-Prager sand at 2 m/s lands on a
// clamped 2 mm steel plate, dynamic (Newmark), each window iterated to convergence.
//  - Impulse: the plate receives what the sand lost: sand momentum change = weight impulse +
//    the walls' impulse on the sand, and the impulse the plate's nodes received equals the
//    sand's impulse on the wall particles (0.5 %, the acceptance bound; the leapfrog's momentum
//    update is trapezoidal like the wall impulse, so the SPH side closes to round-off and the
//    shell side differs by the last window's load only).
//  - Energy: the interface energy error (sand's work on the walls minus the plate's) below
//    1e-3 of the throughput (converged windows and the midpoint load: measured 1e-5), and the
//    books of the whole scene close within 1 % of the initial kinetic energy: sand kinetic +
//    internal (which holds its dissipation) + plate kinetic + strain = initial kinetic +
//    gravity's work on the sand, less the contact potential's share and the SPH ledger's own
//    error (measured 0.7 %).
//  - Nothing passes the plate: every sand particle ends above its upper face.
TEST(CouplingSmall, SandDroppedOnAPlateGivesItItsImpulseAndEnergy) {
    const CaseRun run = run_case_file("cases/sand_drop/sand_drop_small.toml", "sand_drop_small");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    const double mass = 500 * 1600.0 * 1e-6;
    const double t = 0.012;
    const double momentum_change = result_value(summary, "sand_momentum_z") - mass * -2.0;
    const double wall_impulse = result_value(summary, "interface_impulse_z");
    const double shell_impulse = result_value(summary, "shell_impulse_z");
    EXPECT_NEAR(momentum_change, -mass * kGravity * t - wall_impulse,
                1e-9 * std::abs(wall_impulse));
    EXPECT_NEAR(shell_impulse, wall_impulse, 5e-3 * std::abs(wall_impulse));
    // summary.json states that balance itself: shell_impulse_z beside the sand's impulse on the
    // walls as its reference, with the relative error, within the same 0.5 %.
    const FigureReference crossed = figure_reference(summary, "shell_impulse_z");
    EXPECT_EQ(crossed.reference, wall_impulse);
    EXPECT_LT(crossed.relative_error, 5e-3);
    EXPECT_NE(crossed.source.find("momentum conservation across the interface"), std::string::npos);
    EXPECT_LT(std::abs(result_value(summary, "coupling_energy_error")), 1e-3);
    const double initial = 0.5 * mass * 4.0;
    const double held =
        result_value(summary, "kinetic_energy") + result_value(summary, "internal_energy") +
        result_value(summary, "shell_kinetic_energy") +
        result_value(summary, "shell_strain_energy") + result_value(summary, "contact_energy");
    const double put_in = initial + result_value(summary, "gravity_work");
    std::cout << "sand drop: impulse on walls " << wall_impulse << " N s, on the plate "
              << shell_impulse << " N s; energy held " << held << " J, put in " << put_in << " J\n";
    EXPECT_NEAR(held, put_in, 0.01 * initial);
    const auto sand = read_particle_block(frame_path(run.out, "sand_drop_small", 6));
    ASSERT_NE(sand, nullptr);
    double lowest = 1.0;
    for (vtkIdType i = 0; i < sand->GetNumberOfPoints(); ++i) {
        lowest = std::min(lowest, sand->GetPoints()->GetPoint(i)[2]);
    }
    EXPECT_GT(lowest, 0.001); // the plate's upper face (t/2), which it deflects below
    expect_matches_gold(run.out, "cases/sand_drop/sand_drop_small.toml");
}

// The same block at 100 m/s (the fastest impact the coupling is specified for), windows of 0.05 ms:
// the plate, linear elastic, bulges 76 mm under it, and no sand particle ends on its far side. Each
// particle's centre is compared with the deformed plate at the nearest node in plan, plus half the
// thickness (the upper face): a particle through the sheet would be below it by up to a
// spacing. Measured: the smallest clearance over the frames is 1.5 mm from the mid-surface.
TEST(CouplingSmall, ABlockAt100MetresPerSecondDoesNotPassThroughThePlate) {
    const CaseRun run =
        run_case_file("cases/sand_drop/sand_drop_small.toml", "sand_drop_100",
                      "--set 'sph.body[0].velocity=0 0 -100 m/s' --set 'case.end_time=1 ms' --set "
                      "'case.output_interval=0.1 ms' --set 'fem.time_step=0.05 ms'");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    double deepest_plate = 0.0;
    for (int frame = 1; frame <= 10; ++frame) {
        const std::string name = frame_path(run.out, "sand_drop_small", frame);
        const auto sand = read_named_block(name, "sand");
        const auto plate = read_named_block(name, "plate");
        ASSERT_NE(sand, nullptr);
        ASSERT_NE(plate, nullptr);
        for (vtkIdType i = 0; i < sand->GetNumberOfPoints(); ++i) {
            double x[3];
            sand->GetPoint(i, x);
            double nearest = 1e30;
            double face = 0.0;
            for (vtkIdType n = 0; n < plate->GetNumberOfPoints(); ++n) {
                double y[3];
                plate->GetPoint(n, y);
                const double d = (x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]);
                if (d < nearest) {
                    nearest = d;
                    face = y[2] + 0.001;
                }
                deepest_plate = std::min(deepest_plate, y[2]);
            }
            EXPECT_GT(x[2], face) << "particle " << i << " in frame " << frame;
        }
    }
    // The impact is real: the plate went down by several spacings under the block.
    EXPECT_LT(deepest_plate, -0.05);
}

} // namespace
} // namespace grainload::testing

namespace grainload::testing {
namespace {

// A coupled run continued from its checkpoint ends bit for bit where the uninterrupted run
// ends: the checkpoint carries the SPH state, the shell's (Newmark velocities and
// accelerations), the walls' window kinematics and impulses, the interface load and the loads
// the shell had at the window's start. The dynamic, iterated drop is split at 6 ms, in the
// middle of the impact.
TEST(CouplingSmall, RestartOfACoupledRunReproducesTheUninterruptedRun) {
    const std::string base = test_folder("coupling_restart");
    const std::string kase = "'" + source_path("cases/sand_drop/sand_drop_small.toml") + "'";
    std::filesystem::remove_all(base + "_whole");
    std::filesystem::remove_all(base + "_split");
    ASSERT_EQ(run_cli("run " + kase + " --out '" + base + "_whole'", base + ".log").exit_code, 0);
    const auto first = run_cli(
        "run " + kase + " --set 'case.end_time=6 ms' --out '" + base + "_split'", base + ".log");
    ASSERT_EQ(first.exit_code, 0) << first.output;
    const auto second = run_cli("run " + kase + " --out '" + base + "_split' --restart '" + base +
                                    "_split/checkpoint.bin'",
                                base + ".log");
    ASSERT_EQ(second.exit_code, 0) << second.output;
    const std::string frame = "/frames/sand_drop_small_000006.vtm";
    const auto whole = read_particle_block(base + "_whole" + frame);
    const auto split = read_particle_block(base + "_split" + frame);
    ASSERT_EQ(whole->GetNumberOfPoints(), split->GetNumberOfPoints());
    for (vtkIdType i = 0; i < whole->GetNumberOfPoints(); ++i) {
        double a[3];
        double b[3];
        whole->GetPoint(i, a);
        split->GetPoint(i, b);
        EXPECT_TRUE(a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) << "particle " << i;
    }
    const std::string whole_summary = read_file(base + "_whole/summary.json");
    const std::string split_summary = read_file(base + "_split/summary.json");
    for (const char* figure :
         {"centre_deflection", "shell_strain_energy", "interface_impulse_z", "coupling_sand_work",
          "coupling_shell_work", "shell_largest_deflection", "shell_largest_von_mises",
          // The shell's step totals travel in the checkpoint: the split run counts the steps
          // of both its processes, as the whole run does.
          "fem_newton_iterations_last_step", "fem_steps_solved_by_cholmod"}) {
        EXPECT_EQ(result_value(whole_summary, figure), result_value(split_summary, figure))
            << figure;
    }
}

} // namespace
} // namespace grainload::testing

namespace grainload::testing {
namespace {

// `--threads 1` is one thread for the shells' factorisation too: the BLAS under CHOLMOD
// (OpenBLAS) otherwise takes its threads from OPENBLAS_NUM_THREADS or the cores, and its blocked
// updates sum in an order that depends on them. The Janssen silo's first 50 ms (its steel wall
// coupled, the floor's reactions near zero, where a last bit shows) under one and under two
// BLAS threads in the environment write the same wall loads and reactions to the last digit;
// before the run set the BLAS's threads, the floor reaction differed in its 12th digit and
// wall_forces.csv in its rows.
TEST(CouplingSmall, OneThreadIsOneThreadForTheShellsFactorisationToo) {
    const char* before = std::getenv("OPENBLAS_NUM_THREADS");
    const std::string kept = before ? before : "";
    std::vector<CaseRun> runs;
    for (const char* blas : {"1", "2"}) {
        ::setenv("OPENBLAS_NUM_THREADS", blas, 1);
        runs.push_back(run_case_file("cases/silo_janssen/silo_janssen_small.toml",
                                     std::string("blas_threads_") + blas,
                                     "--threads 1 --set 'case.end_time=0.05 s'"));
        ASSERT_EQ(runs.back().cli.exit_code, 0) << runs.back().cli.output;
    }
    if (before) {
        ::setenv("OPENBLAS_NUM_THREADS", kept.c_str(), 1);
    } else {
        ::unsetenv("OPENBLAS_NUM_THREADS");
    }
    EXPECT_EQ(read_file(runs[0].out + "/wall_forces.csv"),
              read_file(runs[1].out + "/wall_forces.csv"));
    EXPECT_EQ(read_file(runs[0].out + "/fem_convergence.csv"),
              read_file(runs[1].out + "/fem_convergence.csv"));
    const std::string one = read_file(runs[0].out + "/summary.json");
    const std::string two = read_file(runs[1].out + "/summary.json");
    for (const char* figure : {"base_a_z", "support_reaction_z"}) {
        EXPECT_EQ(result_value(one, figure), result_value(two, figure)) << figure;
    }
}

} // namespace
} // namespace grainload::testing
