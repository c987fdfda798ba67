#include "sph/sph_solver.hpp"

#include "particles/ordered_sum.hpp"
#include "sph/contact_force.hpp"
#include "sph/particle_removal.hpp"
#include "sph/stress_update.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace grainload::sph {

SphSolver::SphSolver(ParticleSet particles, MaterialList materials, SphOptions options,
                     std::vector<Wall> walls)
    : particles_(std::move(particles)), materials_(std::move(materials)), options_(options),
      kernel_(options.kernel, options.smoothing_length, options.dimension),
      neighbours_(kernel_.support_radius(), options.verlet_skin_factor * options.smoothing_length,
                  options.dimension),
      walls_(std::move(walls)) {
    if (!(options_.particle_spacing > 0.0)) {
        throw std::invalid_argument("SphSolver: particle spacing must be positive");
    }
    // The scene builders append particles one by one: a field's capacity can be up to twice its
    // size (1.09 KB per particle instead of 0.83 at 1e6 particles, bench/sph_throughput).
    particles_.for_each_field([](const auto&, auto& values) { values.shrink_to_fit(); });
    particles_.state.shrink_to_fit();
    const Index n = particles_.size();
    is_wall_.resize(static_cast<std::size_t>(n));
    force_inputs_.sound_speed.resize(static_cast<std::size_t>(n));
    wave_speed_.resize(static_cast<std::size_t>(n));
    any_clamped_ = std::any_of(particles_.clamped.begin(), particles_.clamped.end(),
                               [](char c) { return c != 0; });
    for (Index i = 0; i < n; ++i) {
        is_wall_[i] = particles_.is_wall(i) ? 1 : 0;
        const int m = particles_.material_id[i];
        if (!is_wall_[i] && (m < 0 || m >= static_cast<int>(materials_.size()))) {
            throw std::invalid_argument("SphSolver: particle has no material");
        }
        if (!is_wall_[i]) {
            const auto& elastic = materials_[static_cast<std::size_t>(m)]->elastic();
            wave_speed_[i] = elastic.p_wave_speed();
            force_inputs_.sound_speed[i] = elastic.unscaled_p_wave_speed();
        }
    }
    // integrate_density's floor (it says why): half the material's density.
    constexpr double kLoosestDensityFraction = 0.5;
    density_floor_.reserve(materials_.size());
    for (const auto& material : materials_) {
        density_floor_.push_back(kLoosestDensityFraction * material->density());
    }
    if (options_.formulation == Formulation::total_lagrangian) {
        if (has_images()) {
            throw std::invalid_argument("SphSolver: symmetry planes and periodic axes need the "
                                        "updated-Lagrangian formulation (its neighbours are "
                                        "found anew)");
        }
        total_lagrangian_.emplace(particles_, kernel_);
    }
    if (FluidityUpdate::needed(materials_)) {
        if (total_lagrangian_) { // its reference pairs do not follow a flow
            throw std::invalid_argument("SphSolver: the non-local fluidity needs the "
                                        "updated-Lagrangian formulation");
        }
        fluidity_.emplace();
    }
    frame_ = image_frame(options_.symmetry, options_.periodic);
    wall_filter_ = wall_body_filter(walls_);
    hold_clamped();
    rebuild_neighbours(particles_.position);
}

double SphSolver::stable_time_step() const {
    double fastest = 0.0;
    const Index n = particles_.size();
#pragma omp parallel for reduction(max : fastest) schedule(static)
    for (Index i = 0; i < n; ++i) {
        fastest = std::max(fastest, wave_speed_[i] + particles_.velocity[i].norm());
    }
    if (fastest == 0.0) {
        return std::numeric_limits<double>::infinity();
    }
    return options_.cfl_safety * options_.smoothing_length / fastest;
}

void SphSolver::check_time_step(double dt) const {
    const double limit = stable_time_step();
    if (dt > limit) {
        std::ostringstream message;
        message << "time step " << dt << " s exceeds the CFL limit " << limit << " s (safety "
                << options_.cfl_safety << " * h / (c + |v|)); use dt <= " << limit << " s";
        throw std::invalid_argument(message.str());
    }
}

