#include "sph/sph_model.hpp"

#include "io/case_table.hpp"
#include "sph/body_generator.hpp"
#include "sph/scene_limits.hpp"
#include "sph/sph_case_reader.hpp"
#include "sph/wall_bodies.hpp"

#include <cmath>
#include <filesystem>
#include <iostream>
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

double pressure_of(const Voigt6& s) {
    return -(s[0] + s[1] + s[2]) / 3.0;
}

double von_mises_of(const Voigt6& s) {
    const double p = (s[0] + s[1] + s[2]) / 3.0;
    const double dev = (s[0] - p) * (s[0] - p) + (s[1] - p) * (s[1] - p) + (s[2] - p) * (s[2] - p) +
                       2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
    return std::sqrt(1.5 * dev);
}

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
    model->interactions_ = sph.boolean_or("interactions", true);
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
    return model;
}

void SphModel::add_wall(WallDefinition wall) {
    if (solver_) {
        throw std::logic_error("SphModel::add_wall after build()");
    }
    added_walls_.push_back(std::move(wall));
}

double SphModel::support_radius(const io::CaseTable& root) const {
    const SphOptions options = read_sph_options(root.table("sph"), dimension_, spacing_, gravity_);
    return SmoothingKernel(options.kernel, options.smoothing_length, dimension_).support_radius();
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
    if (sph.has("symmetry") && !interactions_) {
        sph.fail("symmetry", "mirror images act through the particle interactions: expected "
                             "interactions = true with [[sph.symmetry]]");
    }
    if (!added_walls_.empty() && !interactions_) {
        sph.fail("interactions", "walls coupled to shells need the SPH solver: expected "
                                 "interactions = true");
    }
    if (interactions_) {
        build_solver(sph);
        read_probes(sph);
        check_gravity_strain(root, particles(), *materials_, body_names_, gravity_, spacing_,
                             solver_->options().contact.stiffness);
        if (const std::string warning =
                impact_warning(particles(), body_names_, solver_->options().contact.stiffness);
            !warning.empty()) {
            std::cerr << "grainload: warning: " << warning << '\n';
        }
    }
    build_outlets(sph);
    if (solver_) {
        wall_maps_ = WallMapSet(sph, solver_->particles(), solver_->walls(), dimension_);
    } else if (sph.has("wall_map")) {
        sph.fail("wall_map", "wall loads come from the SPH solver: expected interactions = true");
    }
    if (const auto heap = sph.optional_table("heap")) {
        heap_.emplace(*heap, body_names_, particles(), spacing_, gravity_, dimension_);
    }
    initial_position_ = particles().position;
    initial_velocity_ = particles().velocity;
    escape_watch_ = EscapeWatch(particles(), gravity_, dimension_);
    if (!interactions_) {
        compute_accelerations();
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
    SphOptions options = read_sph_options(sph, dimension_, spacing_, gravity_);
    SmoothingKernel kernel(options.kernel, options.smoothing_length, dimension_);
    auto walls = read_rigid_walls(sph, particles_, dimension_, spacing_, kernel.support_radius(),
                                  static_cast<int>(body_names_.size()));
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
    options.symmetry = read_symmetry_planes(sph, particles_, walls, body_names_, dimension_,
                                            spacing_, kernel.support_radius());
    if (!options.symmetry.empty() && options.formulation == Formulation::total_lagrangian) {
        sph.fail("symmetry", "mirror images are found anew as particles move, which the "
                             "total-Lagrangian reference pairs do not do: expected formulation = "
                             "\"updated_lagrangian\" with [[sph.symmetry]]");
    }
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

const std::string& SphModel::body_name(int body_id) const {
    const auto bodies = static_cast<int>(body_names_.size());
    if (body_id < bodies || !solver_) {
        return body_names_[static_cast<std::size_t>(body_id)];
    }
    return solver_->walls()[static_cast<std::size_t>(body_id - bodies)].name;
}

void SphModel::set_output_directory(const std::string& directory) {
    output_directory_ = directory;
    wall_writer_.reset();
    probe_writer_.reset();
}

void SphModel::read_probes(const io::CaseTable& sph) {
    const auto& p = solver_->particles();
    for (const auto& table : sph.array_of_tables("probe")) {
        const Vec3 x = table.vector("position", dim::kLength);
        Index nearest = -1;
        double best = std::numeric_limits<double>::infinity();
        for (Index i = 0; i < p.size(); ++i) {
            const double d = (p.position[i] - x).norm();
            if (!p.is_wall(i) && d < best) {
                best = d;
                nearest = i;
            }
        }
        probes_.emplace_back(table.string("name"), nearest);
    }
}

void SphModel::write_output_rows(double time) const {
    if (output_directory_.empty() || !(time > last_row_time_)) {
        return;
    }
    last_row_time_ = time;
    if (!solver_->walls().empty()) {
        if (!wall_writer_) {
            wall_writer_ = std::make_unique<WallForceWriter>(output_directory_);
        }
        wall_writer_->write(time, solver_->walls());
    }
    if (!sinks_.empty()) {
        sinks_.record(time);
        sinks_.write_csv(output_directory_);
    }
    if (!wall_maps_.empty()) {
        wall_maps_.record(time, output_directory_);
    }
    if (probes_.empty()) {
        return;
    }
    if (!probe_writer_) {
        std::filesystem::create_directories(output_directory_);
        probe_writer_ = std::make_unique<std::ofstream>(output_directory_ + "/probes.csv");
        *probe_writer_ << "time_s,probe,particle,stress_xx_Pa,stress_yy_Pa,stress_zz_Pa,"
                          "stress_xy_Pa,von_mises_Pa,pressure_Pa,plastic_strain\n";
    }
    const auto& p = solver_->particles();
    for (const auto& [name, i] : probes_) {
        if (i < 0) { // its particle left through a sink
            continue;
        }
        const Voigt6& s = p.stress[i];
        *probe_writer_ << time << ',' << name << ',' << i << ',' << s[0] << ',' << s[1] << ','
                       << s[2] << ',' << s[3] << ',' << von_mises_of(s) << ',' << pressure_of(s)
                       << ',' << p.plastic_strain[i] << '\n';
    }
    probe_writer_->flush();
}

void SphModel::add_body(const io::CaseTable& body, int dimension) {
    std::string name = body.string("name");
    for (const auto& existing : body_names_) {
        if (existing == name) {
            body.fail("name", "a body called \"" + name + "\" is already defined");
        }
    }
    const int material = materials_->index_of(body, "material");
    const double spacing = body.positive_quantity("spacing", dim::kLength);
    if (spacing_ > 0.0 && std::abs(spacing - spacing_) > 1e-9 * spacing_) {
        body.fail("spacing", "every body must use the same particle spacing (one smoothing "
                             "length for the scene); the first body uses " +
                                 std::to_string(spacing_) + " m");
    }
    spacing_ = spacing;
    const Vec3 velocity = body.vector_or("velocity", dim::kVelocity, Vec3::Zero());
    const auto& law = (*materials_)[material];
    const auto points =
        generate_body_points(body.table("shape"), spacing, dimension, law.density());
    if (const std::string warning = thin_body_warning(points, spacing, dimension, name);
        !warning.empty()) {
        std::cerr << "grainload: warning: " << warning << '\n';
    }
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
        wall_maps_.accumulate(solver_->particles(), solver_->walls(), t, dt);
        if (settle_ && settle_->record(t + dt, solver_->kinetic_energy())) {
            std::ostringstream event;
            event << "settled at t = " << t + dt << " s: the material's kinetic energy "
                  << solver_->kinetic_energy() << " J is below " << settle_->fraction()
                  << " of its peak " << settle_->peak() << " J";
            events_.push_back(event.str());
        }
        if (!per_window_) {
            exchange_particles(t, dt);
        }
        if (heap_) {
            heap_->record(t + dt, solver_->particles());
        }
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
    for (std::size_t i = 0; i < p.position.size(); ++i) {
        // The internal energy too: no other field reads it, so a NaN there (a NaN heat) would
        // reach the energy books unseen.
        const char* bad = !p.position[i].allFinite()                            ? "position"
                          : !p.velocity[i].allFinite()                          ? "velocity"
                          : !p.stress[i].allFinite()                            ? "stress"
                          : !std::isfinite(p.density[i]) || p.density[i] <= 0.0 ? "density"
                          : !std::isfinite(p.internal_energy[i])                ? "internal energy"
                                                                                : nullptr;
        if (bad != nullptr) {
            std::ostringstream out;
            out << "particle " << i << " (body " << body_name(p.body_id[i])
                << ") has a non-finite or non-physical " << bad;
            return out.str();
        }
    }
    if (auto escape = escape_watch_.check(p, [this](int body) { return body_name(body); })) {
        return escape;
    }
    if (solver_) {
        return solver_->energy_ledger().check(solver_->held_energy(), kEnergySurplusLimit);
    }
    return std::nullopt;
}

void SphModel::append_blocks(io::Frame& frame) const {
    const auto& p = particles();
    for (std::size_t b = 0; b < body_names_.size(); ++b) {
        io::Block block;
        block.name = body_names_[b];
        io::FieldArray velocity{"velocity", 3, {}}, displacement{"displacement", 3, {}};
        io::FieldArray stress{"stress", 6, {}}, pressure{"pressure", 1, {}};
        io::FieldArray von_mises{"von_mises", 1, {}}, plastic{"plastic_strain", 1, {}};
        io::FieldArray density{"density", 1, {}}, body{"body_id", 1, {}};
        io::FieldArray material{"material_id", 1, {}};
        for (std::size_t i = 0; i < p.position.size(); ++i) {
            if (p.body_id[i] != static_cast<int>(b)) {
                continue;
            }
            block.points.push_back(p.position[i]);
            const Vec3 u = p.position[i] - initial_position_[i];
            velocity.values.insert(velocity.values.end(), p.velocity[i].begin(),
                                   p.velocity[i].end());
            displacement.values.insert(displacement.values.end(), u.begin(), u.end());
            stress.values.insert(stress.values.end(), p.stress[i].begin(), p.stress[i].end());
            pressure.values.push_back(pressure_of(p.stress[i]));
            von_mises.values.push_back(von_mises_of(p.stress[i]));
            plastic.values.push_back(p.plastic_strain[i]);
            density.values.push_back(p.density[i]);
            body.values.push_back(p.body_id[i]);
            material.values.push_back(p.material_id[i]);
        }
        block.point_arrays = {velocity, displacement, stress, pressure, von_mises,
                              plastic,  density,      body,   material};
        frame.blocks.push_back(std::move(block));
    }
    append_wall_blocks(frame);
    // Frames are collected exactly at the output instants: wall loads and probes go with them.
    if (solver_) {
        write_output_rows(frame.time);
    }
}

void SphModel::append_wall_blocks(io::Frame& frame) const {
    if (!solver_ || solver_->walls().empty()) {
        return;
    }
    const auto& p = solver_->particles();
    for (const Wall& wall : solver_->walls()) {
        io::Block block;
        block.name = "wall_" + wall.name;
        io::FieldArray velocity{"velocity", 3, {}}, body{"body_id", 1, {}};
        for (Index k = wall.first; k < wall.first + wall.count; ++k) {
            block.points.push_back(p.position[k]);
            velocity.values.insert(velocity.values.end(), p.velocity[k].begin(),
                                   p.velocity[k].end());
            body.values.push_back(wall.body_id);
        }
        block.point_arrays = {velocity, body};
        frame.blocks.push_back(std::move(block));
    }
}

void SphModel::append_results(double t, std::vector<io::ResultFigure>& results) const {
    if (heap_) {
        heap_->append_results(particles(), results);
    }
    if (audit_) {
        sinks_.append_results(scene_mass(), sources_.created(), results);
    }
    wall_maps_.append_results(results);
    if (settle_) {
        // null (NaN) when the scene never settled.
        results.push_back(
            {"settle_time",
             settle_->settled() ? settle_->settle_time() : std::numeric_limits<double>::quiet_NaN(),
             "s", std::nullopt, ""});
        results.push_back({"settle_peak_kinetic_energy", settle_->peak(), "J", std::nullopt, ""});
    }
    if (solver_) {
        results.push_back({"kinetic_energy", solver_->kinetic_energy(), "J", std::nullopt, ""});
        results.push_back({"internal_energy", solver_->internal_energy(), "J", std::nullopt, ""});
        const EnergyLedger& ledger = solver_->energy_ledger();
        results.push_back({"gravity_work", ledger.gravity_work(), "J", std::nullopt, ""});
        results.push_back({"moving_wall_work", ledger.wall_work(), "J", std::nullopt, ""});
        if (audit_) {
            results.push_back({"removed_energy", ledger.removed_held(), "J", std::nullopt, ""});
            results.push_back(
                {"removed_contact_energy", ledger.removed_contact(), "J", std::nullopt, ""});
        }
        if (!sources_.empty()) {
            results.push_back({"created_energy", ledger.created_held(), "J", std::nullopt, ""});
            results.push_back(
                {"created_contact_energy", ledger.created_contact(), "J", std::nullopt, ""});
        }
        const double contact = solver_->contact_energy();
        results.push_back({"contact_energy", contact, "J", std::nullopt, ""});
        // JSON writes a non-finite figure as null: the statement says which entry made it so.
        const double held = solver_->held_energy();
        const auto unbalanced = ledger.non_finite(held, contact);
        results.push_back({"energy_balance_error", ledger.balance_error(held, contact), "",
                           std::nullopt, unbalanced ? "not finite: " + *unbalanced : ""});
        if (!solver_->options().friction.empty()) {
            results.push_back({"wall_friction_work", solver_->wall_contact().friction_work(), "J",
                               std::nullopt, ""});
        }
        for (const Wall& wall : solver_->walls()) {
            for (int a = 0; a < 3; ++a) {
                const std::string axis(1, static_cast<char>('x' + a));
                results.push_back(
                    {"wall_" + wall.name + "_force_" + axis, wall.force[a], "N", std::nullopt, ""});
            }
        }
        return;
    }
    // Without interactions every particle is a point mass in uniform gravity: its exact path is
    // x0 + v0 t + g t^2 / 2, the reference for the whole pipeline (case free_fall).
    double max_error = 0.0;
    double mean_z = 0.0;
    double mean_z_exact = 0.0;
    const auto n = particles_.position.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 exact = initial_position_[i] + t * initial_velocity_[i] + 0.5 * t * t * gravity_;
        max_error = std::max(max_error, (particles_.position[i] - exact).norm());
        mean_z += particles_.position[i].z() / static_cast<double>(n);
        mean_z_exact += exact.z() / static_cast<double>(n);
    }
    results.push_back({"centre_height", mean_z, "m", mean_z_exact, "z0 + v0 t + g t^2/2"});
    results.push_back({"max_position_error", max_error, "m", std::nullopt, ""});
}

std::vector<std::string> SphModel::take_events() {
    return std::exchange(events_, {});
}

} // namespace grainload::sph
