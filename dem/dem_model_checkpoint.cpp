#include "dem/dem_model.hpp"
#include "io/binary_stream.hpp"

#include <stdexcept>

// DemModel's checkpoint: the grains, their spheres and springs, the walls, the neighbour list's
// positions of reference and the scene parts, restored bit for bit.

namespace grainload::dem {

namespace {

void write_springs(std::ostream& out, const std::vector<std::vector<Spring>>& rows) {
    std::vector<std::uint64_t> counts;
    std::vector<Spring> springs;
    for (const auto& row : rows) {
        counts.push_back(row.size());
        springs.insert(springs.end(), row.begin(), row.end());
    }
    io::write_array(out, counts);
    io::write_array(out, springs);
}

std::vector<std::vector<Spring>> read_springs(std::istream& in, std::size_t n) {
    std::vector<std::uint64_t> counts;
    std::vector<Spring> springs;
    io::read_array(in, counts, n, "sphere spring counts");
    io::read_array(in, springs);
    std::vector<std::vector<Spring>> rows(n);
    std::size_t at = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (counts[i] > springs.size() - at) {
            throw std::runtime_error("checkpoint: the spheres' springs are cut short");
        }
        rows[i].assign(springs.begin() + static_cast<std::ptrdiff_t>(at),
                       springs.begin() + static_cast<std::ptrdiff_t>(at + counts[i]));
        at += counts[i];
    }
    return rows;
}

void write_grains(std::ostream& out, const GrainSet& g) {
    io::write_array(out, g.id);
    io::write_array(out, g.body_id);
    io::write_array(out, g.mass);
    io::write_array(out, g.inertia);
    io::write_array(out, g.position);
    io::write_array(out, g.velocity);
    io::write_array(out, g.angular_velocity);
    std::vector<Eigen::Vector4d> orientation;
    for (const auto& q : g.orientation) {
        orientation.push_back(q.coeffs());
    }
    io::write_array(out, orientation);
    io::write_array(out, g.force);
    io::write_array(out, g.torque);
    io::write_value(out, g.next_id);
}

void read_grains(std::istream& in, GrainSet& g, int bodies) {
    io::read_array(in, g.id);
    const std::size_t n = g.id.size();
    io::read_array(in, g.body_id, n, "grain bodies");
    for (const int b : g.body_id) {
        if (b < 0 || b >= bodies) {
            throw std::runtime_error("checkpoint: a grain's body is not one of the case's");
        }
    }
    io::read_array(in, g.mass, n, "grain masses");
    io::read_array(in, g.inertia, n, "grain inertias");
    io::read_array(in, g.position, n, "grain positions");
    io::read_array(in, g.velocity, n, "grain velocities");
    io::read_array(in, g.angular_velocity, n, "grain angular velocities");
    std::vector<Eigen::Vector4d> orientation;
    io::read_array(in, orientation, n, "grain orientations");
    g.orientation.clear();
    for (const auto& c : orientation) {
        g.orientation.emplace_back(c);
    }
    io::read_array(in, g.force, n, "grain forces");
    io::read_array(in, g.torque, n, "grain torques");
    g.next_id = io::read_value<std::uint64_t>(in);
}

void write_spheres(std::ostream& out, const SphereSet& s) {
    io::write_array(out, s.id);
    io::write_array(out, s.grain);
    io::write_array(out, s.radius);
    io::write_array(out, s.offset);
    io::write_array(out, s.contacts);
    write_springs(out, s.springs);
    io::write_value(out, s.next_id);
}

void read_spheres(std::istream& in, SphereSet& s, Index grains) {
    io::read_array(in, s.id);
    const std::size_t n = s.id.size();
    io::read_array(in, s.grain, n, "sphere grains");
    for (std::size_t i = 0; i < n; ++i) {
        // In grain order, every grain with a sphere: first_of_grains relies on both.
        const Index previous = i > 0 ? s.grain[i - 1] : -1;
        if (s.grain[i] < 0 || s.grain[i] < previous || s.grain[i] > previous + 1 ||
            s.grain[i] >= grains) {
            throw std::runtime_error("checkpoint: the spheres do not follow their grains");
        }
    }
    io::read_array(in, s.radius, n, "sphere radii");
    io::read_array(in, s.offset, n, "sphere offsets");
    io::read_array(in, s.contacts, n, "sphere contact counts");
    s.springs = read_springs(in, n);
    s.next_id = io::read_value<std::uint64_t>(in);
    s.position.assign(n, Vec3::Zero());
    s.arm.assign(n, Vec3::Zero());
}

} // namespace

void DemModel::write_checkpoint(std::ostream& out) const {
    write_grains(out, grains_);
    // By grain id, those the sources made included.
    io::write_array(out, start_position_);
    write_spheres(out, spheres_);
    std::vector<Vec3> wall_forces;
    std::vector<double> normal_forces;
    std::vector<char> removed;
    for (const PlaneWall& wall : walls_) {
        wall_forces.push_back(wall.force);
        normal_forces.push_back(wall.normal_force);
        removed.push_back(wall.removed ? 1 : 0);
    }
    io::write_array(out, wall_forces);
    io::write_array(out, normal_forces);
    io::write_array(out, removed);
    io::write_value(out, books_);
    io::write_value(out, step_);
    io::write_array(
        out, std::vector<Vec3>(neighbours_.reference().begin(), neighbours_.reference().end()));
    parts_.write_checkpoint(out);
}

void DemModel::read_checkpoint(std::istream& in) {
    read_grains(in, grains_, static_cast<int>(body_names_.size()));
    io::read_array(in, start_position_, static_cast<std::size_t>(grains_.next_id),
                   "grain start positions");
    read_spheres(in, spheres_, grains_.size());
    if (spheres_.size() > 0 && spheres_.grain.back() != grains_.size() - 1) {
        throw std::runtime_error("checkpoint: a grain has no sphere");
    }
    spheres_.place(grains_);
    std::vector<Vec3> wall_forces;
    std::vector<double> normal_forces;
    std::vector<char> removed;
    io::read_array(in, wall_forces, walls_.size(), "wall forces");
    io::read_array(in, normal_forces, walls_.size(), "walls' normal forces");
    io::read_array(in, removed, walls_.size(), "walls removed");
    for (std::size_t w = 0; w < walls_.size(); ++w) {
        walls_[w].force = wall_forces[w];
        walls_[w].normal_force = normal_forces[w];
        walls_[w].removed = removed[w] != 0;
    }
    books_ = io::read_value<ContactBooks>(in);
    step_ = io::read_value<double>(in);
    // The list the uninterrupted run is using was built at these positions: the same pairs in
    // the same order, so the same sums.
    std::vector<Vec3> reference;
    io::read_array(in, reference, static_cast<std::size_t>(spheres_.size()),
                   "neighbour list positions");
    neighbours_.update(reference, {}, true);
    events_.clear();
    parts_.read_checkpoint(in);
}

} // namespace grainload::dem