void SphSolver::restart(std::span<const Vec3> neighbour_reference, bool forces_valid) {
    rebuild_neighbours(neighbour_reference.empty() ? std::span<const Vec3>(particles_.position)
                                                   : neighbour_reference);
    forces_valid_ = forces_valid;
    // The walls' loads are sums of the wall particles' restored accelerations: summed again
    // here, in the order of compute_forces, a restart that takes no step (a run restarted from
    // its final checkpoint) reports the loads the run ended with, not zero.
    if (forces_valid) {
        for (Wall& wall : walls_) {
            accumulate_wall_load(particles_, wall);
        }
    }
}

std::span<const Vec3> SphSolver::neighbour_reference() const {
    const auto reference = neighbours_.reference();
    return reference.first(std::min(reference.size(), static_cast<std::size_t>(particles_.size())));
}

void SphSolver::remove_particles(std::span<const char> gone) {
    if (total_lagrangian_) {
        throw std::logic_error("SphSolver::remove_particles: the total-Lagrangian reference "
                               "pairs cannot lose particles");
    }
    if (energy_.is_open()) {
        double held = 0.0;
        for (Index i = 0; i < particles_.size(); ++i) {
            if (gone[i] && !is_wall_[i]) {
                held += particles_.mass[i] * (0.5 * particles_.velocity[i].squaredNorm() +
                                              particles_.internal_energy[i]);
            }
        }
        energy_.add_removed(held, contact_energy_of(gone));
    }
    sph::remove_particles(particles_, gone, walls_);
    particles::compact(is_wall_, gone);
    particles::compact(wave_speed_, gone);
    particles::compact(force_inputs_.sound_speed, gone);
    rebuild_neighbours(particles_.position);
}

void SphSolver::add_particles(std::span<const NewParticle> arrivals, bool book_energy) {
    if (total_lagrangian_) {
        throw std::logic_error("SphSolver::add_particles: the total-Lagrangian reference pairs "
                               "cannot gain particles");
    }
    const auto first = static_cast<std::size_t>(particles_.size());
    double held = 0.0;
    for (const NewParticle& a : arrivals) {
        const materials::Material& law = *materials_.at(static_cast<std::size_t>(a.material));
        particles_.add(a.position, a.velocity, a.mass, law.density(), a.body, a.material,
                       law.state_size());
        const auto i = particles_.size() - 1;
        particles_.acceleration[i] = options_.gravity;
        law.initialise_state(std::span(particles_.state)
                                 .subspan(static_cast<std::size_t>(particles_.state_offset[i]),
                                          static_cast<std::size_t>(law.state_size())));
        is_wall_.push_back(0);
        wave_speed_.push_back(law.elastic().p_wave_speed());
        force_inputs_.sound_speed.push_back(law.elastic().unscaled_p_wave_speed());
        held += a.mass * 0.5 * a.velocity.squaredNorm();
    }
    rebuild_neighbours(particles_.position);
    if (book_energy && energy_.is_open()) {
        std::vector<char> flagged(static_cast<std::size_t>(particles_.size()), 0);
        std::fill(flagged.begin() + static_cast<std::ptrdiff_t>(first), flagged.end(), char{1});
        energy_.add_created(held, contact_energy_of(flagged));
    }
}

void SphSolver::refresh_neighbours() {
    if (!has_images()) {
        if (neighbours_.update(particles_.position, is_wall_)) {
            filter_pairs(particles_.body_id, particles_.size());
        }
        return;
    }
    // The images move with their sources, so the list's displacement test covers them; when it
    // is stale the images are selected anew from the particles' current positions.
    if (neighbours_.stale(particles_.position)) {
        detach_images();
        wrap_periodic(particles_.position, is_wall_, options_.periodic);
        rebuild_neighbours(particles_.position);
        attach_images();
    }
}

