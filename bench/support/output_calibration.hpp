#pragma once

#include <string>

namespace grainload::bench {

/// A frame's fixed cost and its cost per point written (particle, wall particle or shell node)
/// [CPU s] (app/calibration.hpp, seconds_per_frame and seconds_per_frame_point).
struct FrameCosts {
    double per_frame = 0.0;
    double per_point = 0.0;
};

/// Measured as `grainload run` pays them: the grainload executable of this build (beside the
/// bench: build/bench/X -> build/app/grainload) runs each case text twice, 500 steps of a fixed
/// step with 51 and with 2 output instants, on one thread; the difference of their CPU times
/// (summary.json cpu_time_s) over 49 instants is a frame of that case (the VTK frame of every
/// block, the checkpoint, the logs, and what the allocator gives back meanwhile). Two cases of
/// different sizes (`small`, `large`: case texts whose time step 1/500 of `end` s is stable)
/// separate the fixed part from the part per point; printed with them. Zeros when the
/// executable cannot be run.
FrameCosts frame_costs(const std::string& small, const std::string& large, double end);

} // namespace grainload::bench
