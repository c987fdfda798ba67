#pragma once
// Everything the SPH integrator needs besides particles and materials, with the case defaults.

#include "io/types.hpp"
#include "sph/kernels.hpp"
#include "sph/symmetry.hpp"

#include <vector>

namespace grainload::sph {

/// Monaghan artificial viscosity (Monaghan & Gingold 1983; Monaghan 1992, eq. 4.1):
/// Pi_ij = (-alpha c_ij mu_ij + beta mu_ij^2) / rho_ij for approaching pairs.
struct ArtificialViscosity {
    double alpha = 0.0;
    double beta = 0.0;
    /// m/s; > 0: the sound speed of the linear term alpha c mu instead of the materials' elastic
    /// wave speed, so that scaling the moduli for a longer time step leaves the viscosity alone.
    double sound_speed = 0.0;
};

/// Artificial stress against the tensile instability (Monaghan 2000; Gray, Monaghan & Swift
/// 2001, eqs. 4.7-4.11): R^a = -epsilon sigma^a / rho^2 for tensile principal stresses
/// sigma^a, scaled pairwise by f^n with f = W(r)/W(particle spacing).
struct ArtificialStress {
    double epsilon = 0.0;
    double exponent = 4.0;
};

/// Contact potential between particles of different bodies and walls, thesis eq. (5.3.12)
/// with the repulsive sign: f_i = -sum_j V_i V_j K (W_ij/W(dp))^(n-1) grad_i W_ij.
/// K here is a pressure; the thesis' K (unit depending on the dimension) is K * W(dp).
struct ContactPotential {
    double stiffness = 0.0; ///< K, Pa; 0 disables contact
    double exponent = 1.0;  ///< n
    /// zeta: normal damping as a fraction of each pair's critical damping (contact_force.hpp).
    double damping_ratio = 0.0;
};

/// Coulomb coefficients of one body-wall pair (thesis section 5.4): mu_kinetic <= mu_static.
struct FrictionPair {
    int body_id = -1;
    int wall_body_id = -1;
    double mu_static = 0.0;
    double mu_kinetic = 0.0;
};

/// Which configuration the kernel sums of a body's stress run over.
enum class Formulation {
    /// Current positions, neighbours found anew (thesis section 4.5): bodies may flow and
    /// separate, as sand does; tension needs artificial stress.
    updated_lagrangian,
    /// Initial positions and neighbours (sph/total_lagrangian.hpp): solids that keep their
    /// neighbours, free of the tensile instability; contact and viscosity stay current.
    total_lagrangian,
};

/// Everything the SPH integrator needs besides particles and materials. The defaults here are
/// the case file's defaults (read_sph_options falls back to them; docs/user-guide/sph.md).
struct SphOptions {
    int dimension = 3; ///< 2: plane strain (z = 0), 3
    KernelType kernel = KernelType::cubic_spline;
    /// h / dp, from which read_sph_options sets smoothing_length.
    double smoothing_length_ratio = 1.3;
    double smoothing_length = 0.0; ///< h, m
    double particle_spacing =
        0.0; ///< dp, m: the reference distance of artificial stress and contact
    Vec3 gravity = Vec3::Zero();
    ArtificialViscosity viscosity;
    ArtificialStress artificial_stress;
    ContactPotential contact;
    /// Body-wall pairs with friction; pairs not listed are frictionless.
    std::vector<FrictionPair> friction;
    /// Randles & Libersky (1996) / Bonet & Lok (1999) corrected gradient in the velocity
    /// gradient (thesis section 4.4.1): exact for linear velocity fields also at free surfaces.
    bool kernel_gradient_correction = true;
    Formulation formulation = Formulation::updated_lagrangian;
    double cfl_safety = 0.3; ///< dt = safety * h / (c + |v|)
    /// The non-local fluidity's field is solved at the first step of each interval of this many
    /// seconds of the run's clock, its excess held by the particles in between (0: every step).
    /// The clock, not a step count, decides, so that a restart solves at the same steps.
    double fluidity_interval = 1e-4;
    double verlet_skin_factor = 0.1; ///< Verlet skin as a fraction of h (0: rebuild each step)
    /// Mirror planes ([[sph.symmetry]]), at most one per axis; empty: none.
    std::vector<SymmetryPlane> symmetry;
    /// Periodic directions ([[sph.periodic]]), at most one per axis and none on an axis with a
    /// symmetry plane; empty: none.
    std::vector<PeriodicAxis> periodic;
};

} // namespace grainload::sph
