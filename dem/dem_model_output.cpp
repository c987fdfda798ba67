#include "dem/dem_model.hpp"
#include "io/binary_stream.hpp"
#include "io/output_streams.hpp"

#include <sstream>

// DemModel's output: the frames' grain blocks, wall_forces.csv, the summary's figures, and the
// checkpoint.

namespace grainload::dem {

namespace {

constexpr std::string_view kWallForcesHeader = "time_s,wall,force_x_N,force_y_N,force_z_N\n";

/// A grain's orientation as its rotation vector (axis times angle in radians, |angle| <= pi):
/// three components, as ParaView's glyphs take them.
Vec3 rotation_vector(const Eigen::Quaterniond& q) {
    const Eigen::AngleAxisd turn(q.w() < 0.0 ? Eigen::Quaterniond(-q.coeffs()) : q);
    return turn.angle() * turn.axis();
}

void append3(io::FieldArray& array, const Vec3& v) {
    array.values.insert(array.values.end(), v.data(), v.data() + 3);
}

} // namespace

void DemModel::append_blocks(io::Frame& frame) const {
    const GrainSet& g = grains_;
    for (std::size_t b = 0; b < body_names_.size(); ++b) {
        io::Block block;
        block.name = body_names_[b];
        io::FieldArray radius{"radius", 1, {}}, velocity{"velocity", 3, {}};
        io::FieldArray spin{"angular_velocity", 3, {}}, orientation{"orientation", 3, {}};
        io::FieldArray contacts{"contact_count", 1, {}}, body{"body_id", 1, {}};
        for (Index i = 0; i < g.size(); ++i) {
            if (g.body_id[i] != static_cast<int>(b)) {
                continue;
            }
            block.points.push_back(g.position[i]);
            radius.values.push_back(g.radius[i]);
            append3(velocity, g.velocity[i]);
            append3(spin, g.angular_velocity[i]);
            append3(orientation, rotation_vector(g.orientation[i]));
            contacts.values.push_back(g.contacts[i]);
            body.values.push_back(g.body_id[i]);
        }
        block.point_arrays = {radius, velocity, spin, orientation, contacts, body};
        frame.blocks.push_back(std::move(block));
    }
    write_wall_rows(frame.time);
    write_part_rows(frame.time);
}

void DemModel::write_wall_rows(double time) const {
    if (output_ == nullptr || walls_.empty() || !(time > last_row_time_)) {
        return;
    }
    last_row_time_ = time;
    std::ostringstream rows;
    rows.precision(17);
    for (const PlaneWall& wall : walls_) {
        rows << time << ',' << wall.name << ',' << wall.force.x() << ',' << wall.force.y() << ','
             << wall.force.z() << '\n';
    }
    output_->open("wall_forces.csv", kWallForcesHeader).append(rows.str());
}

void DemModel::write_part_rows(double time) const {
    if (output_ != nullptr && time > last_part_time_) {
        last_part_time_ = time;
        parts_.at_output(time, *output_);
    }
}

void DemModel::append_results(double /*t*/, std::vector<io::ResultFigure>& results) const {
    const GrainSet& g = grains_;
    results.push_back({"grains", static_cast<double>(g.size()), "", std::nullopt, ""});
    parts_.append_results(results);
    const DemEnergy e = energy();
    results.push_back({"kinetic_energy", e.translational + e.rotational, "J", std::nullopt, ""});
    results.push_back({"contact_energy", e.elastic, "J", std::nullopt, ""});
    results.push_back({"gravity_work", -e.gravity, "J", std::nullopt, ""});
    results.push_back(
        {"contacts", static_cast<double>(books_.pair_contacts), "", std::nullopt, ""});
    results.push_back({"coordination_number",
                       g.size() > 0 ? 2.0 * static_cast<double>(books_.pair_contacts) /
                                          static_cast<double>(g.size())
                                    : 0.0,
                       "", std::nullopt, ""});
    // DEM practice keeps overlaps to about 1 % of a radius where the grains stand for stiff
    // ones: the figure says how soft the contact law made them.
    results.push_back({"deepest_overlap", books_.deepest_overlap, "of a radius", std::nullopt, ""});
    Vec3 load = Vec3::Zero();
    for (const PlaneWall& wall : walls_) {
        load += wall.force;
        for (int a = 0; a < 3; ++a) {
            const std::string axis(1, static_cast<char>('x' + a));
            results.push_back(
                {"wall_" + wall.name + "_force_" + axis, wall.force[a], "N", std::nullopt, ""});
        }
    }
    const double g_norm = gravity_.norm();
    if (!walls_.empty() && g_norm > 0.0) {
        double weight = 0.0;
        for (const double m : g.mass) {
            weight += m * g_norm;
        }
        // At rest the walls carry the grains' weight: the reference is static equilibrium.
        results.push_back({"walls_load_along_gravity", load.dot(gravity_) / g_norm, "N", weight,
                           "the grains' weight, sum m g (static equilibrium at rest)"});
    }
}

void DemModel::describe_model(std::vector<io::ModelChoice>& choices) const {
    const bool linear = settings_.law.model == ContactLaw::Model::linear;
    choices.push_back({"dem contact", linear ? "linear spring-dashpot" : "hertz_mindlin"});
    for (std::size_t b = 0; b < body_names_.size(); ++b) {
        choices.push_back(
            {"dem body " + body_names_[b], "spheres of material " + body_materials_[b]});
    }
    for (const PlaneWall& wall : walls_) {
        choices.push_back({"dem wall " + wall.name, "rigid plane faces"});
    }
}

void DemModel::write_checkpoint(std::ostream& out) const {
    const GrainSet& g = grains_;
    io::write_array(out, g.id);
    io::write_array(out, g.body_id);
    io::write_array(out, g.radius);
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
    io::write_array(out, g.contacts);
    std::vector<std::uint64_t> spring_counts;
    std::vector<Spring> springs;
    for (const auto& row : g.springs) {
        spring_counts.push_back(row.size());
        springs.insert(springs.end(), row.begin(), row.end());
    }
    io::write_array(out, spring_counts);
    io::write_array(out, springs);
    io::write_value(out, g.next_id);
    std::vector<Vec3> wall_forces;
    std::vector<char> removed;
    for (const PlaneWall& wall : walls_) {
        wall_forces.push_back(wall.force);
        removed.push_back(wall.removed ? 1 : 0);
    }
    io::write_array(out, wall_forces);
    io::write_array(out, removed);
    io::write_value(out, books_);
    io::write_value(out, step_);
    io::write_array(
        out, std::vector<Vec3>(neighbours_.reference().begin(), neighbours_.reference().end()));
    parts_.write_checkpoint(out);
}

void DemModel::read_checkpoint(std::istream& in) {
    GrainSet& g = grains_;
    io::read_array(in, g.id);
    const std::size_t n = g.id.size();
    io::read_array(in, g.body_id, n, "grain bodies");
    for (const int b : g.body_id) {
        if (b < 0 || b >= static_cast<int>(body_names_.size())) {
            throw std::runtime_error("checkpoint: a grain's body is not one of the case's");
        }
    }
    io::read_array(in, g.radius, n, "grain radii");
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
    io::read_array(in, g.contacts, n, "grain contact counts");
    std::vector<std::uint64_t> spring_counts;
    std::vector<Spring> springs;
    io::read_array(in, spring_counts, n, "grain spring counts");
    io::read_array(in, springs);
    g.springs.assign(n, {});
    std::size_t at = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (spring_counts[i] > springs.size() - at) {
            throw std::runtime_error("checkpoint: the grains' springs are cut short");
        }
        g.springs[i].assign(springs.begin() + static_cast<std::ptrdiff_t>(at),
                            springs.begin() + static_cast<std::ptrdiff_t>(at + spring_counts[i]));
        at += spring_counts[i];
    }
    g.next_id = io::read_value<std::uint64_t>(in);
    std::vector<Vec3> wall_forces;
    std::vector<char> removed;
    io::read_array(in, wall_forces, walls_.size(), "wall forces");
    io::read_array(in, removed, walls_.size(), "walls removed");
    for (std::size_t w = 0; w < walls_.size(); ++w) {
        walls_[w].force = wall_forces[w];
        walls_[w].removed = removed[w] != 0;
    }
    books_ = io::read_value<ContactBooks>(in);
    step_ = io::read_value<double>(in);
    // The list the uninterrupted run is using was built at these positions: the same pairs in
    // the same order, so the same sums.
    std::vector<Vec3> reference;
    io::read_array(in, reference, n, "neighbour list positions");
    neighbours_.update(reference, {}, true);
    events_.clear();
    parts_.read_checkpoint(in);
}

} // namespace grainload::dem
