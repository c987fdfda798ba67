#include "sph/sph_model.hpp"

#include "sph/outlet_reach.hpp"
#include "sph/scene_limits.hpp"
#include "sph/scene_monitors.hpp"
#include "sph/start_gap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

namespace grainload::sph {

namespace {

// The run is stopped as unstable when its particles hold more surplus energy than all the
// energy that passed through it (EnergyLedger). Physically the surplus cannot exceed what the
// contact potential held at the start and has since released, which the throughput includes,
// so a ratio of 1 is unreachable by a sound run whatever its contacts do; an instability grows
// exponentially and passes it within a few steps of becoming visible.
constexpr double kEnergySurplusLimit = 1.0;

} // namespace

void SphModel::add_wall(WallDefinition wall) {
    if (solver_) {
        throw std::logic_error("SphModel::add_wall after build()");
    }
    added_walls_.push_back(std::move(wall));
}

double SphModel::support_radius() const {
    return SmoothingKernel(options_.kernel, options_.smoothing_length, dimension_).support_radius();
}

int SphModel::body_id(const std::string& name) const {
    for (std::size_t b = 0; b < body_names_.size(); ++b) {
        if (body_names_[b] == name) {
            return static_cast<int>(b);
        }
    }
    return -1;
}

void SphModel::finish_build() {
    initial_position_ = particles().position;
    initial_velocity_ = particles().velocity;
    parts_.add(escape_part(EscapeWatch(particles(), gravity_, dimension_), particles(),
                           [this](int body) { return body_name(body); }));
    if (!phases_->sequence().empty()) {
        parts_.add(phases_);
    }
    if (!interactions_) {
        compute_accelerations();
    }
}

std::vector<std::string> SphModel::start_warnings(const ScenePlaces& places) const {
    std::vector<std::string> warnings;
    for (std::size_t b = 0; b < thin_warnings_.size(); ++b) {
        const auto& sources = sources_->sources();
        const bool filled = std::any_of(sources.begin(), sources.end(), [b](const auto& s) {
            return s.body == static_cast<int>(b);
        });
        if (!thin_warnings_[b].empty() && !filled) {
            warnings.push_back(thin_warnings_[b]);
        }
    }
    if (solver_) {
        const std::vector<Wall>& walls = solver_->walls();
        check_wall_overlaps(places, particles(), walls, *sources_, body_names_, spacing_,
                            dimension_, solver_->kernel().support_radius());
        for (std::string& w :
             check_start_gaps(places, particles(), walls, *sources_, body_names_, solver_->kernel(),
                              solver_->options().contact, gravity_.norm(), spacing_, dimension_)) {
            warnings.push_back(std::move(w));
        }
        for (std::string& w :
             check_sinks_hold_bodies(places, particles(), *sinks_, *sources_, body_names_)) {
            warnings.push_back(std::move(w));
        }
        for (std::string& w : outlet_reach_warnings(places, particles(), walls, *sinks_, *sources_,
                                                    gravity_, spacing_, dimension_)) {
            warnings.push_back(std::move(w));
        }
    }
    return warnings;
}

std::vector<FrictionPair> SphModel::added_wall_friction(const std::vector<Wall>& walls) const {
    std::vector<FrictionPair> pairs;
    const std::size_t first_added = walls.size() - added_walls_.size();
    for (std::size_t k = 0; k < added_walls_.size(); ++k) {
        for (const auto& f : added_walls_[k].friction) {
            pairs.push_back(
                {body_id(f.body), walls[first_added + k].body_id, f.mu_static, f.mu_kinetic});
        }
    }
    return pairs;
}

void SphModel::append_added_walls(std::vector<Wall>& walls) {
    for (WallDefinition& added : added_walls_) {
        const int index = static_cast<int>(walls.size());
        Wall wall = sph::add_wall(particles_, added.name, index,
                                  static_cast<int>(body_names_.size()) + index, added.points,
                                  added.spacing, 1.0, dimension_);
        wall.normals = std::move(added.normals);
        wall.samples = std::move(added.samples);
        wall.two_sided = added.two_sided;
        wall.bodies = std::move(added.bodies);
        for (std::size_t k = 0; k < added.velocities.size(); ++k) {
            particles_.velocity[static_cast<std::size_t>(wall.first) + k] = added.velocities[k];
        }
        wall.centre = added.centre;
        wall.driver = std::move(added.driver);
        walls.push_back(std::move(wall));
    }
}

void SphModel::make_solver(const SphOptions& options, std::vector<Wall> walls) {
    SphSolver::MaterialList list;
    for (int k = 0; k < materials_->size(); ++k) {
        list.push_back(&(*materials_)[k]);
    }
    solver_ = std::make_unique<SphSolver>(std::move(particles_), std::move(list), options,
                                          std::move(walls));
    particles_ = ParticleSet{};
}

const std::string& SphModel::body_name(int body_id) const {
    const auto bodies = static_cast<int>(body_names_.size());
    if (body_id < bodies || !solver_) {
        return body_names_[static_cast<std::size_t>(body_id)];
    }
    return solver_->walls()[static_cast<std::size_t>(body_id - bodies)].name;
}

void SphModel::set_output(io::OutputStreams& output) {
    output_ = &output;
}

Index SphModel::add_body(std::string name, int material, const std::vector<Vec3>& points,
                         const Vec3& velocity, double spacing) {
    spacing_ = spacing;
    const auto& law = (*materials_)[material];
    // Said once the sources are known (start_warnings): a seed layer a source fills is no
    // warning.
    thin_warnings_.push_back(thin_body_warning(points, spacing, dimension_, name));
    const double particle_mass = law.density() * std::pow(spacing, dimension_);
    const int body_index = static_cast<int>(body_names_.size());
    const Index first = particles_.size();
    for (const Vec3& x : points) {
        particles_.add(x, velocity, particle_mass, law.density(), body_index, material,
                       law.state_size());
        const Index i = particles_.size() - 1;
        auto state = std::span(particles_.state)
                         .subspan(static_cast<std::size_t>(
                                      particles_.state_offset[static_cast<std::size_t>(i)]),
                                  static_cast<std::size_t>(law.state_size()));
        law.initialise_state(state);
    }
    body_names_.push_back(std::move(name));
    body_material_.push_back(material);
    return first;
}

std::string SphModel::record_rounding(const std::string& body,
                                      const std::vector<RoundedSize>& rounded, double spacing) {
    if (rounded.empty()) {
        return "";
    }
    // A note, not a warning: every lattice rounds what it does not tile, and the run is as
    // valid; but the body's size, and with it its mass, is the filled one.
    std::ostringstream note;
    note << "grainload: note: body \"" << body << "\" is filled by the " << spacing * 1e3
         << " mm lattice to another size than drawn:";
    for (const RoundedSize& r : rounded) {
        const std::string axis(1, static_cast<char>('x' + r.axis));
        note << ' ' << axis << ' ' << r.drawn * 1e3 << " mm drawn, " << r.filled * 1e3
             << " mm filled (" << std::lround(r.filled / spacing) << " cells);";
        const std::string source =
            "the size drawn along " + axis + "; the value is the extent of the particles' cells";
        body_sizes_.push_back({"body_" + body + "_size_" + axis, r.filled, "m", r.drawn, source});
    }
    note << " summary.json: body_" << body << "_size_*";
    return note.str();
}

double SphModel::stable_time_step() const {
    if (time_step_ > 0.0) {
        return time_step_;
    }
    return solver_ ? solver_->stable_time_step() : std::numeric_limits<double>::infinity();
}

void SphModel::compute_accelerations() {
    const auto n = static_cast<std::size_t>(particles_.size());
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
        particles_.acceleration[i] = gravity_;
    }
}

