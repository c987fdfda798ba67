#include "coupling/coupled_model.hpp"

#include "coupling/window_iteration.hpp"
#include "coupling/window_limits.hpp"
#include "io/binary_stream.hpp"

#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <sstream>

namespace grainload::coupling {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

} // namespace

CoupledModel::CoupledModel(std::unique_ptr<sph::SphModel> sph, std::unique_ptr<fem::ShellModel> fem,
                           std::vector<CoupledPart> parts, CouplingSettings settings)
    : sph_(std::move(sph)), fem_(std::move(fem)), parts_(std::move(parts)), settings_(settings),
      load_(Eigen::VectorXd::Zero(6 * fem_->analysis().mesh().node_count())), start_load_(load_),
      end_load_(load_), pressure_(fem_->analysis().mesh()) {
    sph_->exchange_particles_per_window();
    for (const CoupledPart& part : parts_) {
        pressure_.add_part(fem_->analysis().mesh(), part.elements, part.side);
    }
    pressure_.finish();
}

void CoupledModel::set_window_limits(const WindowLimits& limits) {
    stable_window_max_ = limits.dynamic_max;
    stable_window_min_ = limits.static_min;
    added_mass_lag_ = coupling::added_mass_lag(limits, settings_.window, settings_.added_mass);
}

double CoupledModel::stable_time_step() const {
    double window = settings_.window;
    if (settings_.max_subcycles > 0) {
        window = std::min(window, settings_.max_subcycles * sph_->stable_time_step());
    }
    return window;
}

namespace {
/// Sub-steps between two runs of the SPH watchdog inside a coupling window: its energy sums
/// cost about one pass over the particles, 1/64 of a sub-step's passes at most.
constexpr int kWatchEvery = 64;
} // namespace

int CoupledModel::subcycle(double t, double dt, WindowRecord& record) {
    // Uniform sub-steps that land on the window's end; counted anew whenever the CFL limit
    // drops below the step (the sand speeds up within the window).
    const double end = t + dt;
    double time = t;
    int steps = 0;
    while (time < end) {
        const double limit = sph_->stable_time_step();
        if (auto collapse = step_watch_.record(limit, time)) {
            collapse_ = "sph, within a coupling window: " + *collapse;
            break; // the window stays unfinished: the watchdog stops the run after it
        }
        // The particles' own watchdog (energy created, an escape, a NaN) inside the window
        // too, every kWatchEvery sub-steps: a blow-up whose step shrinks slowly would
        // otherwise crawl to the window's end (the coupled plate at CFL factor 1.0 with
        // 100 ms windows did, once the density floor kept its sound speed bounded).
        if (steps > 0 && steps % kWatchEvery == 0) {
            if (auto problem = sph_->diagnose()) {
                collapse_ = "sph, within a coupling window: " + *problem;
                break;
            }
        }
        const double remaining = end - time;
        const auto n = static_cast<long long>(std::ceil(remaining / limit * (1.0 - 1e-12)));
        const double step = n <= 1 ? remaining : remaining / static_cast<double>(n);
        auto start = Clock::now();
        sph_->advance(time, step);
        record.sand_seconds += seconds_since(start);
        start = Clock::now();
        for (const CoupledPart& part : parts_) {
            const auto& walls = sph_->solver()->walls();
            part.wall->accumulate(sph_->particles(),
                                  walls[static_cast<std::size_t>(part.wall_index)], step);
        }
        record.map_seconds += seconds_since(start);
        time = n <= 1 ? end : time + step;
        ++steps;
    }
    return steps;
}

Eigen::VectorXd CoupledModel::collect_load(double dt) {
    Eigen::VectorXd load = Eigen::VectorXd::Zero(load_.size());
    for (const CoupledPart& part : parts_) {
        part.wall->add_nodal_loads(fem_->analysis(), dt, load);
    }
    return load;
}

