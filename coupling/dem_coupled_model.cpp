#include "coupling/dem_coupled_model.hpp"

#include "coupling/window_iteration.hpp"
#include "io/binary_stream.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace grainload::coupling {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

/// DEM sub-steps between two runs of its watchdog inside a window: a blow-up stops the window
/// early instead of crawling to its end.
constexpr int kWatchEvery = 64;

} // namespace

DemCoupledModel::DemCoupledModel(std::unique_ptr<dem::DemModel> dem,
                                 std::unique_ptr<fem::ShellModel> fem,
                                 std::vector<DemCoupledPart> parts, std::vector<std::string> rigid,
                                 const CouplingSettings& settings)
    : dem_(std::move(dem)), fem_(std::move(fem)), parts_(std::move(parts)),
      rigid_(std::move(rigid)), settings_(settings),
      load_(Eigen::VectorXd::Zero(6 * fem_->analysis().mesh().node_count())), start_load_(load_),
      pressure_(fem_->analysis().mesh()) {
    for (const DemCoupledPart& part : parts_) {
        pressure_.add_part(fem_->analysis().mesh(), part.elements, part.side);
    }
    pressure_.finish();
}

double DemCoupledModel::stable_time_step() const {
    double window = settings_.window;
    if (settings_.max_subcycles > 0) {
        window = std::min(window, settings_.max_subcycles * dem_->stable_time_step());
    }
    return window;
}

int DemCoupledModel::subcycle(double t, double dt, WindowRecord& record) {
    // Uniform steps that land on the window's end, none longer than the DEM's stable step;
    // counted anew when that step drops below them (a Hertz contact's time shortens as the
    // grains speed up), as the SPH coupling's sub-steps are.
    const double end = t + dt;
    double time = t;
    int steps = 0;
    while (time < end) {
        const double remaining = end - time;
        const auto n =
            static_cast<long long>(std::ceil(remaining / dem_->stable_time_step() * (1.0 - 1e-12)));
        const double step = n <= 1 ? remaining : remaining / static_cast<double>(n);
        auto start = Clock::now();
        dem_->advance(time, step);
        record.sand_seconds += seconds_since(start);
        start = Clock::now();
        for (DemCoupledPart& part : parts_) {
            part.wall.accumulate(dem_->walls()[part.wall_index], step);
        }
        record.map_seconds += seconds_since(start);
        time = n <= 1 ? end : time + step;
        if (++steps % kWatchEvery == 0) {
            if (auto problem = dem_->diagnose()) {
                problem_ = "dem, within a coupling window: " + *problem;
                break;
            }
        }
    }
    return steps;
}

WindowRecord DemCoupledModel::run_window(double t, double dt, const Eigen::VectorXd& applied,
                                         Eigen::VectorXd& end_load) {
    WindowRecord record;
    record.time = t + dt;
    record.length = dt;
    const Eigen::VectorXd before = fem_->analysis().dofs();
    Vec3 wall_impulse = Vec3::Zero();
    double grain_work = 0.0;
    for (const DemCoupledPart& part : parts_) {
        wall_impulse -= part.wall.impulse();
        grain_work -= part.wall.work();
    }
    auto start = Clock::now();
    // The grains' load is the window's mean: a static shell takes it at the window's end, a
    // dynamic one 2 F - F(start), whose trapezoidal mean is F (as in the SPH coupling,
    // docs/theory/coupling.md).
    end_load = fem_->dynamic() ? Eigen::VectorXd(2.0 * applied - start_load_) : applied;
    fem_->advance_with_forces(t, dt, end_load);
    record.fem_seconds = seconds_since(start);
    start = Clock::now();
    for (const DemCoupledPart& part : parts_) {
        part.wall.begin_window(fem_->analysis(), dem_->wall(part.wall_index), t, t + dt);
    }
    record.map_seconds = seconds_since(start);
    record.subcycles = subcycle(t, dt, record);
    for (const DemCoupledPart& part : parts_) {
        wall_impulse += part.wall.impulse();
        grain_work += part.wall.work();
    }
    record.sand_work = grain_work;
    record.wall_impulse = wall_impulse;
    record.shell_work = 0.5 * (start_load_ + end_load).dot(fem_->analysis().dofs() - before);
    record.shell_impulse = dt * load_resultant(applied);
    return record;
}

Eigen::VectorXd DemCoupledModel::collect_load(double dt) {
    Eigen::VectorXd produced = Eigen::VectorXd::Zero(load_.size());
    for (DemCoupledPart& part : parts_) {
        part.wall.add_nodal_loads(fem_->analysis(), dt, produced);
    }
    return produced;
}