void SphSolver::rebuild_neighbours(std::span<const Vec3> positions) {
    if (!has_images()) {
        neighbours_.update(positions, is_wall_, true);
        filter_pairs(particles_.body_id, particles_.size());
        return;
    }
    // An image within the support of a particle is within the support of the plane (or of the
    // periodic end), and during the list's life a particle moves less than half the skin:
    // images of the particles within support + skin of a plane or an end cover every pair the
    // list can need.
    const auto n = static_cast<Index>(positions.size());
    std::vector<MirrorMask> allowed(static_cast<std::size_t>(n), MirrorMask{7});
    for (const Wall& wall : walls_) {
        std::fill_n(allowed.begin() + wall.first, wall.count, wall.mirror_planes);
    }
    images_ = select_images(options_.symmetry, options_.periodic, positions, is_wall_, allowed,
                            neighbours_.search_radius());
    wall_image_count_ = 0;
    while (wall_image_count_ < static_cast<Index>(images_.size()) &&
           is_wall_[images_[wall_image_count_].source]) {
        ++wall_image_count_;
    }
    std::vector<Vec3> all(positions.begin(), positions.end());
    all.reserve(all.size() + images_.size());
    for (const GhostImage& image : images_) {
        all.push_back(image_position(positions[image.source], image, frame_));
    }
    frozen_.assign(is_wall_.begin(), is_wall_.end());
    frozen_.resize(all.size(), char{1});
    // Images of grains need no row (nothing reads their rates); images of wall particles carry
    // the loads of the real grains on them (fold_wall_image_loads).
    neighbours_.update(all, frozen_, true, n + wall_image_count_);
    // An image belongs to its source's body or wall.
    std::vector<int> group(particles_.body_id.begin(), particles_.body_id.begin() + n);
    for (const GhostImage& image : images_) {
        group.push_back(particles_.body_id[image.source]);
    }
    filter_pairs(group, n);
}

void SphSolver::filter_pairs(std::span<const int> group, Index real) {
    if (!wall_filter_.empty()) {
        neighbours_.drop_pairs(group, wall_filter_.apart, wall_filter_.groups);
    }
    // The keys of sph/pair_parts.hpp over the list's positions: an image of a grain takes its
    // source's body, an image of a wall particle a key of its own.
    const auto count = static_cast<Index>(group.size());
    std::vector<int> key(group.size());
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < count; ++i) {
        const Index source = i < real ? i : images_[i - real].source;
        key[i] = continuum_key(is_wall_[source] != 0, group[i], i);
    }
    neighbours_.halve_pairs(key);
}

void SphSolver::attach_images(bool kinematics) {
    if (!has_images()) {
        return;
    }
    if (!images_attached_) {
        real_count_ = particles_.size();
        images_attached_ = true;
    }
    write_images(particles_, real_count_, images_, frame_);
    wall_images_.first = real_count_;
    wall_images_.normals.resize(static_cast<std::size_t>(wall_image_count_));
    wall_images_.angular_velocities.resize(static_cast<std::size_t>(wall_image_count_));
    for (Index k = 0; k < wall_image_count_; ++k) {
        const GhostImage& image = images_[k];
        const Wall& wall = walls_[static_cast<std::size_t>(particles_.wall_id[image.source])];
        const auto local = static_cast<std::size_t>(image.source - wall.first);
        wall_images_.normals[k] =
            wall.normals.empty() ? Vec3::Zero() : mirror_vector(wall.normals[local], image.mask);
        wall_images_.angular_velocities[k] =
            wall.angular_velocities.empty()
                ? Vec3::Zero()
                : mirror_axial(wall.angular_velocities[local], image.mask);
    }
    auto& speed = force_inputs_.sound_speed;
    speed.resize(static_cast<std::size_t>(real_count_));
    for (const GhostImage& image : images_) {
        speed.push_back(speed[static_cast<std::size_t>(image.source)]);
    }
    auto& correction = force_inputs_.gradient_correction;
    if (kinematics && !correction.empty()) {
        const auto count = static_cast<Index>(images_.size());
#pragma omp parallel for schedule(static)
        for (Index k = 0; k < count; ++k) {
            correction[real_count_ + k] =
                mirror_matrix(correction[images_[k].source], images_[k].mask);
        }
    }
}

void SphSolver::detach_images() {
    if (!images_attached_) {
        return;
    }
    drop_images(particles_, real_count_);
    force_inputs_.sound_speed.resize(static_cast<std::size_t>(real_count_));
    wall_images_.first = std::numeric_limits<Index>::max();
    images_attached_ = false;
}

void SphSolver::fold_wall_image_loads() {
    // Serial: the images of one source across several planes add to the same particle.
    ParticleSet& p = particles_;
    for (Index k = 0; k < wall_image_count_; ++k) {
        const GhostImage& image = images_[k];
        p.acceleration[image.source] += mirror_vector(p.acceleration[real_count_ + k], image.mask);
    }
}