void CoupledModel::run_window(double t, double dt, const Eigen::VectorXd& applied) {
    const Eigen::VectorXd before = fem_->analysis().dofs();
    Vec3 wall_impulse = Vec3::Zero();
    double sand_work = 0.0;
    for (const CoupledPart& part : parts_) {
        wall_impulse -= part.wall->impulse();
        sand_work -= part.wall->work();
    }
    WindowRecord record;
    record.time = t + dt;
    record.length = dt;
    auto start = Clock::now();
    // The sand's load is the window's mean, constant over it. A static shell takes it as its
    // load at the window's end. Newmark's trapezoidal rule integrates a load linearly between
    // the step's ends, so a dynamic shell gets the end load 2 F - F(start): the mean of the
    // two is F, and the rule is then the implicit midpoint rule under F, whose energy identity
    // makes the shell receive exactly F . dU, the sand's work (same u and v as Newmark for a
    // linear shell; the accelerations, which only this identity uses, alternate about their
    // mean).
    end_load_ = fem_->dynamic() ? Eigen::VectorXd(2.0 * applied - start_load_) : applied;
    fem_->advance_with_forces(t, dt, end_load_);
    record.fem_seconds = seconds_since(start);
    start = Clock::now();
    for (const CoupledPart& part : parts_) {
        part.wall->begin_window(fem_->analysis(), t, t + dt);
    }
    record.map_seconds = seconds_since(start);
    record.subcycles = subcycle(t, dt, record);
    for (const CoupledPart& part : parts_) {
        wall_impulse += part.wall->impulse();
        sand_work += part.wall->work();
    }
    record.sand_work = sand_work;
    record.wall_impulse = wall_impulse;
    // The work the shell receives: its loads at the window's ends, trapezoidal (Newmark's energy
    // identity; for a static linear shell the change of its strain energy).
    record.shell_work = 0.5 * (start_load_ + end_load_).dot(fem_->analysis().dofs() - before);
    record.shell_impulse = dt * load_resultant(applied);
    pending_ = record;
}

void CoupledModel::advance(double t, double dt) {
    if (settings_.max_iterations <= 1) {
        // Staggered: one pass; the next window's load moves from this window's towards the
        // load the sand produced by the relaxation factor (1: the produced load itself). The
        // relaxation damps the exchange's period-two oscillation of a compliant shell, and a
        // sand at rest is unaffected: there the produced load is the applied one.
        run_window(t, dt, load_);
        start_load_ = end_load_;
        const auto start = Clock::now();
        const Eigen::VectorXd produced = collect_load(dt);
        pending_.load_change = relative_change(produced, load_);
        load_ += settings_.relaxation * (produced - load_);
        pending_.map_seconds += seconds_since(start);
    } else {
        iterate_window(t, dt);
    }
    // Particles leave and enter once the window is final: every pass above ran on the same
    // particles.
    sph_->exchange_particles(t, dt);
    // The extremes read the element stresses, which a stored stiffness evaluates only now: the
    // shell's cost.
    const auto start = Clock::now();
    track_extremes();
    pending_.fem_seconds += seconds_since(start);
    monitor_.add(pending_);
}

void CoupledModel::track_extremes() {
    if (parts_.empty()) {
        return; // every interface rigid: the shell's stresses are not the sand's
    }
    for (const CoupledPart& part : parts_) {
        extremes_.add_deflection(fem_->analysis(), part.elements);
    }
    extremes_.add_stress(fem_->analysis());
}

void CoupledModel::iterate_window(double t, double dt) {
    // Fixed-point iteration on the interface load F (coupling/window_iteration.hpp): every pass
    // starts the window afresh from the state saved here.
    std::stringstream saved;
    sph_->write_checkpoint(saved);
    fem_->write_checkpoint(saved);
    const std::string start_state = saved.str();
    Eigen::VectorXd produced;
    pending_ = iterate_passes(
        settings_, load_,
        [&](const Eigen::VectorXd& applied, int pass, Eigen::VectorXd& out) {
            if (pass > 1) {
                std::istringstream in(start_state);
                sph_->read_checkpoint(in);
                fem_->read_checkpoint(in);
            }
            run_window(t, dt, applied);
            const auto start = Clock::now();
            out = collect_load(dt);
            pending_.map_seconds += seconds_since(start);
            return pending_;
        },
        produced);
    start_load_ = end_load_;
    load_ = produced;
}

