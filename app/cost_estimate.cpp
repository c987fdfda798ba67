#include "app/cost_estimate.hpp"

#include "app/resources/discharge_estimate.hpp"
#include "app/resources/shell_cost.hpp"
#include "app/resources/step_plan.hpp"
#include "app/scene.hpp"
#include "app/trade/trade_table.hpp"
#include "coupling/coupled_model.hpp"
#include "coupling/dem_coupled_model.hpp"
#include "dem/dem_model.hpp"
#include "fem/shell_model.hpp"
#include "io/json_value.hpp"
#include "sph/sph_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <vector>

namespace grainload::app {

namespace {

namespace fs = std::filesystem;

/// Neighbour-list entries at t = 0 between bodies, and between a body and a wall particle.
std::pair<Index, Index> count_entries(const sph::SphModel& sph) {
    if (sph.solver() == nullptr) {
        return {0, 0};
    }
    const auto& wall_id = sph.particles().wall_id;
    const particles::NeighbourList& list = sph.solver()->neighbours();
    Index bodies = 0;
    Index contacts = 0;
    const Index n = sph.particles().size();
    for (Index i = 0; i < n; ++i) {
        for (const auto j : list.neighbours(i)) {
            // Entries from n on are mirror images of material particles (symmetry planes).
            const bool contact = wall_id[static_cast<std::size_t>(i)] >= 0 ||
                                 (j < n && wall_id[static_cast<std::size_t>(j)] >= 0);
            (contact ? contacts : bodies) += 1;
        }
    }
    return {bodies, contacts};
}

std::string duration(double s) {
    char text[48];
    if (s < 10.0) {
        std::snprintf(text, sizeof text, "%.2g s", s);
    } else if (s < 120.0) {
        std::snprintf(text, sizeof text, "%.0f s", s);
    } else if (s < 7200.0) {
        std::snprintf(text, sizeof text, "%.0f min", s / 60.0);
    } else {
        std::snprintf(text, sizeof text, "%.1f h", s / 3600.0);
    }
    return text;
}

} // namespace

namespace {

/// Neighbour-list entries of a particle inside a body: the sites of its lattice (the bodies'
/// spacing) within the list's radius (support + Verlet skin), itself excluded, halved: the list
/// holds a pair of one body once (sph/pair_parts.hpp).
double bulk_entries(const sph::SphModel& sph) {
    const sph::SphOptions& options = sph.solver()->options();
    const double radius = sph.solver()->kernel().support_radius() +
                          options.verlet_skin_factor * options.smoothing_length;
    const double reach = radius / sph.spacing();
    const int n = static_cast<int>(std::floor(reach));
    const bool two_d = sph.dimension() == 2;
    double sites = 0.0;
    for (int i = -n; i <= n; ++i) {
        for (int j = -n; j <= n; ++j) {
            for (int k = two_d ? 0 : -n; k <= (two_d ? 0 : n); ++k) {
                sites += i * i + j * j + k * k < reach * reach ? 1.0 : 0.0;
            }
        }
    }
    return 0.5 * (sites - 1.0);
}

/// The calibrated factor on the entries' and body particles' costs for the solver's
/// formulation and kernel-gradient correction (1 for the calibration's own block).
double formulation_factor(const sph::SphOptions& options, const Calibration& c) {
    const bool two_d = options.dimension == 2;
    if (options.formulation == sph::Formulation::total_lagrangian) {
        return two_d ? c.total_lagrangian_factor_2d : c.total_lagrangian_factor_3d;
    }
    if (options.kernel_gradient_correction) {
        return two_d ? c.corrected_factor_2d : c.corrected_factor_3d;
    }
    return 1.0;
}

/// Seconds of one thread per SPH step of a model at the calibrated costs, averaged over a run
/// in which sources add `created` particles on average (each with a full kernel support; less
/// what the outlets take, which can make it negative); fills the counts.
double sph_seconds_per_step(const sph::SphModel& sph, double created, const Calibration& c,
                            CostEstimate& e) {
    const Index n = sph.point_count();
    const auto& wall_id = sph.particles().wall_id;
    const auto walls = static_cast<Index>(
        std::count_if(wall_id.begin(), wall_id.end(), [](int w) { return w >= 0; }));
    const auto [entries, contacts] = count_entries(sph);
    e.sph_particles += n;
    e.plane_strain = sph.dimension() == 2;
    e.wall_particles += walls;
    e.entries += entries;
    e.contact_entries += contacts;
    if (sph.solver() == nullptr) {
        // Free flight (interactions = false): a position update per particle, nanoseconds,
        // negligible beside the frames.
        return 0.0;
    }
    const bool two_d = sph.dimension() == 2;
    const double factor = formulation_factor(sph.solver()->options(), c);
    const double per_entry = factor * (two_d ? c.seconds_per_entry_2d : c.seconds_per_entry_3d);
    const double per_body = factor * (two_d ? c.seconds_per_body_2d : c.seconds_per_body_3d);
    return (static_cast<double>(entries) + created * (created != 0.0 ? bulk_entries(sph) : 0.0)) *
               per_entry +
           static_cast<double>(contacts) *
               (two_d ? c.seconds_per_contact_entry_2d : c.seconds_per_contact_entry_3d) +
           (static_cast<double>(n - walls) + created) * per_body +
           static_cast<double>(walls) * (two_d ? c.seconds_per_wall_2d : c.seconds_per_wall_3d);
}

/// Parallel speed-up: linear between 1 and the measured threads, no further gain beyond them
/// (the calibration knows nothing of more cores).
double speedup_of(int threads, const Calibration& c) {
    const int measured = std::max(1, c.threads_measured);
    const double used = std::min(threads, measured);
    return measured == 1 ? 1.0 : 1.0 + (c.speedup - 1.0) * (used - 1.0) / (measured - 1.0);
}

/// The coupled model's window and its estimated limit, as it reports them at t = 0.
void add_window_limit(const coupling::CoupledModel& coupled, CostEstimate& e) {
    e.coupling_window_limit = coupled.window_limit();
    e.coupling_window = coupled.stable_time_step();
    e.coupling_static = !coupled.fem().dynamic();
    e.coupling_added_mass_lag = coupled.added_mass_lag();
}

} // namespace

namespace {

/// The scene's SPH model, coupled or alone; nullptr without one.
const sph::SphModel* sph_of(const io::Stepper& stepper) {
    if (const auto* coupled = dynamic_cast<const coupling::CoupledModel*>(&stepper)) {
        return &coupled->sph();
    }
    return dynamic_cast<const sph::SphModel*>(&stepper);
}

/// The time loop's stable step over the run: the smallest of the modules' at t = 0, and an SPH
/// model's flow step where it steps the loop itself (not sub-cycled in coupling windows).
StepProfile driver_profile(const Scene& scene, const FlowStep& flow) {
    double rest = std::numeric_limits<double>::infinity();
    double others = std::numeric_limits<double>::infinity();
    for (const auto& stepper : scene.steppers) {
        rest = std::min(rest, stepper->stable_time_step());
        if (dynamic_cast<const sph::SphModel*>(stepper.get()) == nullptr) {
            others = std::min(others, stepper->stable_time_step());
        }
    }
    StepProfile driver;
    driver.rest = std::isfinite(rest) ? rest : scene.settings.output_interval;
    if (flow.profile.flow > 0.0 && flow.profile.flow < others) {
        driver.flow = std::min(flow.profile.flow, driver.rest);
        driver.from = flow.profile.from;
        driver.to = flow.profile.to;
    }
    return driver;
}

/// The SPH model's particles, sources, sinks and their cost per step into `e`; returns one
/// thread's seconds per step.
double add_sph_counts(const sph::SphModel& sph, const Discharge& discharge, double end,
                      const Calibration& calibration, CostEstimate& e) {
    const double sources = sph.solver() ? average_created(sph, end) : 0.0;
    e.average_created += sources;
    e.sinks += static_cast<int>(sph.sinks().sinks().size());
    e.average_discharged += discharge.average;
    e.outlet_rate += discharge.rate;
    e.outlet_opening = discharge.opening;
    e.outlet_declared = e.outlet_declared || discharge.declared;
    e.outlet_known = e.outlet_known && discharge.known;
    e.outlet_earliest = discharge.earliest;
    return sph_seconds_per_step(sph, sources - discharge.average, calibration, e);
}

/// The DEM's grains and their cost over `steps` steps into `e`.
void add_dem(const dem::DemModel& dem, double steps, double end, const Calibration& calibration,
             CostEstimate& e) {
    e.dem_grains += dem.most_grains(end);
    const double sphere_steps = dem.sphere_steps(steps, end);
    e.dem_sphere_steps += sphere_steps;
    // As the SPH step: the per-sphere work shared by the threads, the fixed part whole. The
    // calibration's grains are single spheres: its cost per grain-step is one sphere's, of one
    // force evaluation (the predictor-corrector's passes counted at their most).
    e.dem_seconds +=
        dem.evaluations_per_step() * (sphere_steps * calibration.dem_seconds_per_grain_step /
                                      speedup_of(e.threads, calibration)) +
        steps * calibration.dem_seconds_per_step;
}

/// Every output instant writes a frame, the checkpoint and the logs (t = 0 included).
void add_output(const StepPlan& plan, const Calibration& calibration, CostEstimate& e) {
    e.frames = static_cast<double>(plan.segments.size()) + 1.0;
    const double points = static_cast<double>(e.sph_particles + e.shell_nodes) + e.average_created -
                          e.average_discharged;
    e.output_seconds =
        e.frames * (calibration.seconds_per_frame + calibration.seconds_per_frame_point * points);
}

} // namespace

namespace {

/// The SPH model's particles, steps and cost into `e` over the run's `plan`; its bytes.
double add_sph(const sph::SphModel& sph, const Discharge& discharge, const StepPlan& plan,
               double end, const Calibration& calibration, CostEstimate& e) {
    const double per_step = add_sph_counts(sph, discharge, end, calibration, e);
    e.sph_steps = plan.sph_steps * e.coupling_passes;
    e.particle_steps = (static_cast<double>(sph.point_count() - e.wall_particles) +
                        e.average_created - e.average_discharged) *
                       e.sph_steps;
    // The step's fixed cost is paid whole on every thread count.
    const double fixed = sph.solver() == nullptr ? 0.0
                         : sph.dimension() == 2  ? calibration.seconds_per_step_2d
                                                 : calibration.seconds_per_step_3d;
    e.sph_seconds = (per_step / speedup_of(e.threads, calibration) + fixed) * e.sph_steps;
    return sph.solver() ? static_cast<double>(sph.solver()->bytes()) : 0.0;
}

/// The shells of the scene, alone or coupled, and their cost into `e`; their bytes.
double add_shells(const Scene& scene, const StepPlan& plan, const Calibration& calibration,
                  CostEstimate& e) {
    double bytes = 0.0;
    auto add_shell = [&](const fem::ShellModel& fem, bool in_coupling, bool loaded) {
        const ShellCost cost =
            estimate_shell_cost(fem, plan.segments, in_coupling, loaded, calibration,
                                in_coupling ? e.coupling_passes : 1.0);
        e.shell_nodes += fem.point_count();
        e.shell_dofs += fem.analysis().free_dof_count();
        e.shell_steps += cost.steps;
        e.shell_solved_steps += cost.solved_steps;
        e.shell_factorisations += cost.factorisations;
        e.shell_back_substitutions += cost.back_substitutions;
        e.shell_seconds += cost.seconds;
        bytes +=
            static_cast<double>(fem.analysis().free_dof_count()) * calibration.shell_bytes_per_dof;
    };
    for (const auto& stepper : scene.steppers) {
        if (const auto* model = dynamic_cast<const coupling::CoupledModel*>(stepper.get())) {
            add_shell(model->fem(), true, model->loads_shell());
            add_window_limit(*model, e);
        } else if (const auto* grains =
                       dynamic_cast<const coupling::DemCoupledModel*>(stepper.get())) {
            add_shell(grains->fem(), true, grains->loads_shell());
        } else if (const auto* fem = dynamic_cast<const fem::ShellModel*>(stepper.get())) {
            add_shell(*fem, false, false);
        }
    }
    return bytes;
}

/// The scene's DEM grains, alone or on coupled shells, and their cost into `e`.
void add_grains(const Scene& scene, const StepPlan& plan, const Calibration& calibration,
                CostEstimate& e) {
    for (const auto& stepper : scene.steppers) {
        const dem::DemModel* dem = dynamic_cast<const dem::DemModel*>(stepper.get());
        double dem_steps = static_cast<double>(plan.steps);
        if (const auto* grains = dynamic_cast<const coupling::DemCoupledModel*>(stepper.get())) {
            // Each window sub-cycled in uniform DEM steps (DemCoupledModel::subcycle).
            dem = &grains->dem();
            dem_steps *= std::max(1.0, std::ceil(grains->stable_time_step() /
                                                 dem->stable_time_step() * (1.0 - 1e-12))) *
                         e.coupling_passes;
        }
        if (dem != nullptr) {
            add_dem(*dem, dem_steps, scene.settings.end_time, calibration, e);
        }
    }
}

/// The coupling's max_iterations (1: staggered, or no coupling).
int coupling_iterations(const Scene& scene) {
    for (const auto& stepper : scene.steppers) {
        if (const auto* sph = dynamic_cast<const coupling::CoupledModel*>(stepper.get())) {
            return sph->settings().max_iterations;
        }
        if (const auto* dem = dynamic_cast<const coupling::DemCoupledModel*>(stepper.get())) {
            return dem->settings().max_iterations;
        }
    }
    return 1;
}

} // namespace

CostEstimate estimate_cost(const Scene& scene, int threads, const Calibration& calibration) {
    CostEstimate e;
    e.threads = std::max(1, threads);
    e.calibration = describe_calibration(calibration);
    const double end = scene.settings.end_time;
    const sph::SphModel* sph = nullptr;
    for (const auto& stepper : scene.steppers) {
        sph = sph != nullptr ? sph : sph_of(*stepper);
    }
    const Discharge discharge = sph ? average_discharged(*sph, end) : Discharge{};
    const FlowStep flow =
        sph ? flow_step(*sph, discharge, scene.settings.gravity, end) : FlowStep{};
    const StepProfile driver = driver_profile(scene, flow);
    e.time_step = driver.rest;
    e.flow_speed = flow.profile.flow > 0.0 ? flow.speed : 0.0;
    e.flow_start = flow.profile.from;
    e.flow_end = flow.profile.to;
    e.flow_step = flow.profile.flow;
    const bool coupled = std::any_of(scene.steppers.begin(), scene.steppers.end(), [](auto& s) {
        return dynamic_cast<const coupling::CoupledModel*>(s.get()) != nullptr;
    });
    const StepPlan plan =
        plan_steps(end, scene.settings.output_interval, driver, flow.profile, coupled);
    e.steps = plan.steps;
    e.coupling_max_iterations = coupling_iterations(scene);
    if (e.coupling_max_iterations > 1) {
        e.coupling_passes =
            std::min(kIteratedPasses, static_cast<double>(e.coupling_max_iterations));
    }
    double bytes = calibration.baseline_bytes;
    if (sph != nullptr) {
        bytes += add_sph(*sph, discharge, plan, end, calibration, e);
    }
    bytes += add_shells(scene, plan, calibration, e);
    add_grains(scene, plan, calibration, e);
    add_output(plan, calibration, e);
    e.wall_time_s = e.sph_seconds + e.shell_seconds + e.dem_seconds + e.output_seconds;
    e.memory_bytes = bytes;
    return e;
}

namespace {

// One printf-formatted line of the check's report.
template <class... Values> void add_line(std::ostream& out, const char* format, Values... values) {
    char line[256];
    std::snprintf(line, sizeof line, format, values...);
    out << line;
}

} // namespace

namespace {

void describe_sources_and_sinks(std::ostream& out, const CostEstimate& e) {
    if (e.average_created > 0.0) {
        add_line(out,
                 "      sources: %.0f particles more on average over the run, each with a full "
                 "kernel support\n",
                 e.average_created);
    }
    if (e.sinks > 0 && e.outlet_declared && e.outlet_known) {
        add_line(out,
                 "      sinks: %d; their outlets' Beverloo rate %.4g %s from %.3g s%s takes %.0f "
                 "particles on average over the run\n",
                 e.sinks, e.outlet_rate, e.plane_strain ? "kg/m/s" : "kg/s", e.outlet_opening,
                 e.outlet_earliest ? " (its phase's earliest start)" : "", e.average_discharged);
    } else if (e.sinks > 0) {
        // When the sinks take the material is the flow's outcome (the quarter wagon's load
        // leaves between 2.5 and 7.5 s of 11: its runs took 0.16-0.36 of the estimate).
        add_line(out,
                 "      sinks: %d; the particles they take are counted to the end time (%s), so a "
                 "discharge takes less than estimated\n",
                 e.sinks,
                 e.outlet_declared ? "the outlet opens on settling, not known before the run"
                                   : "no outlet_width declared");
    }
    if (e.flow_speed > 0.0) {
        add_line(out,
                 "      flow: from %.3g to %.3g s the fastest grain leaves the outlet and falls to "
                 "the sink at about %.3g m/s: SPH step %.3g s then\n",
                 e.flow_start, e.flow_end, e.flow_speed, e.flow_step);
    }
}

void describe_coupling(std::ostream& out, const CostEstimate& e) {
    // A static shell with a rigid coupled part or the added mass has no shortest window.
    char limit[128];
    if (e.coupling_static && !(e.coupling_window_limit > 0.0)) {
        std::snprintf(limit, sizeof limit,
                      "has no shortest stable window (estimate, coupling_window_limit = 0)");
    } else {
        std::snprintf(
            limit, sizeof limit, "is stable %s about %.3g s (estimate, coupling_window_limit)",
            e.coupling_static ? "from windows of" : "up to windows of", e.coupling_window_limit);
    }
    add_line(out, "      coupling: window %.3g s; the staggered exchange %s\n", e.coupling_window,
             limit);
    if (e.coupling_max_iterations > 1) {
        add_line(out,
                 "      iterated windows: each counted as %.3g passes (granular sub-steps and "
                 "shell solve), the mean of the measured runs (1.6-4.2); up to %d "
                 "(max_iterations) would cost %.3g times the granular and shell time above\n",
                 e.coupling_passes, e.coupling_max_iterations,
                 e.coupling_max_iterations / e.coupling_passes);
    }
    if (e.coupling_added_mass_lag > 0.0) {
        add_line(out,
                 "      added mass: the shell follows a change of the load within about %.3g "
                 "s (coupling_added_mass_lag)\n",
                 e.coupling_added_mass_lag);
    }
}

} // namespace

std::string describe_cost(const CostEstimate& e) {
    std::ostringstream out;
    add_line(out,
             "cost: %lld SPH particles (%lld of them walls), %lld shell nodes (%lld free DOFs)\n",
             static_cast<long long>(e.sph_particles), static_cast<long long>(e.wall_particles),
             static_cast<long long>(e.shell_nodes), static_cast<long long>(e.shell_dofs));
    if (e.dem_grains > 0) {
        add_line(out, "      DEM: %lld grains, %.3g sphere-steps, %s\n",
                 static_cast<long long>(e.dem_grains), e.dem_sphere_steps,
                 duration(e.dem_seconds).c_str());
    }
    describe_sources_and_sinks(out, e);
    add_line(out,
             "      step %.3g s at t = 0: %lld steps to the end time (%.3g SPH steps, %.3g "
             "particle-steps, %lld + %lld contact neighbour entries)\n",
             e.time_step, e.steps, e.sph_steps, e.particle_steps, static_cast<long long>(e.entries),
             static_cast<long long>(e.contact_entries));
    if (e.shell_steps > 0.0) {
        add_line(
            out,
            "      shell: %.0f steps, %.0f solves of loads that change: %.0f factorisations of "
            "its tangent, %.0f back-substitutions (fem_factorisations, "
            "fem_back_substitutions)\n",
            e.shell_steps, e.shell_solved_steps, e.shell_factorisations,
            e.shell_back_substitutions);
    }
    add_line(out,
             "      estimated wall time %s on %d thread%s (SPH %s, shell %s, %.0f frames %s), "
             "memory %.0f MiB\n",
             duration(e.wall_time_s).c_str(), e.threads, e.threads == 1 ? "" : "s",
             duration(e.sph_seconds).c_str(), duration(e.shell_seconds).c_str(), e.frames,
             duration(e.output_seconds).c_str(), e.memory_bytes / (1024.0 * 1024.0));
    if (e.coupling_window > 0.0) {
        describe_coupling(out, e);
    }
    out << "      throughput: " << e.calibration << '\n';
    return out.str();
}

std::optional<std::string> trade_table_advice(const std::string& case_file) {
    const fs::path path = fs::path(case_file).replace_extension(".trade.csv");
    std::ifstream in(path);
    if (!in) {
        return std::nullopt;
    }
    std::string line;
    std::getline(in, line);
    std::map<std::string, std::size_t> column;
    const std::vector<std::string> header = split_csv_line(line);
    for (std::size_t i = 0; i < header.size(); ++i) {
        column[header[i]] = i;
    }
    for (const char* needed : {"run", "elapsed_s", "change", "figure", "knee", "most_accurate"}) {
        if (!column.count(needed)) {
            return path.string() + " is not a trade.csv (no column '" + needed + "')";
        }
    }
    std::string knee;
    std::string best;
    double knee_time = 0.0;
    double best_time = 0.0;
    double worst = 0.0;
    std::string worst_figure;
    while (std::getline(in, line)) {
        std::vector<std::string> cells = split_csv_line(line);
        cells.resize(header.size());
        if (cells[column["most_accurate"]] == "1") {
            best = cells[column["run"]];
            best_time = std::atof(cells[column["elapsed_s"]].c_str());
        }
        if (cells[column["knee"]] != "1") {
            continue;
        }
        knee = cells[column["run"]];
        knee_time = std::atof(cells[column["elapsed_s"]].c_str());
        const std::string& change = cells[column["change"]];
        if (!change.empty() && std::abs(std::atof(change.c_str())) >= worst) {
            worst = std::abs(std::atof(change.c_str()));
            worst_figure = cells[column["figure"]];
        }
    }
    if (knee.empty()) {
        return path.string() + ": no run of the sweep stayed within its budget";
    }
    char text[512];
    std::snprintf(text, sizeof text,
                  "%s: its knee %s took %.0f s against %.0f s for the most accurate run %s "
                  "(%.1fx less), changing no figure by more than %.2f %% (%s)",
                  path.string().c_str(), knee.c_str(), knee_time, best_time, best.c_str(),
                  best_time / std::max(knee_time, 1e-9), 100.0 * worst, worst_figure.c_str());
    return std::string(text);
}

} // namespace grainload::app