// Sums in fixed blocks (particles/ordered_sum.hpp): the books repeat bit for bit whatever the
// threads.
void SphSolver::book_heating_powers() {
    const ParticleSet& p = particles_;
    const Index n = images_attached_ ? real_count_ : p.size();
    const auto [total, contact] =
        particles::ordered_sums<2>(n, [&](Index i, std::array<double, 2>& sums) {
            if (!is_wall_[i]) {
                sums[0] += p.mass[i] * heating_rate_[i];
                sums[1] += p.mass[i] * contact_heating_rate_[i];
            }
        });
    viscous_power_ = total - contact;
    contact_damping_power_ = contact;
}

void SphSolver::book_dissipation(double dt, Index n) {
    const ParticleSet& p = particles_;
    const double plastic = particles::ordered_sum(n, [&](Index i) {
        return is_wall_[i] ? 0.0 : p.mass[i] * plastic_work_[static_cast<std::size_t>(i)];
    });
    energy_.add_dissipation(plastic, dt * viscous_power_, dt * contact_damping_power_);
}

void SphSolver::compute_forces(double dt) {
    if (!total_lagrangian_) { // its stress terms come from its own pass, not from sigma/rho^2
        prepare_force_inputs(particles_, options_.artificial_stress, force_inputs_);
    }
    compute_accelerations(particles_, neighbours_, kernel_, options_, force_inputs_, heating_rate_,
                          &pair_scratch_, PairArithmetic::lanes_where_available,
                          &contact_heating_rate_);
    book_heating_powers();
    if (total_lagrangian_) {
        total_lagrangian_->add_stress_forces(particles_);
    }
    wall_contact_.apply(particles_, neighbours_, kernel_, options_, walls_, dt, heating_rate_,
                        wall_images_);
    if (images_attached_) {
        fold_wall_image_loads();
    }
    // One wall per thread: each wall's sums keep their serial order.
    const auto wall_count = static_cast<std::ptrdiff_t>(walls_.size());
#pragma omp parallel for schedule(dynamic, 1)
    for (std::ptrdiff_t w = 0; w < wall_count; ++w) {
        accumulate_wall_load(particles_, walls_[static_cast<std::size_t>(w)]);
    }
    hold_clamped();
    forces_valid_ = true;
}

void SphSolver::hold_clamped() {
    // A clamped particle is a Dirichlet condition v = 0 (the built-in root of the cantilever
    // plate of Gray, Monaghan & Swift 2001): zero acceleration after every force evaluation
    // keeps both kicks and the drift from moving it, while its stress and density still evolve
    // from the velocity gradient of its neighbours and it still pushes on them.
    if (!any_clamped_) {
        return;
    }
    ParticleSet& p = particles_;
    const Index n = p.size();
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        if (p.clamped[i]) {
            p.velocity[i].setZero();
            p.acceleration[i].setZero();
        }
    }
}

void SphSolver::compute_kinematics() {
    if (total_lagrangian_) {
        total_lagrangian_->compute_kinematics(particles_, velocity_gradient_);
        return;
    }
    // The force pass, which always follows at the same positions and list, reuses the
    // kernel gradients of this pass where its scalar rows run in plane strain. Not in 3D, where
    // the 8 bytes per list entry (about 38 entries, each pair of a body once) would take the
    // solver past 1 KB per particle, nor where the force pass's vector lanes evaluate them four
    // at a time (rates.hpp force_pass_uses_lanes).
    const bool store_factors = options_.dimension == 2 && !force_pass_uses_lanes(kernel_, options_);
    if (!store_factors) {
        force_inputs_.entry_factor.clear();
        force_inputs_.entry_factor.shrink_to_fit();
    }
    compute_velocity_gradient(particles_, neighbours_, kernel_, options_.kernel_gradient_correction,
                              velocity_gradient_, force_inputs_.gradient_correction,
                              store_factors ? &force_inputs_.entry_factor : nullptr, &pair_scratch_,
                              PairArithmetic::lanes_where_available, &force_inputs_.pair_records);
}

