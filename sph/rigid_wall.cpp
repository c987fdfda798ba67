#include "sph/rigid_wall.hpp"

#include "io/binary_stream.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace grainload::sph {

namespace {

int steps_along(double length, double spacing) {
    return std::max(1, static_cast<int>(std::lround(length / spacing))) + 1;
}

} // namespace

std::vector<Vec3> plane_wall_points(const Vec3& origin, const Vec3& u, const Vec3& v,
                                    const Vec3& normal, double spacing, int layers, int dimension) {
    const int nu = steps_along(u.norm(), spacing);
    const int nv = dimension == 2 ? 1 : steps_along(v.norm(), spacing);
    const Vec3 inward = normal.normalized();
    std::vector<Vec3> points;
    points.reserve(static_cast<std::size_t>(nu) * static_cast<std::size_t>(nv) *
                   static_cast<std::size_t>(layers));
    for (int layer = 0; layer < layers; ++layer) {
        for (int b = 0; b < nv; ++b) {
            for (int a = 0; a < nu; ++a) {
                const double s = static_cast<double>(a) / std::max(nu - 1, 1);
                const double t = nv > 1 ? static_cast<double>(b) / (nv - 1) : 0.0;
                points.push_back(origin + s * u + t * v -
                                 (0.5 + static_cast<double>(layer)) * spacing * inward);
            }
        }
    }
    return points;
}

std::vector<Vec3> box_wall_points(const Vec3& lower, const Vec3& upper, double spacing, int layers,
                                  int dimension, bool open_top) {
    const int up = dimension == 2 ? 1 : 2;
    const double thickness = layers * spacing;
    Vec3 outer_lower = lower - Vec3::Constant(thickness - 0.5 * spacing);
    Vec3 outer_upper = upper + Vec3::Constant(thickness - 0.5 * spacing);
    if (dimension == 2) {
        outer_lower.z() = 0.0;
        outer_upper.z() = 0.0;
    }
    std::array<int, 3> count{1, 1, 1};
    for (int a = 0; a < dimension; ++a) {
        count[a] =
            static_cast<int>(std::floor((outer_upper[a] - outer_lower[a]) / spacing + 1e-9)) + 1;
    }
    std::vector<Vec3> points;
    for (int k = 0; k < count[2]; ++k) {
        for (int j = 0; j < count[1]; ++j) {
            for (int i = 0; i < count[0]; ++i) {
                const Vec3 x = outer_lower + spacing * Vec3(i, j, k);
                bool inside = true;
                for (int a = 0; a < dimension; ++a) {
                    inside = inside && x[a] > lower[a] && x[a] < upper[a];
                }
                const bool above = x[up] > upper[up];
                if (!inside && !(open_top && above)) {
                    points.push_back(x);
                }
            }
        }
    }
    return points;
}

Vec3 history_value(const std::vector<std::pair<double, Vec3>>& history, double time) {
    if (time <= history.front().first) {
        return history.front().second;
    }
    for (std::size_t k = 1; k < history.size(); ++k) {
        const auto& [t1, v1] = history[k];
        if (time < t1) {
            const auto& [t0, v0] = history[k - 1];
            return v0 + (time - t0) / (t1 - t0) * (v1 - v0);
        }
    }
    return history.back().second;
}

namespace {

/// Integral of the history from its first point to `time` (negative before it), summed
/// segment by segment with the trapezoid rule, exact for a linear segment.
Vec3 history_antiderivative(const std::vector<std::pair<double, Vec3>>& history, double time) {
    const double start = history.front().first;
    if (time <= start) {
        return (time - start) * history.front().second;
    }
    Vec3 sum = Vec3::Zero();
    for (std::size_t k = 1; k < history.size(); ++k) {
        const auto& [t0, v0] = history[k - 1];
        const double end = std::min(time, history[k].first);
        sum += 0.5 * (end - t0) * (v0 + history_value(history, end));
        if (time <= history[k].first) {
            return sum;
        }
    }
    return sum + (time - history.back().first) * history.back().second;
}

} // namespace

Vec3 history_integral(const std::vector<std::pair<double, Vec3>>& history, double from, double to) {
    return history_antiderivative(history, to) - history_antiderivative(history, from);
}

