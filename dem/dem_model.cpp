#include "dem/dem_model.hpp"

#include "dem/grain_generator.hpp"
#include "dem/grain_motion.hpp"
#include "dem/triaxial_cell.hpp"
#include "io/case_error.hpp"
#include "materials/material_library.hpp"
#include "particles/compact.hpp"
#include "particles/mass_audit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

namespace grainload::dem {

namespace {

/// The Verlet skin: the declared one, else 0.4 of the largest radius (a rebuild every few
/// dozen steps of a settling packing).
double skin_of(const DemSettings& settings, double largest) {
    return settings.skin.value_or(0.4 * largest);
}

double largest_radius(const DemSettings& settings) {
    double largest = 0.0;
    for (const BodySettings& body : settings.bodies) {
        largest = std::max(largest, body.radius_max * body.largest_sphere());
    }
    return largest;
}

/// The pairs' neighbour range: two of the largest spheres' radii, and the reach of cohesion
/// between the heaviest grains (its pull grows with the lighter grain's mass).
double pair_range(const DemSettings& settings, const materials::MaterialLibrary& materials) {
    double heaviest = 0.0;
    for (const BodySettings& body : settings.bodies) {
        heaviest = std::max(
            heaviest, body.volume_ratio() *
                          sphere_mass(body.radius_max, materials[body.material].elastic().density));
    }
    return 2.0 * largest_radius(settings) +
           cohesion_reach(settings.law, settings.law.cohesion_pull, heaviest);
}

} // namespace

DemModel::DemModel(DemSettings settings, const io::SceneSettings& scene,
                   const materials::MaterialLibrary& materials)
    : settings_(std::move(settings)), gravity_(scene.gravity),
      neighbours_(pair_range(settings_, materials), skin_of(settings_, largest_radius(settings_)),
                  3) {
    scratch_.record = settings_.contact_forces;
    for (std::size_t b = 0; b < settings_.bodies.size(); ++b) {
        const BodySettings& body = settings_.bodies[b];
        const auto& elastic = materials[body.material].elastic();
        body_names_.push_back(body.name);
        body_materials_.push_back(materials.name(body.material));
        body_elastic_.push_back({elastic.young(), elastic.poisson()});
        body_density_.push_back(elastic.density);
        place_grains(body, static_cast<int>(b), elastic.density, grains_, spheres_);
    }
    if (over_damped()) {
        throw io::CaseError(settings_.damping_where +
                            ": gamma_n over-damps a pair of grains, or a grain on a wall (its "
                            "dashpot stops it before it rebounds): expected a smaller gamma_n");
    }
    if (settings_.time_step &&
        *settings_.time_step > 0.1 * shortest_contact_time(settings_.impact_velocity)) {
        throw io::CaseError(settings_.time_step_where + ": a step longer than a tenth of the " +
                            "shortest contact time (" +
                            std::to_string(shortest_contact_time(settings_.impact_velocity)) +
                            " s) resolves no contact: expected a shorter time_step");
    }
    combine_body_pairs();
    walls_ = settings_.walls;
    start_position_ = grains_.position;
    sinks_ = settings_.sinks ? settings_.sinks : std::make_shared<particles::SinkSet>();
    sources_ = std::make_shared<GrainSources>(settings_.sources, settings_.bodies, body_density_,
                                              spheres_, walls_);
    if (!sinks_->empty()) {
        parts_.add(sinks_);
    }
    if (!sources_->empty()) {
        parts_.add(sources_);
    }
    if (!sinks_->empty() || !sources_->empty()) {
        parts_.add(std::make_shared<particles::MassAudit>(
            grains_.total_mass(), 3,
            particles::MassAudit::Books{[this] { return grains_.total_mass(); },
                                        [this] { return sinks_->discharged(); },
                                        [this] { return sources_->created_mass(); }}));
    }
    add_wall_maps();
    add_triaxial();
    add_phases();
    evaluate(0.0);
    start_energy_ = energy().total();
}

void DemModel::combine_body_pairs() {
    for (std::size_t a = 0; a < body_elastic_.size(); ++a) {
        for (const GrainElastic& b : body_elastic_) {
            PairProperties pair;
            combine_elastic(body_elastic_[a], b, pair);
            pair.friction = settings_.law.friction;
            pair.rolling_friction = settings_.law.rolling_friction;
            body_pairs_.push_back(pair);
        }
        PairProperties wall;
        combine_elastic(body_elastic_[a], std::nullopt, wall);
        wall.friction = settings_.law.wall_friction;
        wall.rolling_friction = settings_.law.wall_rolling_friction;
        body_walls_.push_back(wall);
    }
    if (settings_.triaxial && settings_.triaxial->consolidation_friction) {
        consolidation_pairs_ = body_pairs_;
        for (PairProperties& pair : consolidation_pairs_) {
            pair.friction = *settings_.triaxial->consolidation_friction;
        }
        consolidating_ = settings_.triaxial->consolidates(0.0);
    }
}

double DemModel::pair_contact_time(std::size_t a, std::optional<std::size_t> b, bool largest,
                                   double speed) const {
    // The smallest (largest) sphere of the body's smallest (largest) grains.
    const auto radius = [&](std::size_t body) {
        const BodySettings& grains = settings_.bodies[body];
        return largest ? grains.radius_max * grains.largest_sphere()
                       : grains.radius_min * grains.smallest_sphere();
    };
    const auto mass = [&](std::size_t body) {
        return sphere_mass(radius(body), body_density_[body]);
    };
    PairProperties pair;
    pair.mass = mass(a);
    pair.radius = radius(a);
    if (b) {
        pair.mass = mass(a) * mass(*b) / (mass(a) + mass(*b));
        pair.radius = radius(a) * radius(*b) / (radius(a) + radius(*b));
    }
    combine_elastic(body_elastic_[a],
                    b ? std::optional<GrainElastic>(body_elastic_[*b]) : std::nullopt, pair);
    return contact_time(settings_.law, pair, speed);
}

double DemModel::shortest_contact_time(double speed) const {
    double shortest = std::numeric_limits<double>::infinity();
    for (std::size_t a = 0; a < body_elastic_.size(); ++a) {
        if (!settings_.walls.empty()) {
            shortest = std::min(shortest, pair_contact_time(a, std::nullopt, false, speed));
        }
        for (std::size_t b = a; b < body_elastic_.size(); ++b) {
            shortest = std::min(shortest, pair_contact_time(a, b, false, speed));
        }
    }
    return shortest;
}

bool DemModel::over_damped() const {
    // The linear law's dashpot gamma_n m* over-damps the heavier pairs first (its ratio to the
    // critical 2 sqrt(k m*) grows with sqrt(m*)): the largest grains and their walls.
    for (std::size_t a = 0; a < body_elastic_.size(); ++a) {
        for (const bool largest : {false, true}) {
            if (std::isnan(pair_contact_time(a, std::nullopt, largest, 1.0))) {
                return true;
            }
            for (std::size_t b = a; b < body_elastic_.size(); ++b) {
                if (std::isnan(pair_contact_time(a, b, largest, 1.0))) {
                    return true;
                }
            }
        }
    }
    return false;
}

namespace {

/// The grains `source` makes by `end_time`.
double made_by(const SourceSettings& source, double end_time) {
    const double open = std::max(std::min(source.end, end_time) - source.start, 0.0);
    const double made = std::floor(source.rate * open);
    return source.count ? std::min(made, static_cast<double>(*source.count)) : made;
}

} // namespace

Index DemModel::most_grains(double end_time) const {
    double grains = static_cast<double>(grains_.size());
    for (const SourceSettings& source : settings_.sources) {
        grains += made_by(source, end_time);
    }
    return static_cast<Index>(grains);
}

double DemModel::sphere_steps(double steps, double end_time) const {
    double sum = static_cast<double>(spheres_.size()) * steps;
    for (const SourceSettings& source : settings_.sources) {
        const double made = made_by(source, end_time);
        const double mean_arrival = source.start + 0.5 * made / source.rate;
        const double spheres = settings_.bodies[static_cast<std::size_t>(source.body)].spheres;
        sum += spheres * made * steps * std::max(end_time - mean_arrival, 0.0) / end_time;
    }
    return sum;
}

double DemModel::stable_time_step() const {
    if (settings_.time_step) {
        return *settings_.time_step;
    }
    double speed = settings_.impact_velocity;
    if (settings_.law.model == ContactLaw::Model::hertz_mindlin) {
        for (const Vec3& v : grains_.velocity) {
            speed = std::max(speed, 2.0 * v.norm());
        }
    }
    return shortest_contact_time(speed) / settings_.steps_per_contact;
}

void DemModel::evaluate(double time) {
    for (PlaneWall& wall : walls_) {
        wall.move_to(time);
        if (wall.follows()) {
            wall.follow(time);
        }
    }
    neighbours_.update(spheres_.position, {});
    books_ = evaluate_contacts(
        grains_, spheres_, neighbours_, walls_,
        {settings_.law, consolidating_ ? consolidation_pairs_ : body_pairs_, body_walls_, gravity_},
        step_, scratch_);
}

void DemModel::advance(double t, double dt) {
    consolidating_ = settings_.triaxial && settings_.triaxial->consolidates(t);
    if (settings_.integrator == Integrator::predictor_corrector) {
        predictor_corrector_step(t, dt);
    } else {
        verlet_step(t, dt);
    }
    parts_.after_step(t, dt);
    exchange(t, dt);
}

void DemModel::verlet_step(double t, double dt) {
    GrainSet& g = grains_;
    const Index n = g.size();
    const double half = 0.5 * dt;
    momentum_.resize(static_cast<std::size_t>(n));
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        g.velocity[i] += half / g.mass[i] * g.force[i];
        g.position[i] += dt * g.velocity[i];
        if (!(g.inertia[i].x() > 0.0)) {
            continue;
        }
        if (g.isotropic(i)) {
            g.angular_velocity[i] += half / g.inertia[i].x() * g.torque[i];
        } else {
            // A clump: its angular momentum takes the torque's kick; over the step it turns
            // with the angular velocity that momentum has at the step's middle orientation
            // (Euler's equations, the gyroscopic term included, to second order: the midpoint
            // found with one turn by the start's angular velocity).
            momentum_[i] = momentum_of(g.orientation[i], g.inertia[i], g.angular_velocity[i]) +
                           half * g.torque[i];
            const Vec3 start = spin_of(g.orientation[i], g.inertia[i], momentum_[i]);
            const Eigen::Quaterniond middle = rotated(g.orientation[i], half * start);
            g.angular_velocity[i] = spin_of(middle, g.inertia[i], momentum_[i]);
        }
        g.orientation[i] = rotated(g.orientation[i], dt * g.angular_velocity[i]);
    }
    spheres_.place(g);
    step_ = dt;
    evaluate(t + dt);
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        g.velocity[i] += half / g.mass[i] * g.force[i];
        if (!(g.inertia[i].x() > 0.0)) {
            continue;
        }
        if (g.isotropic(i)) {
            g.angular_velocity[i] += half / g.inertia[i].x() * g.torque[i];
        } else {
            g.angular_velocity[i] =
                spin_of(g.orientation[i], g.inertia[i], momentum_[i] + half * g.torque[i]);
        }
    }
}

