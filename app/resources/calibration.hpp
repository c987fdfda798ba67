#pragma once
// The machine's throughput figures for the cost estimate: a calibration file or built-ins.

#include <string>
#include <string_view>

namespace grainload::app {

/// Throughput figures of this machine, measured by `bench/sph_throughput --calibrate FILE`
/// (the build's calibration.json, docs/user-guide/trade.md) or, without that file, the built-in
/// constants below. Costs are process CPU seconds of one thread, which the load of other
/// processes changes little; the speed-up of several threads is a wall-time ratio, which it
/// changes a lot, so the file records how busy the machine was while it measured.
struct Calibration {
    std::string source = "built-in constants (no calibration file)";
    /// Seconds of one thread per SPH step: per neighbour-list entry between body particles
    /// (each pair within support + skin once: the solver's list holds a pair of one body in one
    /// row, sph/pair_parts.hpp), per entry between a body and
    /// a wall particle (contact, dashpot, friction; wall-wall pairs are not listed), per body
    /// particle (kinematics, stress update, integration) and per wall particle. A block of the
    /// generalized cap sand (cubic spline, Verlet skin 0.1 h, artificial viscosity, no gradient
    /// correction) at h = 1.3 dp and 2.0 dp, above a floor of wall particles far from it and
    /// touching it.
    /// Built-in: bench/sph_throughput --calibrate on the 2-core development machine (process
    /// CPU time of one thread, load average 1-2, 2026-12-03); 2D idle walls were below its
    /// noise.
    double seconds_per_entry_2d = 1.5e-8;
    double seconds_per_body_2d = 9.7e-7;
    double seconds_per_wall_2d = 0.0;
    double seconds_per_contact_entry_2d = 1.9e-7;
    double seconds_per_entry_3d = 4.0e-8;
    double seconds_per_body_3d = 5.9e-7;
    double seconds_per_wall_3d = 2.6e-8;
    double seconds_per_contact_entry_3d = 6.1e-8;
    /// A body's step with the kernel-gradient correction on (sph.kernel_gradient_correction,
    /// the default: a pass more over the entries, a 3 x 3 inverse per particle), and in the total
    /// Lagrangian formulation (sph.formulation; a linear elastic block, correction on, its
    /// reference list built once), over the same block's step without: factors on the entries'
    /// and body particles' costs. Built-in: the median of four calibrations (bench/sph_throughput
    /// --calibrate, the block and its two variants alternated) on the 2-core development machine,
    /// quiet, 2026-12-06: 1.25-1.44 and 1.90-2.29 with the correction, 0.70-0.79 and 1.59-1.79
    /// total Lagrangian.
    double corrected_factor_2d = 1.3;
    double corrected_factor_3d = 2.0;
    double total_lagrangian_factor_2d = 0.75;
    double total_lagrangian_factor_3d = 1.7;
    /// A step's fixed cost, whatever its particles (the parallel loops' entries and exits, the
    /// energy books, the watches): `grainload run` of 4 and 8 free particles, 10 000 steps
    /// against 2000. Built-in: the median of five calibrations on the 2-core development
    /// machine, quiet (2026-12-06: 3.3-4.0e-5 s in 2D, 3.7-4.2e-5 s in 3D); each of the two
    /// dozen parallel loops of a step costs about 2 us there even on one thread (libgomp wakes
    /// its team's futex).
    double seconds_per_step_2d = 3.7e-5;
    double seconds_per_step_3d = 3.8e-5;
    /// A DEM step's fixed cost and its cost per grain (the neighbour list, the contacts, the
    /// integration): `grainload run` of a lone grain, 10 000 steps against 2000, and of 1000
    /// glass beads thrown into a box, 15 000 steps against 12 000, piled on its floor
    /// (bench/support/output_calibration.hpp). Built-in: bench/sph_throughput --calibrate on the
    /// 2-core development machine, quiet, 2026-12-06 (6.8e-6 s and 2.26e-7 s).
    double dem_seconds_per_step = 6.8e-6;
    double dem_seconds_per_grain_step = 2.3e-7;
    /// Speed-up of `threads_measured` threads over one on the SPH step, measured the same way
    /// (best of alternated runs). One below 1 contradicts itself (more threads cannot be slower
    /// on an idle machine: the measurement met a busy one) and is discarded on reading:
    /// threads_measured 1, speedup 1 and `note` says so.
    int threads_measured = 1;
    double speedup = 1.0;
    /// Other processes' mean use of the machine while it measured, in cores (from /proc/stat
    /// less the bench's own CPU time); negative: not recorded.
    double others_load = -1.0;
    /// Whether the bench judged the machine quiet (others_load below kQuietLoad throughout).
    bool quiet = true;
    /// What reading the file changed or doubts ("" when nothing): printed with the source.
    std::string note;
    /// A run's memory besides its particles and shells: the executable, its libraries (VTK),
    /// buffers. Peak resident set of `grainload run` on the CI free fall (128 particles): 22.3
    /// MiB.
    double baseline_bytes = 23.4e6;
    /// Shell FEM, in CPU seconds of the process (app/resources/shell_cost.hpp counts what each is
    /// paid for; CHOLMOD's BLAS may run threads of its own, whose time this includes). Built-in:
    /// bench/sph_throughput --calibrate (a 72 x 72 linear elastic plate of 31 110 free DOFs,
    /// a ShellModel as the coupling drives it) on the 2-core development machine, typical of
    /// four measurements under a load of 7-9 (2026-12-05).
    ///  - a factorisation of the tangent of `shell_factorisation_dofs` free DOFs (CHOLMOD);
    ///    others scale as DOFs^1.5, the nested-dissection bound for a mesh of a surface (George
    ///    1973, "Nested dissection of a regular finite element mesh", SIAM J. Numer. Anal. 10);
    double shell_factorisation_seconds = 0.8;
    double shell_factorisation_dofs = 31110.0;
    ///  - per free DOF, a step of a linear shell whose loads changed, its factorisation kept:
    ///    two residuals K u from the stored stiffness, a back-substitution, and every element's
    ///    stresses evaluated again (the coupling's extremes read them after each window);
    double shell_seconds_per_dof_solved_step = 2.0e-6;
    ///  - per free DOF, a coupled window whose loads did not change: one residual and the
    ///    stresses (a rigid coupled part sends no load, so after the ramp nothing changes);
    double shell_seconds_per_dof_settled_step = 1.1e-6;
    ///  - per element, the element loop with the tangent (a Newton iteration of a shell whose
    ///    tangent changes; also the stored stiffness's one build), and per free DOF a
    ///    back-substitution.
    double shell_seconds_per_element_assembly = 1.5e-4;
    double shell_seconds_per_dof_back_substitution = 1.2e-6;
    /// An output instant (the VTK frame of every block, the checkpoint, the logs), in CPU
    /// seconds: a fixed part and a part per point written (particles, walls and shell nodes).
    /// Built-in: bench/sph_throughput --calibrate (`grainload run` of the granular block of
    /// 3178 and 13 618 points, 51 against 2 output instants) on the 2-core development machine,
    /// between two calibrations under load (3.8 and 7.4 ms, 2.3 and 1.5 us; 2026-12-05).
    double seconds_per_frame = 5.5e-3;
    double seconds_per_frame_point = 1.9e-6;
    /// Bytes per free DOF (the factor), from the 256 x 256 plate of
    /// docs/validation/shell_benchmarks.md (392 194 DOF: 1 654 MiB peak).
    double shell_bytes_per_dof = 4.4e3;
};

/// Other processes' use of the machine below which a calibration counts as quiet [cores]:
/// they then take at most 0.25 / cores of the machine from the measurement on every core
/// (12.5 % on two), so its speed-up is low by at most that share.
inline constexpr double kQuietLoad = 0.25;

/// The "source" of the files bench/sph_throughput --calibrate writes.
inline constexpr std::string_view kCalibrationSource = "bench/sph_throughput --calibrate";

/// Reads the calibration: $GRAINLOAD_CALIBRATION if set, else calibration.json in the build
/// directory of this executable (its directory's parent: build/app/grainload ->
/// build/calibration.json); the built-in constants when neither exists. A file that exists but
/// cannot be read is reported in `source` and the constants are used; a speed-up below 1 is
/// discarded (Calibration::speedup); the costs measured by running the grainload executable
/// (a step's fixed cost, the DEM's, an output instant's) that the file lists as not measured,
/// or whose pair is zero, keep the built-in constants, and `note` says the file is incomplete.
Calibration load_calibration();

/// The calibration as check prints it and summary.json records it: its source, how quiet the
/// machine was, and what was discarded.
std::string describe_calibration(const Calibration& calibration);

} // namespace grainload::app
