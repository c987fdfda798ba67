#include "sph/sph_model.hpp"

#include "io/case_table.hpp"
#include "io/named_index.hpp"
#include "materials/material_case_reader.hpp"
#include "particles/particles_case_reader.hpp"
#include "sph/body_shape_reader.hpp"
#include "sph/outlet_reach.hpp"
#include "sph/probes.hpp"
#include "sph/scene_limits.hpp"
#include "sph/scene_monitors.hpp"
#include "sph/sph_case_reader.hpp"
#include "sph/start_gap.hpp"
#include "sph/wall_bodies.hpp"
#include "sph/wall_map_reader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

namespace grainload::sph {

namespace dim = io::dimension;

namespace {

// The run is stopped as unstable when its particles hold more surplus energy than all the
// energy that passed through it (EnergyLedger). Physically the surplus cannot exceed what the
// contact potential held at the start and has since released, which the throughput includes,
// so a ratio of 1 is unreachable by a sound run whatever its contacts do; an instability grows
// exponentially and passes it within a few steps of becoming visible.
constexpr double kEnergySurplusLimit = 1.0;

} // namespace

std::unique_ptr<SphModel> SphModel::from_case(const io::CaseTable& root,
                                              const io::SceneSettings& scene,
                                              const materials::MaterialLibrary& materials) {
    auto model = read_bodies(root, scene, materials);
    model->build(root);
    return model;
}

std::unique_ptr<SphModel> SphModel::read_bodies(const io::CaseTable& root,
                                                const io::SceneSettings& scene,
                                                const materials::MaterialLibrary& materials) {
    std::unique_ptr<SphModel> model(new SphModel(materials));
    const io::CaseTable sph = root.table("sph");
    model->gravity_ = scene.gravity;
    model->dimension_ = scene.dimension;
    model->time_step_ = sph.positive_quantity_or("time_step", dim::kTime, 0.0);
    model->interactions_ =
        sph.boolean_or("interactions", io::default_value(kSphKeys, "interactions") != 0.0);
    if (!model->interactions_ && model->time_step_ == 0.0) {
        sph.fail("time_step", "free flight (interactions = false) has no CFL limit: expected a "
                              "fixed time_step, e.g. \"1 ms\"");
    }
    const auto bodies = sph.array_of_tables("body");
    if (bodies.empty()) {
        sph.fail("", "expected at least one [[sph.body]]");
    }
    for (const auto& body : bodies) {
        model->add_body(body, scene.dimension);
    }
    if (model->interactions_) {
        model->options_ =
            read_sph_options(sph, model->dimension_, model->spacing_, model->gravity_);
    }
    return model;
}

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

void SphModel::build(const io::CaseTable& root) {
    const io::CaseTable sph = root.table("sph");
    const ScenePlaces places = read_scene_places(root);
    phases_ = particles::read_phases(root);
    if (!phases_.empty() && !interactions_) {
        root.fail("phase", "phases act on the SPH solver's walls, sources and sinks: expected "
                           "interactions = true");
    }
    for (const char* table : {"symmetry", "periodic"}) {
        if (sph.has(table) && !interactions_) {
            sph.fail(table, std::string("ghost images act through the particle interactions: "
                                        "expected interactions = true with [[sph.") +
                                table + "]]");
        }
    }
    if (!added_walls_.empty() && !interactions_) {
        sph.fail("interactions", "walls coupled to shells need the SPH solver: expected "
                                 "interactions = true");
    }
    if (interactions_) {
        build_solver(sph);
        if (auto probes = ProbeSet::place(read_probe_settings(sph), solver_->particles())) {
            parts_.add(std::move(probes));
        }
        check_gravity_strain(places, particles(), *materials_, body_names_, gravity_, spacing_,
                             solver_->options().contact.stiffness);
        if (const std::string warning =
                impact_warning(particles(), body_names_, solver_->options().contact.stiffness);
            !warning.empty()) {
            sph.warn(warning);
        }
    }
    build_outlets(sph);
    check_start(sph, places);
    check_phase_conditions(root);
    if (solver_) {
        apply_phase_starts();
    }
    if (solver_) {
        WallMapSet maps = read_wall_maps(sph, solver_->particles(), solver_->walls(), dimension_);
        if (!maps.empty()) {
            parts_.add(wall_map_part(std::move(maps), solver_->particles(), solver_->walls()));
        }
    } else if (sph.has("wall_map")) {
        sph.fail("wall_map", "wall loads come from the SPH solver: expected interactions = true");
    }
    if (const auto heap = sph.optional_table("heap")) {
        parts_.add(heap_part(HeapMonitor(read_heap_settings(*heap, body_names_, gravity_),
                                         particles(), spacing_, gravity_, dimension_),
                             particles()));
    }
    initial_position_ = particles().position;
    initial_velocity_ = particles().velocity;
    parts_.add(escape_part(EscapeWatch(particles(), gravity_, dimension_), particles(),
                           [this](int body) { return body_name(body); }));
    if (!interactions_) {
        compute_accelerations();
    }
}

void SphModel::check_start(const io::CaseTable& sph, const ScenePlaces& places) const {
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
    for (const std::string& warning : warnings) {
        sph.warn(warning);
    }
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

void SphModel::build_solver(const io::CaseTable& sph) {
    SphOptions options = options_;
    SmoothingKernel kernel(options.kernel, options.smoothing_length, dimension_);
    auto walls = read_rigid_walls(sph, particles_, dimension_, spacing_, kernel.support_radius(),
                                  static_cast<int>(body_names_.size()), &phases_);
    const auto wall_tables = sph.array_of_tables("wall");
    for (std::size_t k = 0; k < wall_tables.size(); ++k) {
        walls[k].bodies = read_wall_bodies(wall_tables[k], body_names_);
    }
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
    options.friction = read_friction_pairs(sph, body_names_, walls);
    for (const FrictionPair& pair : added_wall_friction(walls)) {
        options.friction.push_back(pair);
    }
    read_ghost_boundaries(sph, walls, kernel.support_radius(), options);
    if (!options.friction.empty() && !(options.contact.stiffness > 0.0)) {
        sph.fail("friction", "wall friction acts through the contact force: expected an "
                             "[sph.contact] table with a stiffness");
    }
    SphSolver::MaterialList list;
    for (int k = 0; k < materials_->size(); ++k) {
        list.push_back(&(*materials_)[k]);
    }
    solver_ = std::make_unique<SphSolver>(std::move(particles_), std::move(list), options,
                                          std::move(walls));
    particles_ = ParticleSet{};
    if (time_step_ > 0.0) {
        const double limit = solver_->stable_time_step();
        if (time_step_ > limit) {
            std::ostringstream message;
            message << "time step " << time_step_ << " s is above the CFL limit " << limit
                    << " s (cfl_safety * h / (c + |v|), c = sqrt((K + 4G/3)/rho)); use at most "
                    << limit << " s or leave time_step out";
            sph.fail("time_step", message.str());
        }
    }
}

void SphModel::read_ghost_boundaries(const io::CaseTable& sph, std::vector<Wall>& walls,
                                     double support_radius, SphOptions& options) const {
    for (const char* table : {"symmetry", "periodic"}) {
        if (sph.has(table) && options.formulation == Formulation::total_lagrangian) {
            sph.fail(table, std::string("ghost images are found anew as particles move, which "
                                        "the total-Lagrangian reference pairs do not do: "
                                        "expected formulation = \"updated_lagrangian\" with "
                                        "[[sph.") +
                                table + "]]");
        }
    }
    options.symmetry = read_symmetry_planes(sph, particles_, walls, body_names_, dimension_,
                                            spacing_, support_radius);
    options.periodic =
        read_periodic_axes(sph, particles_, walls, body_names_, options.symmetry, dimension_,
                           support_radius + options.verlet_skin_factor * options.smoothing_length);
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

void SphModel::add_body(const io::CaseTable& body, int dimension) {
    std::string name = body.string("name");
    io::refuse_repeated_name(body, body_names_, name, "body");
    const int material = materials::read_material_index(*materials_, body, "material");
    const double spacing = body.positive_quantity("spacing", dim::kLength);
    if (spacing_ > 0.0 && std::abs(spacing - spacing_) > 1e-9 * spacing_) {
        body.fail("spacing", "every body must use the same particle spacing (one smoothing "
                             "length for the scene); the first body uses " +
                                 std::to_string(spacing_) + " m");
    }
    spacing_ = spacing;
    const Vec3 velocity = body.vector_or("velocity", dim::kVelocity, Vec3::Zero());
    const auto& law = (*materials_)[material];
    std::vector<RoundedSize> rounded;
    const auto points =
        generate_body_points(body.table("shape"), spacing, dimension, law.density(), &rounded);
    // Said once the sources are known (check_start): a seed layer a source fills is no warning.
    thin_warnings_.push_back(thin_body_warning(points, spacing, dimension, name));
    report_rounding(body, name, rounded, spacing);
    const double particle_mass = law.density() * std::pow(spacing, dimension);
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
    if (body.has("clamp") && !interactions_) {
        body.fail("clamp", "clamped particles need the SPH solver: expected interactions = true");
    }
    read_clamps(body, particles_, first, dimension);
    read_initial_stress(body, particles_, first, gravity_, spacing);
    body_names_.push_back(std::move(name));
    body_material_.push_back(material);
}

void SphModel::report_rounding(const io::CaseTable& table, const std::string& body,
                               const std::vector<RoundedSize>& rounded, double spacing) {
    if (rounded.empty()) {
        return;
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
    table.notify(note.str());
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
        record_kinetic_energy(t + dt);
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
    // The parts' events of the steps since the last call (a settle), then the phases' ends,
    // which follow them within a step.
    std::vector<std::string> events = parts_.take_events();
    events.insert(events.end(), events_.begin(), events_.end());
    events_.clear();
    return events;
}

} // namespace grainload::sph
