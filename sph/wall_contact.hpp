#pragma once
// What a body particle feels of a wall beyond the repulsion: a normal dashpot and friction.

#include "particles/neighbour_list.hpp"
#include "sph/kernels.hpp"
#include "sph/particle_set.hpp"
#include "sph/sph_options.hpp"
#include "sph/wall.hpp"

#include <limits>
#include <vector>

namespace grainload::sph {

/// What a body particle feels of a wall beyond the contact potential's repulsion: a normal
/// dashpot and Coulomb friction (thesis section 5.4, made a stick/slip law on the sliding
/// velocity, so that a block on an incline starts to slide at tan theta = mu_s).
///
/// For a body particle i touching wall w (wall particles j within the support):
///   contact normal n: the kernel average of the wall's own surface normals n_j where the wall
///   knows them (planes, boxes), sum_j V_j W_ij n_j normalised, exact on a plane; otherwise
///   the wall's colour function (thesis eqs. 5.4.1-5.4.3), n = -grad c / |grad c|,
///   grad c = sum_j V_j grad_i W_ij. On a lattice of wall particles the colour gradient tilts
///   by a few degrees as a particle slides past them, and a normal dashpot on that tilted n
///   would resist sliding: a spurious friction;
///   repulsion load N_c = F_c . n, F_c the contact-potential force of w on i (eq. 5.3.12);
///   relative velocity u = v_i - v_w(x_i), v_w(x_i) = sum_j V_j W_ij (v_j + omega_j x (x_i -
///   x_j)) / sum_j V_j W_ij from the wall particles' own velocities and angular velocities
///   (Wall::velocity_at), whatever drives them: exact for a rigid motion, the shell's motion
///   at the contact point for a coupled shell;
///   normal dashpot D = -2 zeta sqrt(k_n m_i) (u . n) >= -N_c, k_n = sum_j k_ij (e_ij . n)^2
///   (k_ij the pair stiffness |dF/dr|), so the load N = N_c + D is never a pull;
///   sliding velocity u_t = u - (u . n) n and the tangential force that makes it vanish at the
///   next half step of the leapfrog, F_stick = -m_i (u_t / dt + a_t), a_t the tangential
///   part of all other accelerations;
///   stick: F = F_stick when |F_stick| <= mu_s N;  slip: F = mu_k N F_stick / |F_stick|,
///   opposite the slip for a sliding particle (u_t / dt dominates) and opposite the driving
///   force at the onset of sliding (u_t = 0).
/// The reaction -(D n + F) goes to the wall particles j in proportion to V_j W_ij, so wall
/// forces and moments include damping and friction. The heat of both goes to particle i.
/// The wall particles' mirror images of the symmetry planes (sph/symmetry.hpp), particles
/// first, first + 1, ... of the particle set: what Wall::normals and Wall::angular_velocities
/// hold for real wall particles (zero normals where the wall has none, zero angular velocities
/// where it does not turn).
struct WallImages {
    Index first = std::numeric_limits<Index>::max();
    std::vector<Vec3> normals;
    std::vector<Vec3> angular_velocities;
};

class WallContact {
  public:
    /// Adds damping and friction to p.acceleration of body particles, their heat to
    /// heating_rate, and the reaction to wall particles. Call after the contact-potential
    /// force pass, with the step about to be taken.
    /// Reactions on images of wall particles stay on the images (the solver folds them back).
    void apply(ParticleSet& p, const particles::NeighbourList& neighbours,
               const SmoothingKernel& kernel, const SphOptions& options,
               const std::vector<Wall>& walls, double dt, std::vector<double>& heating_rate,
               const WallImages& images = {});

    /// Work done against wall friction so far (J, or J/m in plane strain), positive.
    double friction_work() const { return friction_work_; }
    void set_friction_work(double value) { friction_work_ = value; }
    /// Heat of the dashpot along the walls' normals so far (J, or J/m), positive.
    double damping_work() const { return damping_work_; }
    void set_damping_work(double value) { damping_work_ = value; }
    /// The reactions go to wall particles below the surface, whose velocities differ from the
    /// wall's velocity at the contact point x_i by omega x (x_i - x_j) on a turning wall. The
    /// power the wall puts into the body through the dashpot and friction is
    /// F . v_w(x_i), which is what their heat is booked against; this is that power minus the
    /// power of the distributed reactions at their own velocities (W, last call).
    double reaction_power_correction() const { return reaction_power_correction_; }
    /// Body-wall particle contacts that stuck and slipped in the last call.
    Index sticking() const { return sticking_; }
    Index slipping() const { return slipping_; }

  private:
    struct Record {
        Index particle;
        int wall_index;
        Vec3 force;
        double weight_sum;
        Vec3 wall_velocity;   ///< the wall's velocity at the body particle
        double friction_work; ///< -F_friction . slip dt of this touch [J]
        double damping_work;  ///< -F_dashpot . v_n dt of this touch [J]
    };
    void distribute_reactions(ParticleSet& p, const particles::NeighbourList& neighbours,
                              const SmoothingKernel& kernel);
    /// near_wall_ for the list as it is now, recomputed only when the list has changed.
    void find_particles_near_walls(const ParticleSet& p,
                                   const particles::NeighbourList& neighbours);

    std::vector<std::vector<Record>> per_thread_;
    std::vector<Record> merged_; ///< the threads' records in the particles' order
    /// Whether a body particle's row holds a wall particle: the others cannot touch a wall, and
    /// their neighbour walk is skipped. Kept while the list (its address, generation and
    /// size) stays the same.
    std::vector<char> near_wall_;
    const particles::NeighbourList* near_wall_list_ = nullptr;
    Index near_wall_generation_ = -1;
    double friction_work_ = 0.0;
    double damping_work_ = 0.0;
    double reaction_power_correction_ = 0.0;
    Index sticking_ = 0;
    Index slipping_ = 0;
};

} // namespace grainload::sph
