#include "dem/grain_set.hpp"

#include "particles/compact.hpp"

namespace grainload::dem {

Index GrainSet::add(int body, double grain_mass, const Vec3& moments, const Vec3& at,
                    const Eigen::Quaterniond& turned) {
    id.push_back(next_id++);
    body_id.push_back(body);
    mass.push_back(grain_mass);
    inertia.push_back(moments);
    position.push_back(at);
    velocity.push_back(Vec3::Zero());
    angular_velocity.push_back(Vec3::Zero());
    orientation.push_back(turned);
    force.push_back(Vec3::Zero());
    torque.push_back(Vec3::Zero());
    return size() - 1;
}

Mat3 GrainSet::world_inertia(Index i) const {
    const Mat3 r = orientation[static_cast<std::size_t>(i)].toRotationMatrix();
    return r * inertia[static_cast<std::size_t>(i)].asDiagonal() * r.transpose();
}

double GrainSet::total_mass() const {
    double sum = 0.0;
    for (const double m : mass) {
        sum += m;
    }
    return sum;
}

void GrainSet::keep(std::span<const char> gone) {
    particles::compact(id, gone);
    particles::compact(body_id, gone);
    particles::compact(mass, gone);
    particles::compact(inertia, gone);
    particles::compact(position, gone);
    particles::compact(velocity, gone);
    particles::compact(angular_velocity, gone);
    particles::compact(orientation, gone);
    particles::compact(force, gone);
    particles::compact(torque, gone);
}

} // namespace grainload::dem
