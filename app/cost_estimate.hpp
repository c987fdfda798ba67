#pragma once

#include "io/types.hpp"

#include <optional>
#include <string>

namespace grainload::app {

struct Scene;

/// Throughput figures of this machine, measured by `bench/sph_throughput --calibrate FILE`
/// (the build's calibration.json, docs/user-guide/trade.md) or, without that file, the built-in
/// constants below.
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
    /// Speed-up of `threads_measured` threads over one, measured the same way.
    int threads_measured = 1;
    double speedup = 1.0;
    /// A run's memory besides its particles and shells: the executable, its libraries (VTK),
    /// buffers. Peak resident set of `grainload run` on the CI free fall (128 particles): 22.3
    /// MiB.
    double baseline_bytes = 23.4e6;
    /// Shell FEM: seconds per free DOF and step (assembly, factorisation and solve of one
    /// Newton iteration) and bytes per free DOF (the factor), from the 256 x 256 plate of
    /// docs/validation/shell_benchmarks.md (392 194 DOF: 21.2 s, 1 654 MiB peak). A linear
    /// dynamic shell reuses its factorisation and costs much less: this is an upper bound.
    double shell_seconds_per_dof_step = 5.4e-5;
    double shell_bytes_per_dof = 4.4e3;
};

/// Reads the calibration: $GRAINLOAD_CALIBRATION if set, else calibration.json in the build
/// directory of this executable (its directory's parent: build/app/grainload ->
/// build/calibration.json); the built-in constants when neither exists. A file that exists but
/// cannot be read is reported in `source` and the constants are used.
Calibration load_calibration();

/// What a run of a loaded scene will cost, before it runs.
struct CostEstimate {
    Index sph_particles = 0;  ///< bodies and walls
    Index wall_particles = 0; ///< of which walls
    Index shell_nodes = 0;
    Index shell_dofs = 0;   ///< free DOFs
    double time_step = 0.0; ///< the time loop's step at t = 0 (CFL, window or fixed)
    long long steps = 0;    ///< time-loop steps to end_time at that step
    double sph_steps = 0.0; ///< SPH steps (sub-cycles of coupling windows included)
    double particle_steps = 0.0;
    Index entries = 0;         ///< SPH neighbour-list entries between bodies at t = 0
    Index contact_entries = 0; ///< between a body and a wall particle
    /// Particles the sources create, averaged over the run (each costs a full kernel support)
    double average_created = 0.0;
    /// [[sph.sink]] tables. What those with a declared outlet (outlet_width) take at Beverloo's
    /// rate from the opening is subtracted; the others' is counted to the end time, an upper
    /// bound (docs/user-guide/trade.md)
    int sinks = 0;
    double average_discharged = 0.0; ///< particles the outlets take, averaged over the run
    double outlet_rate = 0.0;        ///< kg/s (kg/m/s in plane strain)
    double outlet_opening = 0.0;     ///< s
    bool outlet_declared = false;
    bool outlet_known = true; ///< the opening time is known before the run
    bool plane_strain = false;
    /// A coupled scene: its window and the staggered exchange's estimated limit
    /// (coupling/window_limits.hpp), the shortest stable window for a static shell, the
    /// longest for a dynamic one (0: no coupling).
    double coupling_window = 0.0;
    double coupling_window_limit = 0.0;
    bool coupling_static = false;
    /// Static shell with the added mass: how long it takes to follow a load change [s]
    /// (coupling/window_limits.hpp, added_mass_lag; 0: none).
    double coupling_added_mass_lag = 0.0;
    int threads = 1;
    double wall_time_s = 0.0;
    double memory_bytes = 0.0;
};

/// The estimate: steps from the stable step at t = 0 held to end_time, landing on every output
/// instant as the driver does (so it is exact for a fixed step and undercounts a CFL run by the
/// speed the material gains: the step is h / (c + |v|)); time per SPH step from the neighbour
/// list at t = 0 (entries, body and wall particles) at the calibrated costs, plus the particles
/// sources create, averaged over the run, each with a full kernel support; and the shell
/// steps; memory from the SPH solver's own heap at t = 0 (SphSolver::bytes) and the shell's
/// DOFs, plus the baseline.
CostEstimate estimate_cost(const Scene& scene, int threads, const Calibration& calibration);

/// The lines `grainload check` prints.
std::string describe_cost(const CostEstimate& estimate, const Calibration& calibration);

/// What the case's trade table (CASE_DIR/CASE_STEM.trade.csv, a copy of a sweep's trade.csv)
/// says its knee costs and loses against its most accurate run; std::nullopt without one.
std::optional<std::string> trade_table_advice(const std::string& case_file);

} // namespace grainload::app