void RigidMotion::move(ParticleSet& particles, Wall& wall, double time, double dt) {
    Vec3 displacement = dt * velocity;
    if (!velocity_history.empty()) {
        displacement = history_integral(velocity_history, time, time + dt);
        velocity = history_value(velocity_history, time + dt);
    }
    Vec3 rotation_vector = dt * angular_velocity;
    if (!angular_velocity_history.empty()) {
        rotation_vector = history_integral(angular_velocity_history, time, time + dt);
        angular_velocity = history_value(angular_velocity_history, time + dt);
    }
    const double angle = rotation_vector.norm();
    const Mat3 rotation =
        angle > 0.0 ? Eigen::AngleAxisd(angle, rotation_vector / angle).matrix() : Mat3::Identity();
    const Vec3 new_centre = centre + displacement;
    for (Vec3& normal : wall.normals) {
        normal = rotation * normal;
    }
    wall.angular_velocities.assign(static_cast<std::size_t>(wall.count), angular_velocity);
    for (Index k = wall.first; k < wall.first + wall.count; ++k) {
        const Vec3 arm = rotation * (particles.position[k] - centre);
        particles.position[k] = new_centre + arm;
        particles.velocity[k] = velocity + angular_velocity.cross(arm);
    }
    centre = new_centre;
    wall.centre = centre;
}

void RigidMotion::start_histories(double start) {
    if (!std::isfinite(start)) {
        return;
    }
    const auto placed = [start](std::vector<std::pair<double, Vec3>> history) {
        for (auto& point : history) {
            point.first += start;
        }
        return history;
    };
    velocity_history = placed(relative_velocity_history);
    angular_velocity_history = placed(relative_angular_velocity_history);
}

bool RigidMotion::at_rest() const {
    return history_phase < 0 && velocity_history.empty() && angular_velocity_history.empty() &&
           velocity.squaredNorm() == 0.0 && angular_velocity.squaredNorm() == 0.0;
}

void RigidMotion::write_state(std::ostream& out) const {
    io::write_array(out, std::vector<Vec3>{centre, velocity, angular_velocity});
}

void RigidMotion::read_state(std::istream& in) {
    std::vector<Vec3> state;
    io::read_array(in, state);
    if (state.size() != 3) {
        throw std::runtime_error("checkpoint: a rigid wall motion holds 3 vectors, found " +
                                 std::to_string(state.size()));
    }
    centre = state[0];
    velocity = state[1];
    angular_velocity = state[2];
}

RigidMotion& attach_rigid_motion(ParticleSet& particles, Wall& wall, const Vec3& velocity,
                                 const Vec3& angular_velocity) {
    auto motion = std::make_shared<RigidMotion>();
    motion->centre = wall.centre;
    motion->velocity = velocity;
    motion->angular_velocity = angular_velocity;
    wall.angular_velocities.assign(static_cast<std::size_t>(wall.count), angular_velocity);
    for (Index k = wall.first; k < wall.first + wall.count; ++k) {
        particles.velocity[k] =
            velocity + angular_velocity.cross(particles.position[k] - wall.centre);
    }
    RigidMotion& reference = *motion;
    wall.driver = std::move(motion);
    return reference;
}

std::vector<Vec3> box_wall_normals(const std::vector<Vec3>& points, const Vec3& lower,
                                   const Vec3& upper, int dimension) {
    std::vector<Vec3> normals;
    normals.reserve(points.size());
    for (const Vec3& x : points) {
        Vec3 inward = x.cwiseMax(lower).cwiseMin(upper) - x;
        if (dimension == 2) {
            inward.z() = 0.0;
        }
        const double length = inward.norm();
        normals.push_back(length > 0.0 ? Vec3(inward / length) : Vec3::Zero());
    }
    return normals;
}

std::string wall_force_rows(double time, const std::vector<Wall>& walls) {
    std::ostringstream out;
    for (const Wall& w : walls) {
        out << time << ',' << w.name << ',' << w.force.x() << ',' << w.force.y() << ','
            << w.force.z() << ',' << w.moment.x() << ',' << w.moment.y() << ',' << w.moment.z()
            << '\n';
    }
    return out.str();
}

} // namespace grainload::sph
