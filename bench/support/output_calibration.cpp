#include "support/output_calibration.hpp"

#include "io/json_value.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace grainload::bench {

namespace {

namespace fs = std::filesystem;

struct FrameRun {
    double cpu_seconds = 0.0;
    double points = 0.0;
};

/// `grainload run` of `text` with `frames` - 1 output intervals over `end`; its summary's CPU
/// time and points; nullopt-like zeros when it failed.
FrameRun run_frames(const fs::path& grainload, const std::string& text, double end, int frames) {
    const fs::path dir =
        fs::temp_directory_path() / ("grainload_bench_frames_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path file = dir / "case.toml";
    std::ofstream(file) << text;
    char settings[256];
    std::snprintf(settings, sizeof settings,
                  " --set 'case.end_time=%.9g s' --set 'case.output_interval=%.9g s' "
                  "--set 'sph.time_step=%.9g s'",
                  end, end / (frames - 1), end / 500.0);
    const std::string command = grainload.string() + " run '" + file.string() + "' --out '" +
                                (dir / "out").string() + "' --threads 1" + settings +
                                " > /dev/null 2>&1";
    FrameRun run;
    if (std::system(command.c_str()) == 0) {
        const io::JsonValue summary = io::read_json_file((dir / "out" / "summary.json").string());
        run.cpu_seconds = summary.number_at("cpu_time_s").value_or(0.0);
        run.points = summary.number_at("particles").value_or(0.0);
    }
    fs::remove_all(dir);
    return run;
}

/// CPU seconds of one frame of `text`: (51 instants - 2 instants) / 49.
FrameRun frame_of(const fs::path& grainload, const std::string& text, double end) {
    const FrameRun many = run_frames(grainload, text, end, 51);
    const FrameRun few = run_frames(grainload, text, end, 2);
    return {std::max(0.0, (many.cpu_seconds - few.cpu_seconds) / 49.0), many.points};
}

} // namespace

FrameCosts frame_costs(const std::string& small, const std::string& large, double end) {
    std::error_code error;
    const fs::path exe = fs::read_symlink("/proc/self/exe", error);
    const fs::path grainload = exe.parent_path().parent_path() / "app" / "grainload";
    FrameCosts c;
    if (error || !fs::exists(grainload)) {
        std::printf("output: no %s to measure frames with\n", grainload.c_str());
        return c;
    }
    const FrameRun a = frame_of(grainload, small, end);
    const FrameRun b = frame_of(grainload, large, end);
    if (b.points > a.points) {
        c.per_point = std::max(0.0, (b.cpu_seconds - a.cpu_seconds) / (b.points - a.points));
    }
    c.per_frame = std::max(0.0, a.cpu_seconds - c.per_point * a.points);
    std::printf("output: %.3e s per frame, %.3e per point (%.0f and %.0f points: %.3e and %.3e "
                "s a frame)\n",
                c.per_frame, c.per_point, a.points, b.points, a.cpu_seconds, b.cpu_seconds);
    return c;
}

} // namespace grainload::bench
