#include "app/run_driver.hpp"

#include "app/checkpoint.hpp"
#include "app/cost_estimate.hpp"
#include "app/progress_reporter.hpp"
#include "app/resources/blas_threads.hpp"
#include "app/resources/openmp_wait.hpp"
#include "app/resources/thread_count.hpp"
#include "app/scene.hpp"
#include "io/atomic_file.hpp"
#include "io/case_error.hpp"
#include "io/output_streams.hpp"
#include "io/run_summary.hpp"
#include "io/step_collapse.hpp"
#include "io/version.hpp"
#include "io/vtk_frame_writer.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <limits>
#include <omp.h>
#include <sstream>
#include <sys/resource.h>

namespace grainload::app {

namespace {

/// This process's CPU time, all threads [s].
double process_cpu_seconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

io::Frame collect_frame(const Scene& scene, double t) {
    io::Frame frame;
    frame.time = t;
    for (const io::Reporter* reporter : scene.reporters) {
        reporter->append_blocks(frame);
    }
    return frame;
}

double stable_step(const Scene& scene) {
    double dt = std::numeric_limits<double>::infinity();
    for (const auto& stepper : scene.steppers) {
        dt = std::min(dt, stepper->stable_time_step());
    }
    return std::isfinite(dt) ? dt : scene.settings.output_interval;
}

/// Advances every stepper. A numerical failure that a module reports by throwing (a singular
/// stiffness matrix, a material point whose iteration diverges) is a diagnosis like any other:
/// the run stops with exit code 3, its summary and its last good frame and checkpoint.
std::optional<std::string> advance(Scene& scene, double t, double dt) {
    for (const auto& stepper : scene.steppers) {
        try {
            stepper->advance(t, dt);
        } catch (const io::CaseError&) {
            throw;
        } catch (const std::runtime_error& error) {
            return std::string(stepper->name()) + ": " + error.what();
        }
    }
    return std::nullopt;
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
    summary.overrides = line.overrides;
    summary.threads = omp_get_max_threads();
    summary.wall_time = wall_time;
    summary.simulated_time = clock.t;
    summary.steps = clock.step;
    summary.points = scene.point_count();
    summary.material_points = scene.material_point_count();
    summary.material_point_steps = clock.material_point_steps;
    summary.shell_nodes = scene.shell_node_count();
    summary.shell_node_steps = clock.shell_node_steps;
    for (const io::Reporter* reporter : scene.reporters) {
        reporter->append_results(clock.t, summary.results);
        reporter->describe_model(summary.model);
        reporter->append_hints(summary.hints);
        reporter->append_phases(summary.phases);
    }
    io::apply_figure_references(scene.references, summary.results);
    return summary;
}

void attach(io::RunSummary& summary, const std::optional<CostEstimate>& estimate) {
    if (estimate) {
        summary.estimated_steps = static_cast<double>(estimate->steps);
        summary.estimated_wall_time = estimate->wall_time_s;
        if (estimate->shell_steps > 0.0) {
            summary.estimated_factorisations = estimate->shell_factorisations;
            summary.estimated_back_substitutions = estimate->shell_back_substitutions;
        }
        summary.estimate_calibration = estimate->calibration;
    }
}

/// The watchdog's exit: summary.json with status "unstable" and the one-line diagnosis, and
/// the message naming the last good frame and its checkpoint, which the run wrote together.
int stop_unstable(const Scene& scene, const CommandLine& line, const RunClock& clock,
                  std::string problem, const std::string& last_frame,
                  const std::optional<CostEstimate>& estimate, ProgressReporter& progress) {
    std::replace(problem.begin(), problem.end(), '\n', ' ');
    const std::string out = line.out.value_or("out/" + scene.settings.name);
    auto summary = make_summary(scene, line, clock, progress.elapsed_seconds());
    attach(summary, estimate);
    summary.status = "unstable";
    summary.diagnosis = problem;
    io::write_run_summary(summary, out + "/summary.json");
    std::ostringstream message;
    message.precision(9);
    message << "grainload: the run became unstable at t = " << clock.t << " s (step " << clock.step
            << "): " << problem << "\nlast good frame: " << last_frame
            << "\ncheckpoint of that frame: " << out << "/checkpoint.bin";
    progress.message(message.str());
    return kExitUnstable;
}

/// The clock of the checkpoint at `path`, the scene restored from it, the frame writer's
/// history, and the run's streamed files cut back to where the checkpoint found them. Refused
/// (io::CaseError, exit code 2) before any file is touched: a checkpoint past the case's end time
/// (there would be nothing to run and no frame at the end time), and an output directory that
/// does not hold the run up to the checkpoint (its last frame, its streamed files as the run
/// wrote them): a restart continues the run where it was written.
RunClock restart_from(Scene& scene, const std::string& path, io::OutputStreams& streams,
                      io::VtkFrameWriter& writer) {
    RunClock clock = read_checkpoint(scene, path);
    const double end = scene.settings.end_time;
    if (clock.t > end * (1.0 + 1e-12)) {
        std::ostringstream message;
        message.precision(9);
        message << "the end time " << end << " s lies before the time of the checkpoint " << path
                << ", " << clock.t << " s: a restart continues a run, so the end time must be at "
                << "least " << clock.t << " s";
        scene.document->root().table("case").fail("end_time", message.str());
    }
    writer.set_history(clock.frame_times);
    const std::string restart_here = "restart in the output directory of the run that wrote it "
                                     "(copy that directory to continue the run elsewhere)";
    if (!std::filesystem::exists(writer.last_frame_path())) {
        throw io::CaseError(path + ": restart refused: the frame of the checkpoint, " +
                            writer.last_frame_path() + ", is not in the output directory " +
                            streams.directory() + "; " + restart_here);
    }
    try {
        streams.resume(clock.streams);
    } catch (const std::runtime_error& error) {
        throw io::CaseError(path + ": restart refused: " + error.what() + "; " + restart_here);
    }
    return clock;
}

} // namespace

int check_case(const CommandLine& line) {
    const auto scene = Scene::load(line.input, line.overrides);
    std::cout << line.input << ": ok (case \"" << scene->settings.name << "\", "
              << scene->settings.dimension << "D, " << scene->materials.size() << " materials, "
              << scene->point_count() << " particles and nodes, end time "
              << scene->settings.end_time << " s)\n";
    // What will be modelled, as summary.json's "model" block will say it.
    std::vector<io::ModelChoice> model;
    for (const io::Reporter* reporter : scene->reporters) {
        reporter->describe_model(model);
    }
    std::cout << "model:";
    for (std::size_t k = 0; k < model.size(); ++k) {
        std::cout << (k == 0 ? " " : "; ") << model[k].item << ": " << model[k].choice;
    }
    std::cout << '\n';
    const Calibration calibration = load_calibration();
    const int threads =
        line.auto_threads ? auto_threads() : line.threads.value_or(omp_get_max_threads());
    const CostEstimate cost = estimate_cost(*scene, threads, calibration);
    std::cout << describe_cost(cost);
    // An hour is where a cheaper setting starts to matter: say what the trade table
    // measured, or how to make one.
    constexpr double kLongRun = 3600.0;
    if (cost.wall_time_s > kLongRun) {
        const auto advice = trade_table_advice(line.input);
        std::cout << "      longer than an hour: "
                  << advice.value_or("no trade table next to the case; `grainload trade` measures "
                                     "what cheaper settings cost and lose (docs/user-guide/"
                                     "trade.md)")
                  << '\n';
    }
    return kExitOk;
}

namespace {

/// What one run of a case works with, from its start (or checkpoint) to its end.
struct CaseRun {
    const CommandLine& line;
    Scene& scene;
    const std::optional<CostEstimate>& estimate;
    std::string out;
    io::OutputStreams& streams;
    io::VtkFrameWriter& writer;
    RunClock& clock;
    ProgressReporter& progress;
    /// An end time within round-off of an output instant is that instant: "0.15 s" is 2e-17 s
    /// short of 3 * 0.05, and a run stopped there and restarted would otherwise take other
    /// steps.
    double end_tolerance = 0.0;
};

/// The log's first lines: the build, the case, its threads and output, and a restart's point.
void announce(CaseRun& run) {
    run.progress.message("grainload " + std::string(kVersion) + " (" + kGitHash + "): case " +
                         run.scene.settings.name + ", " + std::to_string(run.scene.point_count()) +
                         " points, " + std::to_string(omp_get_max_threads()) +
                         (omp_get_max_threads() == 1 ? " thread" : " threads") +
                         (run.line.auto_threads ? " (auto: the cores free at start)" : "") +
                         ", output " + run.out);
    if (run.line.restart) {
        std::ostringstream restarted;
        restarted.precision(9);
        restarted << "restarted from " << *run.line.restart << " at t = " << run.clock.t
                  << " s (step " << run.clock.step << "); every streamed file continues from it";
        run.progress.message(restarted.str());
    }
}

/// A frame, then the modules' logs, then the checkpoint, which records where every streamed
/// file then stands: a restart cuts the files back to exactly that.
void write_output(CaseRun& run) {
    run.writer.write(collect_frame(run.scene, run.clock.t));
    run.clock.frame_times = run.writer.times();
    for (const io::Reporter* reporter : run.scene.reporters) {
        reporter->write_logs();
    }
    run.clock.streams = run.streams.marks();
    write_checkpoint(run.scene, run.clock, run.out + "/checkpoint.bin");
}

/// Output instants are k * interval, computed afresh rather than accumulated, so that a
/// restarted run steps through exactly the same instants (and time steps) as a whole run.
double next_output_time(const CaseRun& run) {
    const io::SceneSettings& settings = run.scene.settings;
    const double instant =
        settings.output_interval * static_cast<double>(run.clock.frame_times.size());
    return instant < settings.end_time + run.end_tolerance ? instant : settings.end_time;
}

/// The time loop to the end time; the watchdog's exit code when a step fails or the step
/// collapses, else std::nullopt. `dt` holds the last step.
std::optional<int> step_to_the_end(CaseRun& run, double& dt) {
    Scene& scene = run.scene;
    RunClock& clock = run.clock;
    io::StepCollapseWatch step_watch;
    while (clock.t < scene.settings.end_time - run.end_tolerance) {
        const double next_output = next_output_time(run);
        const double stable = stable_step(scene);
        if (auto collapse = step_watch.record(stable, clock.t)) {
            return stop_unstable(scene, run.line, clock, *collapse, run.writer.last_frame_path(),
                                 run.estimate, run.progress);
        }
        dt = std::min(stable, next_output - clock.t);
        const auto points = static_cast<double>(scene.material_point_count());
        const long long inner_before = scene.inner_steps();
        std::optional<std::string> failure = advance(scene, clock.t, dt);
        // A coupled window holds many SPH steps: count those, not the window.
        const long long inner = scene.inner_steps() - inner_before;
        clock.material_point_steps += points * static_cast<double>(inner > 0 ? inner : 1);
        clock.shell_node_steps += static_cast<double>(scene.shell_node_count());
        clock.t += dt;
        ++clock.step;
        for (io::Reporter* reporter : scene.reporters) {
            for (const std::string& event : reporter->take_events()) {
                run.progress.message(event);
            }
        }
        if (auto problem = failure ? failure : diagnose(scene)) {
            return stop_unstable(scene, run.line, clock, *problem, run.writer.last_frame_path(),
                                 run.estimate, run.progress);
        }
        if (clock.t >= next_output - run.end_tolerance) {
            clock.t = next_output;
            write_output(run);
        }
        run.progress.update(clock.t, clock.step, dt, clock.material_point_steps);
    }
    return std::nullopt;
}

/// summary.json, the hints, and the closing lines with the estimate against the run.
void finish(CaseRun& run, double cpu_start) {
    auto summary = make_summary(run.scene, run.line, run.clock, run.progress.elapsed_seconds());
    summary.cpu_time = process_cpu_seconds() - cpu_start;
    attach(summary, run.estimate);
    io::write_run_summary(summary, run.out + "/summary.json");
    for (const std::string& hint : summary.hints) {
        run.progress.message("hint: " + hint);
    }
    run.progress.message("done: " + std::to_string(run.clock.step) + " steps, " +
                         std::to_string(summary.wall_time) + " s wall time; " + run.out +
                         "/summary.json, " + run.out + "/" + run.scene.settings.name + ".pvd");
    if (const auto& estimate = run.estimate) {
        run.progress.message(
            "estimate before the run: " + std::to_string(estimate->steps) + " steps, " +
            std::to_string(estimate->wall_time_s) + " s (actual / estimate: steps " +
            std::to_string(static_cast<double>(run.clock.step) /
                           static_cast<double>(estimate->steps)) +
            ", wall time " +
            (estimate->wall_time_s > 0.0 ? std::to_string(summary.wall_time / estimate->wall_time_s)
                                         : std::string("not estimated")) +
            ")");
    }
}

} // namespace

int run_case(const CommandLine& line) {
    if (line.auto_threads) {
        omp_set_num_threads(auto_threads());
    } else if (line.threads) {
        omp_set_num_threads(*line.threads);
    }
    follow_blas_threads(omp_get_max_threads());
    auto scene = Scene::load(line.input, line.overrides);
    // The estimate `check` prints, kept for summary.json's estimate-against-actual ratios (a
    // restarted run covers only part of the time, so it has none).
    std::optional<CostEstimate> estimate;
    if (!line.restart) {
        estimate = estimate_cost(*scene, omp_get_max_threads(), load_calibration());
    }
    const std::string out = line.out.value_or("out/" + scene->settings.name);
    std::filesystem::create_directories(out);
    io::OutputStreams streams(out);
    io::VtkFrameWriter writer(out, scene->settings.name);
    RunClock clock;
    if (line.restart) {
        clock = restart_from(*scene, *line.restart, streams, writer);
    }
    for (io::Reporter* reporter : scene->reporters) {
        reporter->set_output(streams);
    }
    ProgressReporter progress(streams.open("log.txt"), scene->settings.end_time);
    const double cpu_start = process_cpu_seconds();
    CaseRun run{line,  *scene,   estimate,
                out,   streams,  writer,
                clock, progress, 1e-12 * scene->settings.end_time};
    announce(run);
    if (clock.frame_times.empty()) {
        write_output(run);
    }
    double dt = 0.0;
    if (const auto stopped = step_to_the_end(run, dt)) {
        return *stopped;
    }
    progress.update(clock.t, clock.step, dt, clock.material_point_steps, true);
    finish(run, cpu_start);
    return kExitOk;
}

} // namespace grainload::app
