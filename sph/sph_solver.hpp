#pragma once
// Explicit SPH for solids in plane strain and 3D, integrated by kick-drift-kick leapfrog.

#include "materials/material.hpp"
#include "particles/neighbour_list.hpp"
#include "sph/energy_ledger.hpp"
#include "sph/fluidity_update.hpp"
#include "sph/kernels.hpp"
#include "sph/particle_set.hpp"
#include "sph/rates.hpp"
#include "sph/sph_options.hpp"
#include "sph/total_lagrangian.hpp"
#include "sph/wall.hpp"
#include "sph/wall_bodies.hpp"
#include "sph/wall_contact.hpp"

#include <optional>
#include <vector>

namespace grainload::sph {

/// Explicit SPH for solids: one code path for plane strain (dimension 2) and 3D.
///
/// Time integration is the kick-drift-kick leapfrog (velocity Verlet), second order and
/// symplectic for conservative forces:
///   v(n+1/2) = v(n) + dt/2 a(n);  x(n+1) = x(n) + dt v(n+1/2);
///   rates from v(n+1/2) at x(n+1) -> rho, sigma at n+1;  a(n+1);  v(n+1) = v(n+1/2) + dt/2 a(n+1).
/// Clamped particles have v = a = 0 from construction on, so neither kick nor drift moves them.
class SphSolver {
  public:
    /// Non-owning: the materials (a case's MaterialLibrary) outlive the solver.
    using MaterialList = std::vector<const materials::Material*>;

    /// materials[k] is the material of particles with material_id k.
    SphSolver(ParticleSet particles, MaterialList materials, SphOptions options,
              std::vector<Wall> walls = {});

    /// CFL limit (Monaghan 1992): safety * h / max_i (c_i + |v_i|), c = sqrt((K + 4G/3)/rho).
    double stable_time_step() const;
    /// Throws std::invalid_argument, giving the limit, when dt exceeds stable_time_step().
    void check_time_step(double dt) const;
    /// Advance by dt (not checked against the CFL limit: call check_time_step for user input).
    void step(double dt);