WindowRecord DemCoupledModel::iterate_window(double t, double dt) {
    // Fixed-point iteration on the interface load, as the SPH coupling's
    // (coupling/window_iteration.hpp): every pass starts the window afresh from the state saved
    // here, the grains, the shell and the walls' books.
    std::stringstream saved;
    dem_->write_checkpoint(saved);
    fem_->write_checkpoint(saved);
    for (const DemCoupledPart& part : parts_) {
        part.wall.write_state(saved, dem_->walls()[part.wall_index]);
    }
    const std::string start_state = saved.str();
    Eigen::VectorXd end_load;
    Eigen::VectorXd produced;
    const WindowRecord record = iterate_passes(
        settings_, load_,
        [&](const Eigen::VectorXd& applied, int pass, Eigen::VectorXd& out) {
            if (pass > 1) {
                std::istringstream in(start_state);
                dem_->read_checkpoint(in);
                fem_->read_checkpoint(in);
                for (DemCoupledPart& part : parts_) {
                    part.wall.read_state(in, dem_->wall(part.wall_index));
                }
                (void)dem_->take_events(); // the pass before's, said again by this one
            }
            WindowRecord pass_record = run_window(t, dt, applied, end_load);
            const auto start = Clock::now();
            out = collect_load(dt);
            pass_record.map_seconds += seconds_since(start);
            return pass_record;
        },
        produced);
    start_load_ = end_load;
    load_ = produced;
    return record;
}

void DemCoupledModel::advance(double t, double dt) {
    WindowRecord record;
    if (settings_.max_iterations <= 1) {
        // Staggered: the next window's load moves from this window's towards the grains' by
        // the relaxation factor.
        Eigen::VectorXd end_load;
        record = run_window(t, dt, load_, end_load);
        start_load_ = end_load;
        const Eigen::VectorXd produced = collect_load(dt);
        record.load_change = relative_change(produced, load_);
        load_ += settings_.relaxation * (produced - load_);
    } else {
        record = iterate_window(t, dt);
    }
    const auto start = Clock::now();
    if (!parts_.empty()) {
        for (const DemCoupledPart& part : parts_) {
            extremes_.add_deflection(fem_->analysis(), part.elements);
        }
        extremes_.add_stress(fem_->analysis());
    }
    record.fem_seconds += seconds_since(start);
    monitor_.add(record);
    const dem::DemEnergy energy = dem_->energy();
    energy_scale_ = std::max(energy_scale_, std::abs(energy.gravity) + energy.translational +
                                                energy.rotational + energy.elastic);
}

std::optional<std::string> DemCoupledModel::diagnose() const {
    if (problem_) {
        return problem_;
    }
    if (auto problem = dem_->diagnose()) {
        return "dem: " + *problem;
    }
    if (auto problem = fem_->diagnose()) {
        return "fem: " + *problem;
    }
    if (!load_.allFinite()) {
        return std::string("interface load is not finite");
    }
    if (auto problem = monitor_.check(settings_.energy_error_limit, energy_scale_)) {
        std::ostringstream remedy;
        remedy << *problem
               << "; the exchange is unstable: " << (fem_->dynamic() ? "shorten" : "lengthen")
               << " [coupling] window or lower the relaxation (now " << settings_.relaxation << ")";
        return remedy.str();
    }
    return std::nullopt;
}

void DemCoupledModel::write_checkpoint(std::ostream& out) const {
    dem_->write_checkpoint(out);
    fem_->write_checkpoint(out);
    io::write_array(out, std::vector<double>(load_.begin(), load_.end()));
    io::write_array(out, std::vector<double>(start_load_.begin(), start_load_.end()));
    io::write_array(out, monitor_.state());
    io::write_array(out,
                    std::vector<double>{
                        static_cast<double>(monitor_.windows().size() + windows_before_restart_),
                        extremes_.deflection, extremes_.von_mises, energy_scale_});
    for (const DemCoupledPart& part : parts_) {
        part.wall.write_state(out, dem_->walls()[part.wall_index]);
    }
}

void DemCoupledModel::read_checkpoint(std::istream& in) {
    dem_->read_checkpoint(in);
    fem_->read_checkpoint(in);
    const auto n = static_cast<std::size_t>(load_.size());
    std::vector<double> load;
    io::read_array(in, load, n, "the interface load");
    load_ = Eigen::Map<const Eigen::VectorXd>(load.data(), load_.size());
    io::read_array(in, load, n, "the interface load");
    start_load_ = Eigen::Map<const Eigen::VectorXd>(load.data(), load_.size());
    // The last window's end load: the shell's forces since then, which its support reactions
    // (summary.json) balance even when no window follows the restart.
    fem_->restore_forces(start_load_);
    std::vector<double> state;
    io::read_array(in, state);
    monitor_.set_state(state);
    std::vector<double> windows;
    io::read_array(in, windows, 4, "the coupling's window count, extremes and energy scale");
    windows_before_restart_ =
        io::state_count(windows[0], 9007199254740992.0, "the coupling's window count");
    extremes_.deflection = windows[1];
    extremes_.von_mises = windows[2];
    energy_scale_ = windows[3];
    for (DemCoupledPart& part : parts_) {
        part.wall.read_state(in, dem_->wall(part.wall_index));
    }
}

} // namespace grainload::coupling