void DemModel::add_wall_maps() {
    if (settings_.wall_maps.empty()) {
        return;
    }
    scratch_.mapped_walls.assign(walls_.size(), 0);
    for (const particles::WallMapSet::Map& map : settings_.wall_maps) {
        for (const int w : map.walls) {
            scratch_.mapped_walls[static_cast<std::size_t>(w)] = 1;
        }
    }
    // Each contact's force on the wall at its point, sphere by sphere in order: the last
    // evaluation's, the forces the step ended with.
    auto loads = [this](int wall, std::vector<particles::WallLoad>& out) {
        for (const std::vector<MappedLoad>& sphere : scratch_.mapped_loads) {
            for (const MappedLoad& mapped : sphere) {
                if (mapped.wall == static_cast<std::uint32_t>(wall)) {
                    out.push_back(mapped.load);
                }
            }
        }
    };
    parts_.add(particles::wall_map_part("dem.wall_map", particles::WallMapSet(settings_.wall_maps),
                                        std::move(loads)));
}

void DemModel::add_triaxial() {
    if (settings_.triaxial) {
        parts_.add(std::make_shared<TriaxialCell>(*settings_.triaxial, walls_, spheres_));
    }
}

void DemModel::add_phases() {
    if (settings_.phases.empty()) {
        return;
    }
    particles::PhasePart::Hooks hooks{[this] { return kinetic_energy(); },
                                      [this] { return sinks_->discharged(); },
                                      [this](const particles::PhaseSequence& phases) {
                                          for (PlaneWall& wall : walls_) {
                                              if (wall.removal_phase >= 0) {
                                                  wall.remove_at = phases.start(wall.removal_phase);
                                              }
                                          }
                                          sources_->apply_phase_starts(phases);
                                      }};
    phases_ = std::make_shared<particles::PhasePart>(settings_.phases, std::move(hooks), true);
    parts_.add(phases_);
    phases_->apply_starts();
}

