#pragma once
// The run's ParaView time series: a .vtm multiblock per frame and the .pvd that lists them.

#include "io/frame.hpp"

#include <string>
#include <vector>

namespace grainload::io {

/// Writes one ParaView time series: per frame a .vtm multiblock (SPH bodies as .vtp vertex
/// clouds, shells as .vtu) under DIR/frames/, and DIR/<case>.pvd listing every frame with its
/// time. Pieces use VTK's XML writers (appended raw binary, zlib). Every file is written under a
/// temporary name and renamed, and the .pvd is rewritten last, so it only ever lists complete
/// frames.
class VtkFrameWriter {
  public:
    VtkFrameWriter(std::string directory, std::string case_name);

    /// Write `frame`; returns the path of its .vtm file.
    std::string write(const Frame& frame);
    /// Frames written so far (index, time); restored on restart so the .pvd stays complete.
    void set_history(std::vector<double> times) { times_ = std::move(times); }
    const std::vector<double>& times() const { return times_; }
    /// Path of the newest complete frame's .vtm; empty before the first frame.
    std::string last_frame_path() const;

  private:
    std::string frame_stem(std::size_t index) const;
    void write_block(const Block& block, const std::string& path) const;
    void write_multiblock_index(const Frame& frame, std::size_t index) const;
    void write_collection() const;

    std::string directory_;
    std::string case_name_;
    std::vector<double> times_;
};

} // namespace grainload::io