    /// After particle fields were replaced (a checkpoint): rebuild the neighbour list from the
    /// positions it was last built from (`neighbour_reference`; empty: the current positions)
    /// and, unless `forces_valid`, the forces. A checkpoint written after a step holds that
    /// step's accelerations, which were computed from the mid-step velocity; recomputing them
    /// from the end-of-step velocity would change the continuation at round-off level. With
    /// valid forces the walls' loads are summed from the restored accelerations.
    void restart(std::span<const Vec3> neighbour_reference, bool forces_valid);
    bool forces_valid() const { return forces_valid_; }
    /// Take the particles with gone[i] != 0 out of the scene (sph/particle_removal.hpp), between
    /// steps: the energy ledger books what they held and the contact potential they shared
    /// (EnergyLedger::add_removed), the per-particle work arrays and wall ranges follow, and
    /// the neighbour list is rebuilt at the current positions. The accelerations stay valid
    /// (the next kick uses the forces of the step just ended, removed neighbours included).
    /// Not with Formulation::total_lagrangian, whose reference pairs are fixed.
    void remove_particles(std::span<const char> gone);
    /// A particle entering the scene (a source): where, how fast, its mass, body and material.
    struct NewParticle {
        Vec3 position;
        Vec3 velocity;
        double mass = 0.0;
        int body = 0;
        int material = 0;
    };
    /// Append `arrivals` after every particle there (so the walls' ranges stay as they are),
    /// between steps: each gets its material's density and initial state (initialise_state),
    /// zero stress and the acceleration of gravity (it has no neighbour yet: the next kick
    /// starts it in free flight), the per-particle work arrays grow, and the neighbour list
    /// is rebuilt at the current positions. With `book_energy` the ledger books what they
    /// bring and the contact potential they start with (EnergyLedger::add_created); a
    /// checkpoint's replay, whose ledger is read afterwards, books nothing.
    void add_particles(std::span<const NewParticle> arrivals, bool book_energy);
    double time() const { return time_; }
    /// The driver's clock, which wall motion histories follow (also after a restart).
    void set_time(double time) { time_ = time; }
    Index step_count() const { return steps_; }
    /// Change gravity from the next step on (a tilted frame, a ramped load).
    void set_gravity(const Vec3& gravity) {
        options_.gravity = gravity;
        forces_valid_ = false;
    }
    /// The dt of the last step: wall friction's stick force depends on it, so a restart that
    /// sets it back reproduces the uninterrupted run.
    double last_time_step() const { return last_dt_; }
    void set_last_time_step(double dt) { last_dt_ = dt; }
    WallContact& wall_contact() { return wall_contact_; }
    const WallContact& wall_contact() const { return wall_contact_; }
    ParticleSet& particles() { return particles_; }
    const ParticleSet& particles() const { return particles_; }
    const SphOptions& options() const { return options_; }
    const SmoothingKernel& kernel() const { return kernel_; }
    /// With symmetry planes or periodic axes the list's rows beyond particles().size() are empty
    /// and its entries there name ghost images (ghost_images()), which exist in the particle set
    /// only during a step.
    const particles::NeighbourList& neighbours() const { return neighbours_; }
    /// The positions of the particles (images left out) at the last list build, which a
    /// checkpoint stores: restart() selects the same images from them and rebuilds the same list.
    std::span<const Vec3> neighbour_reference() const;
    /// The ghost images of the current neighbour list: entry k is particle size() + k of the
    /// list (sph/symmetry.hpp); empty without symmetry planes and periodic axes.
    const std::vector<GhostImage>& ghost_images() const { return images_; }
    /// The per-particle inputs of the force pass (sound speeds of the viscosity, ...).
    const ForceInputs& force_inputs() const { return force_inputs_; }
    std::vector<Wall>& walls() { return walls_; }
    const std::vector<Wall>& walls() const { return walls_; }
    const MaterialList& materials() const { return materials_; }
    /// The non-local fluidity's solve, where a material has one (before each stress update).
    const FluidityUpdate* fluidity() const { return fluidity_ ? &*fluidity_ : nullptr; }

    /// Sums over material particles (walls excluded), for conservation checks.
    Vec3 linear_momentum() const;
    Vec3 angular_momentum() const; ///< about the origin
    double kinetic_energy() const;
    double internal_energy() const; ///< sum m e
    /// Sum of V sigma : C^-1 : sigma / 2: the elastic strain energy from the stresses.
    double elastic_strain_energy() const;
    /// Kinetic plus internal energy of the material particles (EnergyLedger's "held").
    double held_energy() const;
    /// Energy stored in the contact potential of all pairs of different bodies and of bodies
    /// and walls (a pass over the neighbour list: for summaries and the ledger's opening).
    double contact_energy() const;
    /// The part of contact_energy() in pairs with at least one flagged particle.
    double contact_energy_of(std::span<const char> flagged) const;
    /// Opened at the first step (or restored from a checkpoint).
    const EnergyLedger& energy_ledger() const { return energy_; }
    EnergyLedger& energy_ledger() { return energy_; }
    /// Heap bytes of particles, neighbour list and work arrays.
    std::size_t bytes() const;

