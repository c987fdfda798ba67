#pragma once
// What a run of a loaded scene will cost, estimated before it runs (grainload check).

#include "app/resources/calibration.hpp"
#include "io/types.hpp"

#include <optional>
#include <string>

namespace grainload::app {

struct Scene;

/// Passes an iterated coupling window (max_iterations > 1) is counted with, before the run:
/// the mean, rounded, of the iterated runs measured in docs/validation/coupling.md and
/// docs/user-guide/coupling.md (1.6 to 4.2 passes a window; SPH and DEM, Aitken and IQN-ILS),
/// never more than max_iterations.
inline constexpr double kIteratedPasses = 3.0;

/// What a run of a loaded scene will cost, before it runs.
struct CostEstimate {
    Index sph_particles = 0;  ///< bodies and walls
    Index wall_particles = 0; ///< of which walls
    Index shell_nodes = 0;
    /// DEM grains, their spheres' steps (a clump of n spheres counts n) and the steps' time (the
    /// calibration's fixed cost per step and cost per grain-step of its single spheres).
    Index dem_grains = 0;
    double dem_sphere_steps = 0.0;
    double dem_seconds = 0.0;
    Index shell_dofs = 0;   ///< free DOFs
    double time_step = 0.0; ///< the time loop's step at t = 0 (CFL, window or fixed)
    long long steps = 0;    ///< time-loop steps to end_time (at that step, but for `flow`)
    double sph_steps = 0.0; ///< SPH steps (sub-cycles of coupling windows included)
    double particle_steps = 0.0;
    /// While a declared outlet discharges, the CFL step h / (c + |v|) shrinks with the speed
    /// of the fastest grain: `flow_speed` from `flow_start` to `flow_end` (0: none foreseen).
    double flow_speed = 0.0;
    double flow_start = 0.0;
    double flow_end = 0.0;
    double flow_step = 0.0;    ///< the SPH step then
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
    bool outlet_known = true;     ///< the opening time is known before the run
    bool outlet_earliest = false; ///< the opening is a phase's earliest start
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
    /// Iterated windows (max_iterations > 1): the passes a window is counted with (each pass
    /// reruns the granular sub-steps and solves the shell again) and the most it may take.
    double coupling_passes = 1.0;
    int coupling_max_iterations = 1;
    /// The shells' steps (app/resources/shell_cost.hpp), as summary.json's fem_factorisations and
    /// fem_back_substitutions count them.
    double shell_steps = 0.0;
    double shell_solved_steps = 0.0;
    double shell_factorisations = 0.0;
    double shell_back_substitutions = 0.0;
    int threads = 1;
    double sph_seconds = 0.0;   ///< on `threads` threads
    double shell_seconds = 0.0; ///< one thread: the shell's solver is serial
    double frames = 0.0;        ///< output instants, t = 0 included
    double output_seconds = 0.0;
    double wall_time_s = 0.0; ///< the three together
    double memory_bytes = 0.0;
    std::string calibration; ///< which calibration it used (describe_calibration)
};

/// The estimate: steps from the stable step at t = 0 held to end_time, landing on every output
/// instant as the driver does (so it is exact for a fixed step and undercounts a CFL run by the
/// speed the material gains: the step is h / (c + |v|)), but for the flow of a declared outlet
/// (the fastest grain's speed, CostEstimate::flow_speed); time per SPH step from the neighbour
/// list at t = 0 (entries, body and wall particles) at the calibrated costs, plus the particles
/// sources create and less those outlets take, averaged over the run, each with a full kernel
/// support; and the shell's steps as the run takes them (app/resources/shell_cost.hpp:
/// factorisations counted, a stored stiffness, rigid coupled parts); memory from the SPH solver's
/// own heap at t = 0 (SphSolver::bytes) and the shell's DOFs, plus the baseline.
CostEstimate estimate_cost(const Scene& scene, int threads, const Calibration& calibration);

/// The lines `grainload check` prints.
std::string describe_cost(const CostEstimate& estimate);

/// What the case's trade table (CASE_DIR/CASE_STEM.trade.csv, a copy of a sweep's trade.csv)
/// says its knee costs and loses against its most accurate run; std::nullopt without one.
std::optional<std::string> trade_table_advice(const std::string& case_file);

} // namespace grainload::app
