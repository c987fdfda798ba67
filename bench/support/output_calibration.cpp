#include "support/output_calibration.hpp"

#include "io/json_value.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <unistd.h>
#include <utility>

namespace grainload::bench {

namespace {

namespace fs = std::filesystem;

struct FrameRun {
    double cpu_seconds = 0.0;
    double points = 0.0;
    bool ran = false; ///< the run exited 0 and wrote its summary
};

/// `grainload run` of `text` with `frames` - 1 output intervals over `end` at steps of `step`
/// (default: 500 steps; `method`.time_step); its summary's CPU time and points; not `ran`
/// (and said so, with the command) when it failed.
FrameRun run_frames(const fs::path& grainload, const std::string& text, double end, int frames,
                    double step = 0.0, const char* method = "sph") {
    const fs::path dir =
        fs::temp_directory_path() / ("grainload_bench_frames_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path file = dir / "case.toml";
    std::ofstream(file) << text;
    char settings[256];
    std::snprintf(settings, sizeof settings,
                  " --set 'case.end_time=%.9g s' --set 'case.output_interval=%.9g s' "
                  "--set '%s.time_step=%.9g s'",
                  end, end / (frames - 1), method, step > 0.0 ? step : end / 500.0);
    const std::string command = grainload.string() + " run '" + file.string() + "' --out '" +
                                (dir / "out").string() + "' --threads 1" + settings +
                                " > /dev/null 2>&1";
    FrameRun run;
    const int status = std::system(command.c_str());
    if (status == 0) {
        const io::JsonValue summary = io::read_json_file((dir / "out" / "summary.json").string());
        run.cpu_seconds = summary.number_at("cpu_time_s").value_or(0.0);
        run.points = summary.number_at("particles").value_or(0.0);
        run.ran = summary.number_at("cpu_time_s").has_value();
    } else {
        std::printf("calibration: `%s` failed (status %d)\n", command.c_str(), status);
    }
    fs::remove_all(dir);
    return run;
}

/// The least CPU time of three runs of `text` (other processes only add to it), alternated
/// with `other`'s three so that a slow spell of the machine meets both. A run that failed
/// stops the rounds and leaves its side not `ran`: its zero CPU time is no least time.
std::pair<FrameRun, FrameRun> least_of_three(const std::function<FrameRun()>& run,
                                             const std::function<FrameRun()>& other) {
    std::pair<FrameRun, FrameRun> least;
    for (int round = 0; round < 3; ++round) {
        const FrameRun a = run();
        const FrameRun b = other();
        if (!a.ran || !b.ran) {
            return {a, b};
        }
        if (round == 0 || a.cpu_seconds < least.first.cpu_seconds) {
            least.first = a;
        }
        if (round == 0 || b.cpu_seconds < least.second.cpu_seconds) {
            least.second = b;
        }
    }
    return least;
}

/// CPU seconds of one frame of `text`: (51 instants - 2 instants) / 49.
FrameRun frame_of(const fs::path& grainload, const std::string& text, double end) {
    const auto [many, few] = least_of_three([&] { return run_frames(grainload, text, end, 51); },
                                            [&] { return run_frames(grainload, text, end, 2); });
    return {std::max(0.0, (many.cpu_seconds - few.cpu_seconds) / 49.0), many.points,
            many.ran && few.ran};
}

/// The grainload executable of this build (build/bench/X -> build/app/grainload); empty when
/// there is none.
fs::path grainload_executable() {
    std::error_code error;
    const fs::path exe = fs::read_symlink("/proc/self/exe", error);
    const fs::path grainload = exe.parent_path().parent_path() / "app" / "grainload";
    if (error || !fs::exists(grainload)) {
        std::printf("calibration: no %s to run\n", grainload.c_str());
        return {};
    }
    return grainload;
}

/// CPU seconds of one step of `text` beyond what its start and two frames cost, from `from` to
/// `to` steps; the run's points.
FrameRun step_of(const fs::path& grainload, const std::string& text, double step,
                 const char* method = "sph", double from = 2000.0, double to = 10000.0) {
    const auto [few, many] =
        least_of_three([&] { return run_frames(grainload, text, from * step, 2, step, method); },
                       [&] { return run_frames(grainload, text, to * step, 2, step, method); });
    return {std::max(0.0, (many.cpu_seconds - few.cpu_seconds) / (to - from)), many.points,
            many.ran && few.ran};
}

} // namespace

StepCosts step_costs(const std::string& tiny_2d, const std::string& tiny_3d, double time_step) {
    StepCosts c;
    const fs::path grainload = grainload_executable();
    if (grainload.empty()) {
        return c;
    }
    const FrameRun two = step_of(grainload, tiny_2d, time_step);
    const FrameRun three = step_of(grainload, tiny_3d, time_step);
    c.per_step_2d = two.cpu_seconds;
    c.per_step_3d = three.cpu_seconds;
    c.measured = two.ran && three.ran;
    std::printf("steps: %.3e s per 2D step, %.3e per 3D step beyond their particles' work\n",
                c.per_step_2d, c.per_step_3d);
    return c;
}

namespace {

/// A DEM case of glass beads of radius 2.5 mm (Hertz-Mindlin, E = 10 MPa, friction 0.5) in a
/// 0.1 m square box: `body` is its [[dem.body]] table's placement. Damped (gamma_n = 3000 1/s)
/// so that beads thrown down pile within 60 ms (a mean of 2.5-2.8 contacts per bead from 60 to
/// 75 ms, where gamma_n = 200 1/s leaves them bouncing, 0.3 contacts a bead).
std::string dem_case(const std::string& body) {
    return "[case]\nend_time = \"1 s\"\n[[material]]\nname = \"glass\"\nmodel = "
           "\"linear_elastic\"\ndensity = \"2500 kg/m^3\"\nyoungs_modulus = \"10 MPa\"\n"
           "poisson_ratio = 0.3\n[dem]\n[dem.contact]\nlaw = \"hertz_mindlin\"\n"
           "gamma_n = \"3000 1/s\"\ngamma_t = \"500 1/s\"\nfriction = 0.5\n[[dem.body]]\n"
           "name = \"beads\"\nmaterial = \"glass\"\nradius = \"2.5 mm\"\n" +
           body +
           "[[dem.wall]]\nname = \"box\"\ntype = \"box\"\nmin = \"0 0 0 m\"\n"
           "max = \"0.1 0.1 10 m\"\n";
}

} // namespace

DemCosts dem_costs() {
    const std::string tiny = dem_case("centre = \"0.05 0.05 5 m\"\n");
    // 1000 beads at solid fraction 0.25: a layer 26 mm deep.
    const std::string packed = dem_case("count = 1000\nmin = \"0 0 0 m\"\n"
                                        "max = \"0.1 0.1 0.0262 m\"\nvelocity = \"0 0 -1 m/s\"\n");
    const double time_step = 5e-6;
    DemCosts c;
    const fs::path grainload = grainload_executable();
    if (grainload.empty()) {
        return c;
    }
    const FrameRun lone = step_of(grainload, tiny, time_step, "dem");
    c.per_step = lone.cpu_seconds;
    const FrameRun step = step_of(grainload, packed, time_step, "dem", 12000.0, 15000.0);
    c.measured = lone.ran && step.ran;
    if (step.points > 0.0) {
        c.per_grain_step = std::max(0.0, (step.cpu_seconds - c.per_step) / step.points);
    }
    std::printf("dem: %.3e s per step and %.3e per grain-step (%.0f grains: %.3e s a step)\n",
                c.per_step, c.per_grain_step, step.points, step.cpu_seconds);
    return c;
}

FrameCosts frame_costs(const std::string& small, const std::string& large, double end) {
    FrameCosts c;
    const fs::path grainload = grainload_executable();
    if (grainload.empty()) {
        return c;
    }
    const FrameRun a = frame_of(grainload, small, end);
    const FrameRun b = frame_of(grainload, large, end);
    c.measured = a.ran && b.ran;
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
