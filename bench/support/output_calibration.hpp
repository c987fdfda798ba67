#pragma once
// What frames, steps and DEM contacts cost, measured as `grainload run` pays them.

#include <string>

namespace grainload::bench {

/// A frame's fixed cost and its cost per point written (particle, wall particle or shell node)
/// [CPU s] (app/resources/calibration.hpp, seconds_per_frame and seconds_per_frame_point).
struct FrameCosts {
    double per_frame = 0.0;
    double per_point = 0.0;
    bool measured = false; ///< every run it took exited 0 (else the figures are not written)
};

/// Measured as `grainload run` pays them: the grainload executable of this build (beside the
/// bench: build/bench/X -> build/app/grainload) runs each case text twice, 500 steps of a fixed
/// step with 51 and with 2 output instants, on one thread; the difference of their CPU times
/// (summary.json cpu_time_s) over 49 instants is a frame of that case (the VTK frame of every
/// block, the checkpoint, the logs, and what the allocator gives back meanwhile). Two cases of
/// different sizes (`small`, `large`: case texts whose time step 1/500 of `end` s is stable)
/// separate the fixed part from the part per point; printed with them. Not `measured` when
/// the executable is missing or one of its runs failed (a build relinking it meanwhile).
FrameCosts frame_costs(const std::string& small, const std::string& large, double end);

/// A model step's fixed cost, whatever its particles: the parallel loops' entries and exits, the
/// energy books, the watches, the time loop's checks [CPU s of one thread]
/// (app/resources/calibration.hpp, seconds_per_step_2d and _3d).
struct StepCosts {
    double per_step_2d = 0.0;
    double per_step_3d = 0.0;
    bool measured = false;
};

/// Measured as `grainload run` pays them: each case text (a handful of particles, whose own
/// work is negligible; its step `time_step` stable) run on one thread with 2 output instants
/// for 2000 and for 10 000 steps; the difference of their CPU times over 8000 steps. Not `measured`
/// when the executable cannot be run.
StepCosts step_costs(const std::string& tiny_2d, const std::string& tiny_3d, double time_step);

/// A DEM step's cost: a fixed part, whatever its grains (its passes' loops, the books), and a
/// part per grain (the neighbour list, the contact laws, the integration)
/// [CPU s of one thread] (app/resources/calibration.hpp, dem_seconds_per_step and
/// dem_seconds_per_grain_step).
struct DemCosts {
    double per_step = 0.0;
    double per_grain_step = 0.0;
    bool measured = false;
};

/// Measured as `grainload run` pays them, on one thread with 2 output instants, at a fixed step
/// of 5 us: a grain falling alone (its own work negligible) for 2000 and for 10 000 steps, the
/// difference over 8000 steps the fixed part; 1000 glass beads of radius 2.5 mm thrown down at
/// 1 m/s into a 0.1 m square box from a layer at solid fraction 0.25 (Hertz-Mindlin with
/// friction, damped), for 12 000 and 15 000 steps, when they have piled on the floor (from
/// 60 ms: 2.5-2.8 contacts a bead, the regime of a silo or a hopper):
/// the difference over the grains and 3000 steps, less the fixed part, the part per grain.
/// Not `measured` when the executable cannot be run.
DemCosts dem_costs();

} // namespace grainload::bench