void DemModel::exchange(double t, double dt) {
    const double time = t + dt;
    // As in the SPH scene: a phase that ends on a time or on settling does so before the
    // removals, so a gate due at its successor's start opens with this step; one that ends on
    // the mass the sinks took can only after them, and its gates follow at once.
    if (phases_) {
        phases_->advance(time);
    }
    remove_walls(time);
    remove_departed(time);
    if (phases_ && phases_->advance(time)) {
        remove_walls(time);
        remove_departed(time);
    }
    if (parts_.empty()) {
        return;
    }
    const std::vector<particles::Arrival> arrivals = parts_.collect_arrivals(grains_.view(), t, dt);
    if (!arrivals.empty()) {
        add_arrivals(arrivals);
    }
    parts_.end_step(time);
}

void DemModel::remove_walls(double time) {
    for (PlaneWall& wall : walls_) {
        // A wall due at remove_at (a time, or a phase's start, which the step that ended the
        // phase before it reaches) leaves after the step whose end reaches it.
        if (!wall.removed && particles::reaches(time, wall.remove_at)) {
            wall.removed = true;
            wall.force = Vec3::Zero();
            wall.normal_force = 0.0;
            std::ostringstream text;
            text << "wall " << wall.name << " removed at t = " << time << " s";
            events_.push_back(text.str());
        }
    }
}

