#include "app/run_driver.hpp"

#include "app/progress_reporter.hpp"
#include "app/scene.hpp"
#include "io/atomic_file.hpp"
#include "io/binary_stream.hpp"
#include "io/run_summary.hpp"
#include "io/version.hpp"
#include "io/vtk_frame_writer.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <omp.h>

namespace grainload::app {

namespace {

constexpr std::uint64_t kCheckpointMagic = 0x474c434b50543031; // "GLCKPT01"

/// The mutable part of a run that a checkpoint must carry besides the models.
struct RunClock {
    double t = 0.0;
    long long step = 0;
    std::vector<double> frame_times;
};

io::Frame collect_frame(const Scene& scene, double t) {
    io::Frame frame;
    frame.time = t;
    for (const auto& stepper : scene.steppers) {
        stepper->append_blocks(frame);
    }
    return frame;
}

void write_checkpoint(const Scene& scene, const RunClock& clock, const std::string& path) {
    io::write_file_atomically(
        path,
        [&](std::ostream& out) {
            io::write_value(out, kCheckpointMagic);
            io::write_value(out, clock.t);
            io::write_value(out, clock.step);
            io::write_array(out, clock.frame_times);
            for (const auto& stepper : scene.steppers) {
                stepper->write_checkpoint(out);
            }
        },
        true);
}

RunClock read_checkpoint(Scene& scene, const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in || io::read_value<std::uint64_t>(in) != kCheckpointMagic) {
        throw io::CaseError(path + ": not a grainload checkpoint");
    }
    RunClock clock;
    clock.t = io::read_value<double>(in);
    clock.step = io::read_value<long long>(in);
    io::read_array(in, clock.frame_times);
    for (const auto& stepper : scene.steppers) {
        stepper->read_checkpoint(in);
    }
    return clock;
}

double stable_step(const Scene& scene) {
    double dt = std::numeric_limits<double>::infinity();
    for (const auto& stepper : scene.steppers) {
        dt = std::min(dt, stepper->stable_time_step());
    }
    return std::isfinite(dt) ? dt : scene.settings.output_interval;
}

std::optional<std::string> diagnose(const Scene& scene) {
    for (const auto& stepper : scene.steppers) {
        if (auto problem = stepper->diagnose()) {
            return std::string(stepper->name()) + ": " + *problem;
        }
    }
    return std::nullopt;
}

io::RunSummary make_summary(const Scene& scene, const CommandLine& line, const RunClock& clock,
                            double wall_time) {
    io::RunSummary summary;
    summary.case_name = scene.settings.name;
    summary.case_file = line.input;
    summary.threads = omp_get_max_threads();
    summary.wall_time = wall_time;
    summary.simulated_time = clock.t;
    summary.steps = clock.step;
    summary.points = scene.point_count();
    summary.material_points = scene.material_point_count();
    for (const auto& stepper : scene.steppers) {
        stepper->append_results(clock.t, summary.results);
    }
    return summary;
}

} // namespace

int check_case(const CommandLine& line) {
    const auto scene = Scene::load(line.input, line.overrides);
    std::cout << line.input << ": ok (case \"" << scene->settings.name << "\", "
              << scene->settings.dimension << "D, " << scene->materials.size() << " materials, "
              << scene->point_count() << " particles and nodes, end time "
              << scene->settings.end_time << " s)\n";
    return kExitOk;
}

int run_case(const CommandLine& line) {
    if (line.threads) {
        omp_set_num_threads(*line.threads);
    }
    auto scene = Scene::load(line.input, line.overrides);
    const std::string out = line.out.value_or("out/" + scene->settings.name);
    std::filesystem::create_directories(out);
    std::ofstream log(out + "/log.txt", line.restart ? std::ios::app : std::ios::trunc);
    for (const auto& stepper : scene->steppers) {
        stepper->set_output_directory(out);
    }
    io::VtkFrameWriter writer(out, scene->settings.name);
    RunClock clock;
    if (line.restart) {
        clock = read_checkpoint(*scene, *line.restart);
        writer.set_history(clock.frame_times);
    }
    ProgressReporter progress(log, scene->settings.end_time, scene->material_point_count());
    progress.message("grainload " + std::string(kVersion) + " (" + kGitHash + "): case " +
                     scene->settings.name + ", " + std::to_string(scene->point_count()) +
                     " points, " + std::to_string(omp_get_max_threads()) + " threads, output " +
                     out);
    const std::string checkpoint = out + "/checkpoint.bin";
    auto write_output = [&] {
        writer.write(collect_frame(*scene, clock.t));
        clock.frame_times = writer.times();
        write_checkpoint(*scene, clock, checkpoint);
        for (const auto& stepper : scene->steppers) {
            stepper->write_logs(out);
        }
    };
    if (clock.frame_times.empty()) {
        write_output();
    }
    // Output instants are k * interval, computed afresh rather than accumulated, so that a
    // restarted run steps through exactly the same instants (and time steps) as a whole run.
    // An end time within round-off of an instant is that instant: "0.15 s" is 2e-17 s short of
    // 3 * 0.05, and a run stopped there and restarted would otherwise take different steps.
    const double end_tolerance = 1e-12 * scene->settings.end_time;
    auto next_output_time = [&] {
        const double instant =
            scene->settings.output_interval * static_cast<double>(clock.frame_times.size());
        return instant < scene->settings.end_time + end_tolerance ? instant
                                                                  : scene->settings.end_time;
    };
    double dt = 0.0;
    while (clock.t < scene->settings.end_time - end_tolerance) {
        const double next_output = next_output_time();
        dt = std::min(stable_step(*scene), next_output - clock.t);
        for (const auto& stepper : scene->steppers) {
            stepper->advance(clock.t, dt);
        }
        clock.t += dt;
        ++clock.step;
        if (auto problem = diagnose(*scene)) {
            auto summary = make_summary(*scene, line, clock, progress.elapsed_seconds());
            summary.status = "unstable";
            summary.diagnosis = *problem;
            io::write_run_summary(summary, out + "/summary.json");
            progress.message("grainload: the run became unstable at t = " +
                             std::to_string(clock.t) + " s (step " + std::to_string(clock.step) +
                             "): " + *problem + "\nlast good frame: " + writer.last_frame_path() +
                             "\ncheckpoint of that frame: " + checkpoint);
            return kExitUnstable;
        }
        if (clock.t >= next_output - end_tolerance) {
            clock.t = next_output;
            write_output();
        }
        progress.update(clock.t, clock.step, dt);
    }
    progress.update(clock.t, clock.step, dt, true);
    const auto summary = make_summary(*scene, line, clock, progress.elapsed_seconds());
    io::write_run_summary(summary, out + "/summary.json");
    progress.message("done: " + std::to_string(clock.step) + " steps, " +
                     std::to_string(summary.wall_time) + " s wall time; " + out +
                     "/summary.json, " + out + "/" + scene->settings.name + ".pvd");
    return kExitOk;
}

} // namespace grainload::app
