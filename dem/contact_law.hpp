#pragma once
// The force of one contact: Hooke or Hertz-Mindlin in the normal, a spring and Coulomb's slider
// in the tangent, viscous damping in both.

#include "io/types.hpp"

#include <optional>

namespace grainload::dem {

/// The contact law of a scene ([dem.contact]). Normal force on grain a from grain (or wall) b,
/// with overlap delta > 0, normal n from b to a and relative normal speed v_n = (v_a - v_b).n:
///   linear (Kelvin-Voigt, as Lazarevic, Dvornik & Fresl 2002 model silo grains):
///       f_n = k_n delta - c_n v_n
///   hertz_mindlin (Hertz 1882; Mindlin 1949; as in Balevicius et al. 2004 and Markauskas'
///   hopper study of axisymmetric particles):
///       f_n = 4/3 E* sqrt(R* delta) delta - c_n v_n
/// with c_n = gamma_n m* (Balevicius et al.'s normal damping coefficient in 1/s), or, for the
/// linear law given a restitution e, c_n = 2 sqrt(k_n m*) (-ln e) / sqrt(pi^2 + ln^2 e), which
/// makes the coefficient of restitution of every pair exactly e (the damped oscillator's half
/// period, Schwager & Poeschel 2007). For Hertz given e, c_n = alpha sqrt(m* k(delta)) with
/// k = 2 E* sqrt(R* delta) the contact's tangent stiffness (the form of Tsuji, Tanaka & Ishida
/// 1992, whose restitution is the same at every impact speed): alpha is the root of e(alpha)
/// = e, e(alpha) solved once from the impact's dimensionless equation
/// x'' + alpha sqrt(15/8) x^(1/4) x' + (5/4) x^(3/2) = 0 (hertz_restitution_damping), so that
/// every pair rebounds with exactly e, not with the linear law's mapping's approximation
/// (Antypov & Elliott 2011). The dashpot is not cut at zero force: the Kelvin-Voigt element as
/// the seeds state it, for which these restitutions hold.
/// Tangent: a spring xi integrated from the tangential relative speed, f_t = -k_t xi -
/// gamma_t m* v_t, capped at mu max(f_n, 0) (Coulomb); at the cap the spring is reset to the
/// slip force less the dashpot's part, -(f_t + gamma_t m* v_t) / k_t (Cundall & Strack 1979;
/// Luding 2008). k_t = ratio k_n (linear; 2/7 makes the normal and
/// tangential periods of a sphere equal, Silbert et al. 2001) or 8 G* sqrt(R* delta) (Mindlin).
/// Rolling resistance (optional): the elastic-plastic spring-dashpot of Ai, Chen, Rotter & Ooi
/// 2011 (their model C): a torque spring M_k integrated from the relative rolling rotation
/// (omega_a - omega_b without its part along n), stiffness k_r = 2.25 k_n mu_r^2 R*^2 (k_n the
/// normal law's tangent stiffness), capped at mu_r R* max(f_n, 0) (full mobilisation: a grain
/// rolls against a constant torque); below the cap a dashpot -C_r omega_r with
/// C_r = eta_r 2 sqrt(I_r k_r) quiets a grain rocking at rest.
/// Cohesion (optional, the linear law only): Lazarevic, Dvornik & Fresl 2002 (eqs. 4 and 10)
/// let the linear spring pull a pair that separates within the reach -N_c / k_n <= delta <= 0,
/// f_n = k_n delta, capped so at N_c = p_N g min(m_a, m_b), a share p_N of the lighter grain's
/// weight (0.1 in their silo): grains cling but none hangs from another, as real dry grains
/// carry load by pressing. No dashpot, no tangential or rolling force in that reach; a pair
/// that approaches there feels nothing, so each parting costs N_c^2 / (2 k_n).
struct ContactLaw {
    enum class Model { linear, hertz_mindlin };
    Model model = Model::linear;
    double normal_stiffness = 0.0;           ///< k_n of the linear law [N/m]
    double tangential_stiffness_ratio = 0.0; ///< k_t / k_n of the linear law
    double gamma_n = 0.0;                    ///< [1/s]
    double gamma_t = 0.0;                    ///< [1/s]
    std::optional<double> restitution;       ///< e instead of gamma_n
    double hertz_alpha = 0.0;                ///< Hertz with a restitution: alpha of e
    double friction = 0.0;                   ///< mu between grains
    double wall_friction = 0.0;              ///< mu between a grain and a wall
    double rolling_friction = 0.0;           ///< mu_r between grains
    double wall_rolling_friction = 0.0;      ///< mu_r between a grain and a wall
    double rolling_damping = 0.0;            ///< eta_r, the rolling dashpot's damping ratio
    double cohesion_pull = 0.0;              ///< p_N g between grains: N_c per kg [N/kg]
    double wall_cohesion_pull = 0.0;         ///< p_N g between a grain and a wall [N/kg]
};

/// The pair's effective properties: m*, R*, E*, G* (a wall: infinite mass and radius, rigid).
struct PairProperties {
    double mass = 0.0;   ///< m* = m_a m_b / (m_a + m_b); m_a at a wall
    double radius = 0.0; ///< R* = R_a R_b / (R_a + R_b); R_a at a wall
    double young = 0.0;  ///< E* = 1 / ((1 - nu_a^2)/E_a + (1 - nu_b^2)/E_b)
    double shear = 0.0;  ///< G* = 1 / ((2 - nu_a)/G_a + (2 - nu_b)/G_b)
    double friction = 0.0;
    double rolling_friction = 0.0;
    /// I_r = 1 / (1/(I_a + m_a r_a^2) + 1/(I_b + m_b r_b^2)) of the rolling dashpot, each side
    /// (7/5) m r^2, a sphere of its grain's mass rolling on its contact point; I_a + m_a r_a^2
    /// at a wall.
    double rolling_inertia = 0.0;
};

/// The elastic constants of one side of a contact.
struct GrainElastic {
    double young = 0.0;
    double poisson = 0.0;
    double shear() const { return young / (2.0 * (1.0 + poisson)); }
};
/// E* and G* of two grains; of a grain on a rigid wall with `b` empty.
void combine_elastic(const GrainElastic& a, const std::optional<GrainElastic>& b,
                     PairProperties& pair);

/// One contact's state and result. In: overlap, normal n (from b to a), the relative velocity
/// of the contact points (a's less b's), the relative angular velocity (a's less b's), the time
/// step, and the tangential and rolling springs as the last step left them. Out: the force on
/// a (b gets its opposite), the rolling torque on a (b gets its opposite), the springs for the
/// next step.
struct ContactState {
    double overlap = 0.0;
    Vec3 normal = Vec3::Zero();
    Vec3 relative_velocity = Vec3::Zero();
    Vec3 relative_rotation = Vec3::Zero();
    Vec3 spring = Vec3::Zero();
    Vec3 rolling = Vec3::Zero();
    Vec3 force = Vec3::Zero();
    Vec3 torque = Vec3::Zero();
    /// The elastic energy the contact holds (normal and tangential springs), for the books.
    double elastic_energy = 0.0;
    /// The normal spring's force (the dashpot's left out) and its tangent stiffness
    /// dF_n/d(overlap) at the contact's overlap [N, N/m]: what a servo wall's contacts sum.
    double elastic_n = 0.0;
    double stiffness_n = 0.0;
};

/// Evaluate the contact: state.force, state.torque, the springs and state.elastic_energy from
/// the rest.
void contact_force(const ContactLaw& law, const PairProperties& pair, double time_step,
                   ContactState& state);

/// The cohesive pull of a pair within reach (state.overlap <= 0): state.force, zero torque and
/// springs, the spring's energy. `pull` is the pair's N_c [N].
void cohesive_force(const ContactLaw& law, double pull, ContactState& state);

/// How far apart (a negative overlap's size) a pair whose lighter grain has `mass` still
/// pulls: N_c / k_n with N_c = `pull_per_mass` times the mass; 0 without cohesion.
inline double cohesion_reach(const ContactLaw& law, double pull_per_mass, double mass) {
    return pull_per_mass > 0.0 ? pull_per_mass * mass / law.normal_stiffness : 0.0;
}

/// The alpha of a Hertz contact's dashpot alpha sqrt(m* k(delta)) that rebounds with the
/// coefficient of restitution e (0 < e <= 1): bisection on e(alpha), each e(alpha) from the
/// impact's dimensionless equation integrated by fourth-order Runge-Kutta.
double hertz_restitution_damping(double restitution);
/// The coefficient of restitution of a Hertz impact with the dashpot's alpha.
double hertz_restitution(double alpha);

/// The duration of a contact of the pair at a normal impact speed `speed`: pi / omega for the
/// linear law (omega the damped frequency), Hertz's 2.94 delta_max / v for the elastic Hertz
/// law (Johnson 1985, eq. 11.24), which damping lengthens by little.
double contact_time(const ContactLaw& law, const PairProperties& pair, double speed);

} // namespace grainload::dem
