#include "app/cost_estimate.hpp"

#include "app/scene.hpp"
#include "app/trade_table.hpp"
#include "coupling/coupled_model.hpp"
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

std::string calibration_path() {
    if (const char* path = std::getenv("GRAINLOAD_CALIBRATION")) {
        return path;
    }
    std::error_code error;
    const fs::path exe = fs::read_symlink("/proc/self/exe", error);
    return error ? std::string() : (exe.parent_path().parent_path() / "calibration.json").string();
}

/// Driver steps and SPH steps from t = 0 to the end at a constant step `dt` (SPH at
/// `sph_dt` inside each), landing on every output instant as the driver's loop does. Counted in
/// doubles: a step of 1e-300 s gives more steps than a long long holds (a cast of such a double
/// is undefined behaviour), so `steps` stops at kMostSteps.
struct StepCount {
    long long steps = 0;
    double sph_steps = 0.0;
};

constexpr double kMostSteps = 1e18;

StepCount count_steps(double end, double interval, double dt, double sph_dt) {
    StepCount count;
    const double tolerance = 1e-12 * end;
    // io/scene_settings.cpp holds end / interval to io::kMostOutputIntervals.
    const auto intervals = static_cast<long long>(std::ceil(end / interval - 1e-9));
    double steps = 0.0;
    for (long long k = 0; k < intervals; ++k) {
        const double start = static_cast<double>(k) * interval;
        const double stop = std::min(static_cast<double>(k + 1) * interval, end);
        const double length = stop - start;
        if (length <= tolerance) {
            continue;
        }
        const double n = std::ceil(length / dt * (1.0 - 1e-12));
        steps += n;
        const double window = length / n;
        count.sph_steps += n * std::ceil(window / sph_dt * (1.0 - 1e-12));
    }
    count.steps = static_cast<long long>(std::min(steps, kMostSteps));
    return count;
}

/// Neighbour-list entries at t = 0 between bodies, and between a body and a wall particle.
std::pair<Index, Index> count_entries(const sph::SphModel& sph) {
    if (sph.solver() == nullptr) {
        return {0, 0};
    }
    const auto& wall_id = sph.particles().wall_id;
    const sph::NeighbourList& list = sph.solver()->neighbours();
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
    if (s < 120.0) {
        std::snprintf(text, sizeof text, "%.0f s", s);
    } else if (s < 7200.0) {
        std::snprintf(text, sizeof text, "%.0f min", s / 60.0);
    } else {
        std::snprintf(text, sizeof text, "%.1f h", s / 3600.0);
    }
    return text;
}

} // namespace

Calibration load_calibration() {
    Calibration c;
    const std::string path = calibration_path();
    if (path.empty() || !fs::exists(path)) {
        return c;
    }
    try {
        const io::JsonValue file = io::read_json_file(path);
        const auto get = [&](const char* key, double fallback) {
            return file.number_at(key).value_or(fallback);
        };
        c.seconds_per_entry_2d = get("seconds_per_entry_2d", c.seconds_per_entry_2d);
        c.seconds_per_body_2d = get("seconds_per_body_2d", c.seconds_per_body_2d);
        c.seconds_per_wall_2d = get("seconds_per_wall_2d", c.seconds_per_wall_2d);
        c.seconds_per_contact_entry_2d =
            get("seconds_per_contact_entry_2d", c.seconds_per_contact_entry_2d);
        c.seconds_per_entry_3d = get("seconds_per_entry_3d", c.seconds_per_entry_3d);
        c.seconds_per_body_3d = get("seconds_per_body_3d", c.seconds_per_body_3d);
        c.seconds_per_wall_3d = get("seconds_per_wall_3d", c.seconds_per_wall_3d);
        c.seconds_per_contact_entry_3d =
            get("seconds_per_contact_entry_3d", c.seconds_per_contact_entry_3d);
        c.threads_measured = static_cast<int>(get("threads_measured", 1.0));
        c.speedup = get("speedup", 1.0);
        c.source = path + " (" + file.string_at("date").value_or("undated") + ")";
    } catch (const io::JsonError& e) {
        c.source = std::string("built-in constants (") + e.what() + ")";
    }
    return c;
}

