#include "app/checkpoint.hpp"

#include "io/binary_stream.hpp"
#include "io/checkpoint_file.hpp"

#include <cmath>
#include <filesystem>
#include <istream>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace grainload::app {

namespace {

void write_payload(const Scene& scene, const RunClock& clock, std::ostream& out) {
    io::write_value(out, clock.t);
    io::write_value(out, clock.step);
    io::write_array(out, clock.frame_times);
    io::write_value(out, static_cast<std::uint64_t>(clock.streams.size()));
    for (const io::StreamMark& mark : clock.streams) {
        io::write_string(out, mark.name);
        io::write_value(out, mark.length);
        io::write_value(out, mark.hash);
    }
    for (const auto& stepper : scene.steppers) {
        stepper->write_checkpoint(out);
    }
}

/// A checkpoint is written right after the frame at clock.t, so the clock must name that frame.
void check_clock(const RunClock& clock) {
    bool sound = std::isfinite(clock.t) && clock.t >= 0.0 && clock.step >= 0 &&
                 !clock.frame_times.empty() && clock.frame_times.back() == clock.t;
    for (std::size_t k = 1; sound && k < clock.frame_times.size(); ++k) {
        sound = clock.frame_times[k] > clock.frame_times[k - 1];
    }
    if (!sound) {
        throw std::runtime_error("its clock (time, step, frame times) is not that of a run");
    }
}

/// A stream's name must stay inside the output directory: the restart cuts the file it names.
void check_stream_name(const std::string& name) {
    const std::filesystem::path path(name);
    bool inside = !name.empty() && path.is_relative();
    for (const auto& part : path) {
        inside = inside && part != ".." && part != ".";
    }
    if (!inside || name.find('\0') != std::string::npos) {
        throw std::runtime_error("a streamed file's name is not a path inside the output "
                                 "directory");
    }
}

std::vector<io::StreamMark> read_streams(std::istream& in) {
    // Each mark takes at least its three 8-byte fields.
    const std::uint64_t count = io::read_count(in, 24);
    std::vector<io::StreamMark> marks(static_cast<std::size_t>(count));
    for (io::StreamMark& mark : marks) {
        mark.name = io::read_string(in);
        check_stream_name(mark.name);
        mark.length = io::read_value<std::uint64_t>(in);
        mark.hash = io::read_value<std::uint64_t>(in);
    }
    return marks;
}

RunClock read_payload(Scene& scene, std::istream& in) {
    RunClock clock;
    clock.t = io::read_value<double>(in);
    clock.step = io::read_value<long long>(in);
    io::read_array(in, clock.frame_times);
    check_clock(clock);
    clock.streams = read_streams(in);
    for (const auto& stepper : scene.steppers) {
        stepper->read_checkpoint(in);
    }
    return clock;
}

} // namespace

void write_checkpoint(const Scene& scene, const RunClock& clock, const std::string& path) {
    io::write_checkpoint_file(path, [&](std::ostream& out) { write_payload(scene, clock, out); });
}

RunClock read_checkpoint(Scene& scene, const std::string& path) {
    RunClock clock;
    io::read_checkpoint_file(path, [&](std::istream& in) { clock = read_payload(scene, in); });
    return clock;
}

std::string checkpoint_bytes(const Scene& scene, const RunClock& clock) {
    std::ostringstream payload(std::ios::binary);
    write_payload(scene, clock, payload);
    return io::frame_checkpoint(payload.str());
}

RunClock read_checkpoint_bytes(Scene& scene, std::string_view bytes) {
    RunClock clock;
    io::read_checkpoint_bytes(bytes, "checkpoint",
                              [&](std::istream& in) { clock = read_payload(scene, in); });
    return clock;
}

} // namespace grainload::app
