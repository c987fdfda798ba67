#include "dem/contact_law.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace grainload::dem {

void combine_elastic(const GrainElastic& a, const std::optional<GrainElastic>& b,
                     PairProperties& pair) {
    double compliance = (1.0 - a.poisson * a.poisson) / a.young;
    double shear_compliance = (2.0 - a.poisson) / a.shear();
    if (b) {
        compliance += (1.0 - b->poisson * b->poisson) / b->young;
        shear_compliance += (2.0 - b->poisson) / b->shear();
    }
    pair.young = 1.0 / compliance;
    pair.shear = 1.0 / shear_compliance;
}

namespace {

/// The linear law's normal dashpot: gamma_n m*, or the one that gives restitution e.
double linear_damping(const ContactLaw& law, const PairProperties& pair) {
    if (!law.restitution) {
        return law.gamma_n * pair.mass;
    }
    const double log_e = std::log(*law.restitution);
    return 2.0 * std::sqrt(law.normal_stiffness * pair.mass) * (-log_e) /
           std::sqrt(std::numbers::pi * std::numbers::pi + log_e * log_e);
}

/// The part of `v` in the plane normal to `n`, turned back to its length: a spring carried
/// along as the contact turns (Luding 2008).
Vec3 turned_into_plane(const Vec3& v, const Vec3& n) {
    const double length = v.norm();
    Vec3 in_plane = v - v.dot(n) * n;
    const double turned = in_plane.norm();
    if (turned > 0.0) {
        in_plane *= length / turned;
    }
    return in_plane;
}

/// Ai, Chen, Rotter & Ooi 2011, model C: the rolling spring's torque, capped at full
/// mobilisation, with its dashpot below the cap; the torque on a, the spring and its energy
/// into `state`. `stiffness_n` is the normal law's tangent stiffness.
void rolling_resistance(const ContactLaw& law, const PairProperties& pair, double stiffness_n,
                        double normal_force, double time_step, ContactState& state) {
    const Vec3& n = state.normal;
    // Rolling only: the relative turn about the normal (twisting) meets no resistance here.
    const Vec3 rolling_rate = state.relative_rotation - state.relative_rotation.dot(n) * n;
    const double stiffness_r = 2.25 * stiffness_n * pair.rolling_friction * pair.rolling_friction *
                               pair.radius * pair.radius;
    Vec3 spring = turned_into_plane(state.rolling, n) - stiffness_r * time_step * rolling_rate;
    const double limit = pair.rolling_friction * pair.radius * std::max(normal_force, 0.0);
    const double magnitude = spring.norm();
    Vec3 torque = spring;
    if (magnitude > limit) {
        spring *= magnitude > 0.0 ? limit / magnitude : 0.0;
        torque = spring; // fully mobilised: no dashpot (Ai et al.'s f = 0)
    } else {
        torque -= law.rolling_damping * 2.0 * std::sqrt(pair.rolling_inertia * stiffness_r) *
                  rolling_rate;
        // Nor does the dashpot's torque with the spring's pass full mobilisation: a contact
        // that forms on a fast-spinning grain would otherwise brake it at C_r omega, tens of
        // times the torque the contact can carry.
        const double total = torque.norm();
        if (total > limit) {
            torque *= limit / total;
        }
    }
    state.rolling = spring;
    state.torque = torque;
    if (stiffness_r > 0.0) {
        state.elastic_energy += 0.5 * spring.squaredNorm() / stiffness_r;
    }
}

} // namespace