namespace {

/// The particles source `s` creates by `end`: what its rate owes, but no more than its sites
/// hold (a full box owes on); 0 for one that has not started by then.
double created_by(const sph::SourceSet::Source& s, double end) {
    const double stop = std::min(s.end, end);
    if (!(stop > s.start) || !(s.particle_mass > 0.0)) {
        return 0.0;
    }
    return std::min(s.mass_rate * (stop - s.start) / s.particle_mass,
                    static_cast<double>(s.sites.size()));
}

/// The particles the sources create, averaged over the run [0, end]: one created at t is there
/// for end - t. (What the sinks take is average_discharged's.)
double average_created(const sph::SphModel& sph, double end) {
    double average = 0.0;
    if (!(end > 0.0)) {
        return average;
    }
    for (const sph::SourceSet::Source& s : sph.sources().sources()) {
        const double stop = std::min(s.end, end);
        average += created_by(s, end) * (end - 0.5 * (s.start + stop)) / end;
    }
    return average;
}

/// The particles the sinks with a declared outlet ([[sph.sink]] outlet_width) take, averaged
/// over the run [0, end]: at Beverloo's rate from the opening (the first wall removed at a
/// stated time; t = 0 when no wall is due to go) until the material there and to come is
/// gone. A wall due to go on settling or at a phase has no time yet: then `known` is false and
/// nothing is taken (the estimate stays an upper bound).
struct Discharge {
    double average = 0.0; ///< particles taken, averaged over the run
    double rate = 0.0;    ///< the outlets' Beverloo rate, kg/s (kg/m/s in plane strain)
    double opening = 0.0;
    bool declared = false; ///< a sink with an outlet
    bool known = true;     ///< the opening time is known before the run
};

Discharge average_discharged(const sph::SphModel& sph, double end) {
    Discharge d;
    for (std::size_t s = 0; s < sph.sinks().sinks().size(); ++s) {
        if (const auto rate = sph.sinks().outlet_rate(s)) {
            d.rate += *rate;
            d.declared = true;
        }
    }
    if (!d.declared || !sph.solver() || !(end > 0.0)) {
        return d;
    }
    double opening = std::numeric_limits<double>::infinity();
    bool pending = false;
    for (const sph::Wall& wall : sph.solver()->walls()) {
        opening = std::min(opening, wall.removal_time);
        pending = pending || wall.removal_on_settle || wall.removal_phase >= 0;
    }
    if (!std::isfinite(opening) && pending) {
        d.known = false;
        return d;
    }
    d.opening = std::isfinite(opening) ? opening : 0.0;
    const sph::ParticleSet& p = sph.particles();
    double mass = 0.0;
    double count = 0.0;
    for (Index i = 0; i < p.size(); ++i) {
        mass += p.is_wall(i) ? 0.0 : p.mass[i];
        count += p.is_wall(i) ? 0.0 : 1.0;
    }
    for (const sph::SourceSet::Source& source : sph.sources().sources()) {
        const double made = created_by(source, end);
        mass += made * source.particle_mass;
        count += made;
    }
    const double span = end - d.opening;
    if (!(span > 0.0) || !(mass > 0.0) || !(d.rate > 0.0)) {
        return d;
    }
    // Mass taken by t: min(M, W (t - t_open)); its integral over the run, per particle.
    const double emptied = mass / d.rate;
    const double integral = span <= emptied ? 0.5 * d.rate * span * span
                                            : 0.5 * mass * emptied + mass * (span - emptied);
    d.average = integral / end * (count / mass);
    return d;
}

/// Neighbour-list entries of a particle inside a body: the sites of its lattice (the bodies'
/// spacing) within the kernel's support radius, itself excluded.
double bulk_entries(const sph::SphModel& sph) {
    const double reach = sph.solver()->kernel().support_radius() / sph.spacing();
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
    return sites - 1.0;
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
    const bool two_d = sph.dimension() == 2;
    return (static_cast<double>(entries) + created * (created != 0.0 ? bulk_entries(sph) : 0.0)) *
               (two_d ? c.seconds_per_entry_2d : c.seconds_per_entry_3d) +
           static_cast<double>(contacts) *
               (two_d ? c.seconds_per_contact_entry_2d : c.seconds_per_contact_entry_3d) +
           (static_cast<double>(n - walls) + created) *
               (two_d ? c.seconds_per_body_2d : c.seconds_per_body_3d) +
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

CostEstimate estimate_cost(const Scene& scene, int threads, const Calibration& calibration) {
    CostEstimate e;
    e.threads = std::max(1, threads);
    double dt = std::numeric_limits<double>::infinity();
    for (const auto& stepper : scene.steppers) {
        dt = std::min(dt, stepper->stable_time_step());
    }
    const double end = scene.settings.end_time;
    const double interval = scene.settings.output_interval;
    e.time_step = std::isfinite(dt) ? dt : interval;
    e.steps = count_steps(end, interval, e.time_step, e.time_step).steps;
    const double speedup = speedup_of(e.threads, calibration);
    double seconds = 0.0;
    double bytes = calibration.baseline_bytes;
    auto add_sph = [&](const sph::SphModel& sph, double sph_dt) {
        const double sph_steps = count_steps(end, interval, e.time_step, sph_dt).sph_steps;
        e.sph_steps += sph_steps;
        const Discharge discharge = average_discharged(sph, end);
        const double sources = sph.solver() ? average_created(sph, end) : 0.0;
        e.average_created += sources;
        const double created = sources - discharge.average;
        seconds += sph_seconds_per_step(sph, created, calibration, e) * sph_steps / speedup;
        e.particle_steps += (static_cast<double>(sph.point_count()) + created) * sph_steps;
        e.sinks += static_cast<int>(sph.sinks().sinks().size());
        e.average_discharged += discharge.average;
        e.outlet_rate += discharge.rate;
        e.outlet_opening = discharge.opening;
        e.outlet_declared = e.outlet_declared || discharge.declared;
        e.outlet_known = e.outlet_known && discharge.known;
        bytes += sph.solver() ? static_cast<double>(sph.solver()->bytes()) : 0.0;
    };
    auto add_shell = [&](const fem::ShellModel& fem) {
        const auto dofs = static_cast<double>(fem.analysis().free_dof_count());
        e.shell_nodes += fem.point_count();
        e.shell_dofs += fem.analysis().free_dof_count();
        seconds += dofs * static_cast<double>(e.steps) * calibration.shell_seconds_per_dof_step;
        bytes += dofs * calibration.shell_bytes_per_dof;
    };
    for (const auto& stepper : scene.steppers) {
        if (const auto* coupled = dynamic_cast<const coupling::CoupledModel*>(stepper.get())) {
            add_sph(coupled->sph(), coupled->sph().stable_time_step());
            add_shell(coupled->fem());
            add_window_limit(*coupled, e);
        } else if (const auto* sph = dynamic_cast<const sph::SphModel*>(stepper.get())) {
            add_sph(*sph, e.time_step);
        } else if (const auto* fem = dynamic_cast<const fem::ShellModel*>(stepper.get())) {
            add_shell(*fem);
        }
    }
    e.wall_time_s = seconds;
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

std::string describe_cost(const CostEstimate& e, const Calibration& calibration) {
    std::ostringstream out;
    add_line(out,
             "cost: %lld SPH particles (%lld of them walls), %lld shell nodes (%lld free DOFs)\n",
             static_cast<long long>(e.sph_particles), static_cast<long long>(e.wall_particles),
             static_cast<long long>(e.shell_nodes), static_cast<long long>(e.shell_dofs));
    if (e.average_created > 0.0) {
        add_line(out,
                 "      sources: %.0f particles more on average over the run, each with a full "
                 "kernel support\n",
                 e.average_created);
    }
    if (e.sinks > 0 && e.outlet_declared && e.outlet_known) {
        add_line(out,
                 "      sinks: %d; their outlets' Beverloo rate %.4g %s from %.3g s takes %.0f "
                 "particles on average over the run\n",
                 e.sinks, e.outlet_rate, e.plane_strain ? "kg/m/s" : "kg/s", e.outlet_opening,
                 e.average_discharged);
    } else if (e.sinks > 0) {
        // When the sinks take the material is the flow's outcome (the quarter wagon's load
        // leaves between 2.5 and 7.5 s of 11: its runs took 0.16-0.36 of the estimate).
        add_line(out,
                 "      sinks: %d; the particles they take are counted to the end time (%s), so a "
                 "discharge takes less than estimated\n",
                 e.sinks,
                 e.outlet_declared ? "the outlet opens on settling or at a phase, not known before "
                                     "the run"
                                   : "no outlet_width declared");
    }
    add_line(out,
             "      step %.3g s at t = 0: %lld steps to the end time (%.3g SPH steps, %.3g "
             "particle-steps, %lld + %lld contact neighbour entries)\n",
             e.time_step, e.steps, e.sph_steps, e.particle_steps, static_cast<long long>(e.entries),
             static_cast<long long>(e.contact_entries));
    add_line(out, "      estimated wall time %s on %d threads, memory %.0f MiB\n",
             duration(e.wall_time_s).c_str(), e.threads, e.memory_bytes / (1024.0 * 1024.0));
    if (e.coupling_window > 0.0) {
        // A static shell with a rigid coupled part or the added mass has no shortest window.
        char limit[128];
        if (e.coupling_static && !(e.coupling_window_limit > 0.0)) {
            std::snprintf(limit, sizeof limit,
                          "has no shortest stable window (estimate, coupling_window_limit = 0)");
        } else {
            std::snprintf(limit, sizeof limit,
                          "is stable %s about %.3g s (estimate, coupling_window_limit)",
                          e.coupling_static ? "from windows of" : "up to windows of",
                          e.coupling_window_limit);
        }
        add_line(out, "      coupling: window %.3g s; the staggered exchange %s\n",
                 e.coupling_window, limit);
        if (e.coupling_added_mass_lag > 0.0) {
            add_line(out,
                     "      added mass: the shell follows a change of the load within about %.3g "
                     "s (coupling_added_mass_lag)\n",
                     e.coupling_added_mass_lag);
        }
    }
    out << "      throughput: " << calibration.source << '\n';
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