void SphModel::advance(double t, double dt) {
    if (solver_) {
        solver_->set_time(t);
        solver_->step(dt);
        parts_.after_step(t, dt);
        if (!per_window_) {
            exchange_particles(t, dt);
        }
        parts_.end_step(t + dt);
        return;
    }
    // Velocity Verlet (kick-drift-kick): second order, and exact for a constant acceleration,
    // which the free-fall case checks to round-off.
    const auto n = static_cast<std::size_t>(particles_.size());
    auto& p = particles_;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
        p.velocity[i] += 0.5 * dt * p.acceleration[i];
        p.position[i] += dt * p.velocity[i];
    }
    compute_accelerations();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
        p.velocity[i] += 0.5 * dt * p.acceleration[i];
    }
}

std::optional<std::string> SphModel::diagnose() const {
    const auto& p = particles();
    // The internal energy too: no other field reads it, so a NaN there (a NaN heat) would
    // reach the energy books unseen.
    auto fault = [&p](std::size_t i) -> const char* {
        return !p.position[i].allFinite()                            ? "position"
               : !p.velocity[i].allFinite()                          ? "velocity"
               : !p.stress[i].allFinite()                            ? "stress"
               : !std::isfinite(p.density[i]) || p.density[i] <= 0.0 ? "density"
               : !std::isfinite(p.internal_energy[i])                ? "internal energy"
                                                                     : nullptr;
    };
    // Every step, so scanned by all threads; the lowest faulty index is the serial scan's.
    const std::size_t n = p.position.size();
    std::size_t first = n;
#pragma omp parallel for schedule(static) reduction(min : first)
    for (std::size_t i = 0; i < n; ++i) {
        if (fault(i) != nullptr) {
            first = std::min(first, i);
        }
    }
    if (first < n) {
        std::ostringstream out;
        out << "particle " << first << " (body " << body_name(p.body_id[first])
            << ") has a non-finite or non-physical " << fault(first);
        return out.str();
    }
    if (auto diagnosis = parts_.diagnose()) {
        return diagnosis;
    }
    if (solver_) {
        return solver_->energy_ledger().check(solver_->held_energy(), kEnergySurplusLimit);
    }
    return std::nullopt;
}

std::vector<std::string> SphModel::take_events() {
    // The parts' events of the steps since the last call (a settle), the phases' ends last,
    // which follow them within a step.
    return parts_.take_events();
}

} // namespace grainload::sph