void contact_force(const ContactLaw& law, const PairProperties& pair, double time_step,
                   ContactState& state) {
    const Vec3& n = state.normal;
    const double delta = state.overlap;
    const double normal_speed = state.relative_velocity.dot(n);
    const Vec3 tangential_velocity = state.relative_velocity - normal_speed * n;

    double elastic_normal = 0.0;
    double stiffness_n = 0.0; // tangent
    double stiffness_t = 0.0;
    double damping_n = 0.0;
    if (law.model == ContactLaw::Model::linear) {
        elastic_normal = law.normal_stiffness * delta;
        stiffness_n = law.normal_stiffness;
        stiffness_t = law.tangential_stiffness_ratio * law.normal_stiffness;
        damping_n = linear_damping(law, pair);
        state.elastic_energy = 0.5 * elastic_normal * delta;
    } else {
        const double root = std::sqrt(pair.radius * delta);
        elastic_normal = 4.0 / 3.0 * pair.young * root * delta;
        stiffness_n = 2.0 * pair.young * root;
        stiffness_t = 8.0 * pair.shear * root;
        damping_n = law.restitution
                        ? law.hertz_alpha * std::sqrt(pair.mass * 2.0 * pair.young * root)
                        : law.gamma_n * pair.mass;
        state.elastic_energy = 0.4 * elastic_normal * delta;
    }
    const double normal_force = elastic_normal - damping_n * normal_speed;
    state.elastic_n = elastic_normal;
    state.stiffness_n = stiffness_n;

    // The spring lives in the tangent plane: turn it with the contact, then add this step's
    // slip.
    Vec3 spring = turned_into_plane(state.spring, n) + tangential_velocity * time_step;
    const Vec3 damping_t = law.gamma_t * pair.mass * tangential_velocity;
    Vec3 tangential = -stiffness_t * spring - damping_t;
    // Friction needs the grains pressed together: where the dashpot pulls at the end of a
    // contact (a normal force below zero) the slider carries nothing.
    const double limit = pair.friction * std::max(normal_force, 0.0);
    const double magnitude = tangential.norm();
    if (magnitude > limit) {
        tangential *= magnitude > 0.0 ? limit / magnitude : 0.0;
        // The spring takes the slip force less the dashpot's share (Luding 2008), so that a
        // contact that stops slipping starts from the force it slid with.
        spring = stiffness_t > 0.0 ? Vec3(-(tangential + damping_t) / stiffness_t) : Vec3::Zero();
    }
    state.spring = spring;
    if (stiffness_t > 0.0) {
        state.elastic_energy += 0.5 * stiffness_t * spring.squaredNorm();
    }
    state.force = normal_force * n + tangential;
    if (pair.rolling_friction > 0.0) {
        rolling_resistance(law, pair, stiffness_n, normal_force, time_step, state);
    } else {
        state.torque = Vec3::Zero();
        state.rolling = Vec3::Zero();
    }
}

void cohesive_force(const ContactLaw& law, double pull, ContactState& state) {
    state.torque = Vec3::Zero();
    state.spring = Vec3::Zero();
    state.rolling = Vec3::Zero();
    const bool separating = state.relative_velocity.dot(state.normal) > 0.0;
    const double delta = state.overlap;
    if (separating && delta >= -pull / law.normal_stiffness) {
        state.force = law.normal_stiffness * delta * state.normal;
        state.elastic_energy = 0.5 * law.normal_stiffness * delta * delta;
    } else {
        state.force = Vec3::Zero();
        state.elastic_energy = 0.0;
    }
}

double hertz_restitution(double alpha) {
    // x = delta / delta_max(elastic), tau = t v / delta_max: x(0) = 0, x'(0) = 1, until the
    // grains part (x back to 0); e = -x'. The elastic impact lasts tau = 2.94.
    const double damping = alpha * std::sqrt(15.0 / 8.0);
    const auto rate = [damping](double x, double v) {
        const double pressed = std::max(x, 0.0);
        return -damping * std::pow(pressed, 0.25) * v - 1.25 * std::pow(pressed, 1.5);
    };
    constexpr double step = 2.5e-4;
    double x = 0.0;
    double v = 1.0;
    for (int k = 0; k < 1000000 && (x > 0.0 || v > 0.0 || k == 0); ++k) {
        const double a1 = rate(x, v);
        const double a2 = rate(x + 0.5 * step * v, v + 0.5 * step * a1);
        const double a3 = rate(x + 0.5 * step * (v + 0.5 * step * a1), v + 0.5 * step * a2);
        const double a4 = rate(x + step * (v + 0.5 * step * a2), v + step * a3);
        x += step * (v + step / 6.0 * (a1 + a2 + a3));
        v += step / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
    }
    return std::max(-v, 0.0);
}

double hertz_restitution_damping(double restitution) {
    double low = 0.0;
    double high = 1.0;
    while (hertz_restitution(high) > restitution) {
        high *= 2.0;
    }
    // e(alpha) falls from 1 at alpha = 0; 45 halvings leave the root to 1e-13 of it.
    for (int k = 0; k < 45; ++k) {
        const double middle = 0.5 * (low + high);
        (hertz_restitution(middle) > restitution ? low : high) = middle;
    }
    return 0.5 * (low + high);
}

double contact_time(const ContactLaw& law, const PairProperties& pair, double speed) {
    if (law.model == ContactLaw::Model::linear) {
        const double damping = linear_damping(law, pair) / pair.mass;
        const double omega0_squared = law.normal_stiffness / pair.mass;
        return std::numbers::pi / std::sqrt(omega0_squared - 0.25 * damping * damping);
    }
    // Hertz: delta_max from (1/2) m* v^2 = (8/15) E* sqrt(R*) delta^(5/2); the duration is
    // 2 delta_max / v times int_0^1 (1 - x^(5/2))^(-1/2) dx = (2/5) B(2/5, 1/2).
    const double delta_max = std::pow(
        15.0 * pair.mass * speed * speed / (16.0 * pair.young * std::sqrt(pair.radius)), 0.4);
    const double beta = std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
    return 2.0 * delta_max / speed * 0.4 * beta;
}

} // namespace grainload::dem