// The continuity equation (thesis eq. 4.5.3.13) needs a neighbourhood: a particle that has flown
// off the body (a grain in the spray of a discharge, a spalled grain) keeps one or two
// neighbours that move away from it, its SPH divergence stays positive and its density decays
// towards zero, so its volume m / rho, which the contact potential multiplies (thesis eq.
// 5.3.12), grows without bound and throws it and its wall through each other (the wagon's
// discharge blew up at 6.3 and 7.7 s with densities of 0.007 and 34 kg/m^3 at the door's ends).
// A granular material cannot loosen below its loosest packing, about 0.55 of the solid volume
// against 0.64 for the densest random packing of spheres; half the material's density is below
// any packing, so the floor never touches a continuum and holds a free grain's volume at twice
// its own.
void SphSolver::integrate_density(double dt, Index n) {
    ParticleSet& p = particles_;
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        if (!is_wall_[i]) {
            p.density[i] = std::max(p.density[i] + dt * p.density_rate[i],
                                    density_floor_[static_cast<std::size_t>(p.material_id[i])]);
        }
    }
}

void SphSolver::step(double dt) {
    if (!forces_valid_) {
        attach_images();
        refresh_neighbours();
        compute_kinematics();
        attach_images(true);
        compute_forces(last_dt_ > 0.0 ? last_dt_ : dt);
        detach_images();
    }
    if (!energy_.is_open()) {
        energy_.open(held_energy(), elastic_strain_energy(), contact_energy());
    }
    ParticleSet& p = particles_;
    const Index n = p.size();
    // The first half kick, then the drift by dt v(n+1/2), so gravity's work over the step is
    // exactly sum m g . dt v(n+1/2); one loop, its sum in fixed blocks (the same bits on any
    // number of threads).
    const Vec3 gravity = options_.gravity;
    const double gravity_power = particles::ordered_sum(
        n,
        [&](Index i) {
            if (is_wall_[i]) {
                return 0.0;
            }
            p.velocity[i] += 0.5 * dt * p.acceleration[i];
            p.position[i] += dt * p.velocity[i];
            return p.mass[i] * gravity.dot(p.velocity[i]);
        },
        0);
    energy_.add_gravity_work(dt * gravity_power);
    for (Wall& wall : walls_) {
        if (wall.moves()) {
            wall.driver->move(p, wall, time_, dt);
        }
    }
    // Images (symmetry planes, periodic axes) join the particle set for the passes of this step:
    // they take part in every neighbour sum but are never integrated, and are copied from their
    // sources after each update of the fields the passes read.
    attach_images();
    refresh_neighbours();
    compute_kinematics();
    attach_images(true);
    if (!total_lagrangian_) { // the total-Lagrangian density is rho0 / det F, already set
        integrate_density(dt, n);
    }
    // From the stresses of the step's start, at the first step of each fluidity interval.
    if (fluidity_ && FluidityUpdate::due(time_, dt, options_.fluidity_interval)) {
        fluidity_->apply(p, n, images_, materials_, neighbours_, kernel_);
    }
    plastic_work_.resize(static_cast<std::size_t>(n)); // every material particle's entry set
    update_stresses(p, materials_, dt, n, plastic_work_);
    attach_images(true);
    compute_forces(dt);
    energy_.add_wall_work(wall_work(dt));
    detach_images();
    // The second half kick and the step's heating, in one loop.
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        if (!is_wall_[i]) {
            p.velocity[i] += 0.5 * dt * p.acceleration[i];
        }
        p.internal_energy[i] += dt * heating_rate_[i];
    }
    book_dissipation(dt, n);
    time_ += dt;
    last_dt_ = dt;
    ++steps_;
}

std::size_t SphSolver::bytes() const {
    const ParticleSet& p = particles_;
    auto held = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
    std::size_t particle_bytes = held(p.state);
    p.for_each_field([&](const auto&, const auto& values) { particle_bytes += held(values); });
    const std::size_t work =
        held(is_wall_) + held(force_inputs_.stress_over_rho2) + held(force_inputs_.pair_records) +
        held(force_inputs_.artificial_stress) + held(force_inputs_.sound_speed) +
        held(wave_speed_) + held(force_inputs_.gradient_correction) +
        held(force_inputs_.entry_factor) + held(velocity_gradient_) + held(heating_rate_) +
        held(contact_heating_rate_) + held(plastic_work_);
    return particle_bytes + work + pair_scratch_.bytes() + neighbours_.bytes() +
           (total_lagrangian_ ? total_lagrangian_->bytes() : 0) +
           (fluidity_ ? fluidity_->bytes() : 0);
}

} // namespace grainload::sph