  private:
    /// rho += dt drho/dt for the material particles, floored at half the material density.
    void integrate_density(double dt, Index n);
    /// Rebuild the list if stale (images attached, when there are planes or periodic axes;
    /// particles that left a periodic box wrapped back into it first).
    void refresh_neighbours();
    /// After a rebuild over `group` (each position's body or wall; the first `real` are
    /// particles, the others images_): leave out
    /// the pairs of walls and the bodies they do not act on, and keep each same-body pair in
    /// one row (NeighbourList::halve_pairs).
    void filter_pairs(std::span<const int> group, Index real);
    /// Rebuild the list at `positions` (of the particles without images): with symmetry planes
    /// or periodic axes the images are selected anew, within the list's search radius of a
    /// plane or a periodic end.
    void rebuild_neighbours(std::span<const Vec3> positions);
    /// Append the ghost images to the particle set (and the sound speeds), copied from their
    /// sources; with `kinematics` also the gradient correction. No-op without images.
    void attach_images(bool kinematics = false);
    /// Drop the images again: outside a step the particle set holds no ghosts.
    void detach_images();
    /// Add the loads on the images of wall particles, mirrored, to their sources: the load a
    /// real wall particle gets from the images of grains in the full (or repeated) model.
    void fold_wall_image_loads();
    void compute_kinematics();
    void compute_forces(double dt);
    /// viscous_power_ and contact_damping_power_ of the force pass just taken.
    void book_heating_powers();
    /// The step's dissipation by mechanism into the energy books (EnergyLedger::add_dissipation).
    void book_dissipation(double dt, Index n);
    /// Zero velocity and acceleration of clamped particles (ParticleSet::clamped).
    void hold_clamped();
    /// Work of the walls on the particles over a step of length dt: minus the reactions the
    /// walls' particles carry times their velocity.
    double wall_work(double dt) const;

    ParticleSet particles_;
    MaterialList materials_;
    SphOptions options_;
    SmoothingKernel kernel_;
    particles::NeighbourList neighbours_;
    std::vector<Wall> walls_;
    /// Body-wall pairs left out of the neighbour list after each build (Wall::bodies); empty:
    /// none, and the list is used as built.
    WallBodyFilter wall_filter_;
    WallContact wall_contact_;
    EnergyLedger energy_;
    /// Set with Formulation::total_lagrangian: the reference configuration is the particles
    /// the solver was built with (a restart rebuilds the solver from the case first).
    std::optional<TotalLagrangian> total_lagrangian_;
    std::vector<char> is_wall_;
    /// Whether the scene clamps any particle (particles added later never are): the step then
    /// skips hold_clamped's loop.
    bool any_clamped_ = false;
    PairScratch pair_scratch_; ///< the pair passes' sums of the threads after the first
    ForceInputs force_inputs_;
    /// P-wave speed of each particle's (scaled) material, for the CFL step; 0 for walls.
    std::vector<double> wave_speed_;
    /// Lowest density of each material, by material id (integrate_density says why).
    std::vector<double> density_floor_;
    std::vector<Mat3> velocity_gradient_;
    std::vector<double> heating_rate_;
    /// The dashpot-between-bodies part of heating_rate_ (compute_accelerations).
    std::vector<double> contact_heating_rate_;
    /// The last force pass's heating powers of the material particles before the walls' (W):
    /// the artificial viscosity's and the dashpot between bodies'.
    double viscous_power_ = 0.0;
    double contact_damping_power_ = 0.0;
    /// Each particle's specific plastic work of the step (update_stresses), J/kg.
    std::vector<double> plastic_work_;
    bool has_images() const { return !options_.symmetry.empty() || !options_.periodic.empty(); }
    /// Images of the symmetry planes and periodic axes (options_.symmetry, options_.periodic),
    /// selected at each list build.
    std::vector<GhostImage> images_;
    std::optional<FluidityUpdate> fluidity_;
    Index wall_image_count_ = 0; ///< images_ of wall particles, which come first
    WallImages wall_images_;     ///< their normals and angular velocities while attached
    ImageFrame frame_;           ///< where the images stand (planes, periods)
    /// is_wall_ followed by a 1 per image: images pair neither with walls nor with each other;
    /// images of grains have no list row, images of wall particles one (of real grains).
    std::vector<char> frozen_;
    Index real_count_ = 0; ///< particles without images while they are attached
    bool images_attached_ = false;
    bool forces_valid_ = false;
    double time_ = 0.0;
    double last_dt_ = 0.0;
    Index steps_ = 0;
};

} // namespace grainload::sph