void DemModel::remove_departed(double time) {
    if (parts_.empty()) {
        return;
    }
    std::vector<char> gone(static_cast<std::size_t>(grains_.size()), 0);
    if (parts_.collect_departures(grains_.view(), time, gone) > 0) {
        remove_grains(gone);
    }
}

void DemModel::add_arrivals(const std::vector<particles::Arrival>& arrivals) {
    for (const particles::Arrival& arrival : arrivals) {
        const auto body = static_cast<std::size_t>(arrival.body);
        const GrainShape shape =
            grain_shape(settings_.bodies[body], arrival.radius, body_density_[body]);
        const Index g =
            add_grain(settings_.bodies[body], arrival.body, shape, arrival.position,
                      arrival.orientation, arrival.velocity, Vec3::Zero(), grains_, spheres_);
        // Placed clear of every sphere and wall: gravity alone acts on it until the next step's
        // evaluation.
        grains_.force[static_cast<std::size_t>(g)] = shape.mass * gravity_;
        start_position_.push_back(arrival.position);
    }
    spheres_.place(grains_);
    neighbours_.update(spheres_.position, {}, true);
}

void DemModel::remove_grains(const std::vector<char>& gone) {
    std::vector<Index> new_index(gone.size(), -1);
    Index kept = 0;
    for (std::size_t i = 0; i < gone.size(); ++i) {
        if (!gone[i]) {
            new_index[i] = kept++;
        }
    }
    grains_.keep(gone);
    spheres_.keep(gone, new_index);
    parts_.after_removal(new_index);
    if (books_.deepest_grain >= 0) {
        books_.deepest_grain = new_index[static_cast<std::size_t>(books_.deepest_grain)];
        books_.deepest_overlap = books_.deepest_grain >= 0 ? books_.deepest_overlap : 0.0;
    }
    // The list's rows are the old indices: a new list, at the positions now.
    neighbours_.update(spheres_.position, {}, true);
}

std::vector<std::string> DemModel::take_events() {
    std::vector<std::string> events = std::move(events_);
    events_.clear();
    for (std::string& line : parts_.take_events()) {
        events.push_back(std::move(line));
    }
    return events;
}

double DemModel::kinetic_energy() const {
    const DemEnergy e = energy();
    return e.translational + e.rotational;
}

void DemModel::append_phases(std::vector<io::PhaseRecord>& records) const {
    if (phases_) {
        phases_->sequence().append_records(records);
    }
}

DemEnergy DemModel::energy() const {
    DemEnergy e;
    const GrainSet& g = grains_;
    for (Index i = 0; i < g.size(); ++i) {
        e.translational += 0.5 * g.mass[i] * g.velocity[i].squaredNorm();
        e.rotational += g.isotropic(i)
                            ? 0.5 * g.inertia[i].x() * g.angular_velocity[i].squaredNorm()
                            : 0.5 * g.angular_velocity[i].dot(momentum_of(
                                        g.orientation[i], g.inertia[i], g.angular_velocity[i]));
        e.gravity -= g.mass[i] * gravity_.dot(g.position[i] - start_position_[g.id[i]]);
    }
    e.elastic = books_.elastic_energy;
    return e;
}

std::optional<std::string> DemModel::diagnose() const {
    const GrainSet& g = grains_;
    for (Index i = 0; i < g.size(); ++i) {
        if (!g.position[i].allFinite() || !g.velocity[i].allFinite() ||
            !g.angular_velocity[i].allFinite()) {
            std::ostringstream text;
            text << "grain " << g.id[i] << " (body " << body_names_[g.body_id[i]]
                 << "): its position or velocity is not finite";
            return text.str();
        }
    }
    // Beyond a radius of overlap one grain passes into another: the contact is too soft for
    // the speeds of the scene (or the step too long for its stiffness).
    if (books_.deepest_overlap > 1.0) {
        const Index i = books_.deepest_grain;
        std::ostringstream text;
        text << "grain " << g.id[i] << " (body " << body_names_[g.body_id[i]]
             << ") overlaps a neighbour or wall by " << books_.deepest_overlap
             << " of its radius: the contact is too soft for the speeds of the scene; expected "
                "a stiffer [dem.contact] or material, or a shorter step";
        return text.str();
    }
    return std::nullopt;
}

} // namespace grainload::dem
