#include "dem/grain_set.hpp"

#include "particles/compact.hpp"

#include <numbers>

namespace grainload::dem {

void GrainSet::add(int body, double grain_radius, double density, const Vec3& at, bool rotates) {
    const double m =
        4.0 / 3.0 * std::numbers::pi * grain_radius * grain_radius * grain_radius * density;
    id.push_back(next_id++);
    body_id.push_back(body);
    radius.push_back(grain_radius);
    mass.push_back(m);
    inertia.push_back(rotates ? 0.4 * m * grain_radius * grain_radius : 0.0);
    position.push_back(at);
    velocity.push_back(Vec3::Zero());
    angular_velocity.push_back(Vec3::Zero());
    orientation.push_back(Eigen::Quaterniond::Identity());
    force.push_back(Vec3::Zero());
    torque.push_back(Vec3::Zero());
    contacts.push_back(0);
    springs.emplace_back();
}

void GrainSet::keep(std::span<const char> gone) {
    particles::compact(id, gone);
    particles::compact(body_id, gone);
    particles::compact(radius, gone);
    particles::compact(mass, gone);
    particles::compact(inertia, gone);
    particles::compact(position, gone);
    particles::compact(velocity, gone);
    particles::compact(angular_velocity, gone);
    particles::compact(orientation, gone);
    particles::compact(force, gone);
    particles::compact(torque, gone);
    particles::compact(contacts, gone);
    particles::compact(springs, gone);
}

} // namespace grainload::dem