std::optional<std::string> CoupledModel::diagnose() const {
    if (collapse_) {
        return collapse_;
    }
    if (auto problem = sph_->diagnose()) {
        return "sph: " + *problem;
    }
    if (auto problem = fem_->diagnose()) {
        return "fem: " + *problem;
    }
    if (!load_.allFinite()) {
        return std::string("interface load is not finite");
    }
    const double scale = sph_->solver()->energy_ledger().throughput();
    if (auto problem = monitor_.check(settings_.energy_error_limit, scale)) {
        return *problem + "; the exchange is unstable: " + instability_remedy();
    }
    return std::nullopt;
}

std::string CoupledModel::instability_remedy() const {
    // The staggered exchange is stable below a window for a dynamic shell and above one for a
    // static shell (window_limits.hpp); iterating converges to the monolithic answer either way.
    std::ostringstream remedy;
    if (fem_->dynamic()) {
        remedy << "shorten [coupling] window (estimated stable up to " << stable_window_max_
               << " s)";
    } else {
        remedy << "lengthen [coupling] window (a static shell needs the longer window";
        if (stable_window_min_ > 0.0) {
            remedy << "; estimated stable from " << stable_window_min_ << " s";
        }
        remedy << "), give the shell the sand's inertia (added_mass = "
               << (settings_.added_mass > 0.0 ? "more than " : "")
               << (settings_.added_mass > 0.0 ? settings_.added_mass : 4.0) << ")";
    }
    remedy << ", lower the relaxation (now " << settings_.relaxation << "), or iterate ";
    if (settings_.max_iterations > 1) {
        remedy << "further (max_iterations now " << settings_.max_iterations << ")";
    } else {
        remedy << "(max_iterations > 1)";
    }
    return remedy.str();
}

void CoupledModel::write_checkpoint(std::ostream& out) const {
    sph_->write_checkpoint(out);
    fem_->write_checkpoint(out);
    io::write_array(out, std::vector<double>(load_.begin(), load_.end()));
    io::write_array(out, std::vector<double>(start_load_.begin(), start_load_.end()));
    io::write_array(out, monitor_.state());
    io::write_array(out, std::vector<double>{static_cast<double>(monitor_.windows().size() +
                                                                 windows_before_restart_),
                                             extremes_.deflection, extremes_.von_mises});
}

void CoupledModel::read_checkpoint(std::istream& in) {
    sph_->read_checkpoint(in);
    fem_->read_checkpoint(in);
    std::vector<double> load;
    io::read_array(in, load);
    if (static_cast<Eigen::Index>(load.size()) != load_.size()) {
        throw std::runtime_error("checkpoint: the interface load does not match the shell mesh");
    }
    load_ = Eigen::Map<const Eigen::VectorXd>(load.data(), load_.size());
    io::read_array(in, load);
    if (static_cast<Eigen::Index>(load.size()) != load_.size()) {
        throw std::runtime_error("checkpoint: the interface load does not match the shell mesh");
    }
    start_load_ = Eigen::Map<const Eigen::VectorXd>(load.data(), load_.size());
    // The last window's end load is the next one's start: the shell's forces since then, which
    // its support reactions (summary.json) balance even when no window follows the restart.
    end_load_ = start_load_;
    fem_->restore_forces(start_load_);
    std::vector<double> state;
    io::read_array(in, state);
    monitor_.set_state(state);
    std::vector<double> windows;
    io::read_array(in, windows);
    if (windows.size() != 3) {
        throw std::runtime_error(
            "checkpoint: the coupling's window count and extremes are missing");
    }
    // Whole numbers below 2^53 are exact in a double.
    windows_before_restart_ =
        io::state_count(windows[0], 9007199254740992.0, "the coupling's window count");
    extremes_.deflection = windows[1];
    extremes_.von_mises = windows[2];
}

} // namespace grainload::coupling
