#pragma once
// Checkpoints of a run: the run clock and every module's state, written and restored.

#include "app/scene.hpp"
#include "io/output_streams.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace grainload::app {

/// The mutable part of a run that a checkpoint must carry besides the models.
struct RunClock {
    double t = 0.0;
    long long step = 0;
    std::vector<double> frame_times;
    /// Where each streamed file stood when the checkpoint was written (io/output_streams.hpp).
    std::vector<io::StreamMark> streams;
    /// Material points summed over this process's steps (particles leaving through a sink stop
    /// counting), for the particle-steps per second of its wall time; not checkpointed.
    double material_point_steps = 0.0;
    /// Shell nodes summed over this process's steps, likewise.
    double shell_node_steps = 0.0;
};

/// Write the clock and every module's state to `path` (framing and checksum:
/// io/checkpoint_file.hpp), atomically.
void write_checkpoint(const Scene& scene, const RunClock& clock, const std::string& path);

/// Restore `scene` from `path` and return the clock. A truncated or corrupted file, one of
/// another case, or a directory throws io::CaseError naming the file (exit code 2).
RunClock read_checkpoint(Scene& scene, const std::string& path);

/// The bytes write_checkpoint would write (for the fuzz harness and tests).
std::string checkpoint_bytes(const Scene& scene, const RunClock& clock);

/// Same as read_checkpoint, from a checkpoint held in memory (for the fuzz harness).
RunClock read_checkpoint_bytes(Scene& scene, std::string_view bytes);

} // namespace grainload::app
