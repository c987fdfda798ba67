#include "dem/dem_model.hpp"
#include "io/output_streams.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

// DemModel's output: the frames' grain blocks, wall_forces.csv and the summary's figures.

namespace grainload::dem {

namespace {

constexpr std::string_view kWallForcesHeader =
    "time_s,wall,force_x_N,force_y_N,force_z_N,normal_N\n";

/// A grain's orientation as its rotation vector (axis times angle in radians, |angle| <= pi):
/// three components, as ParaView's glyphs take them.
Vec3 rotation_vector(const Eigen::Quaterniond& q) {
    const Eigen::AngleAxisd turn(q.w() < 0.0 ? Eigen::Quaterniond(-q.coeffs()) : q);
    return turn.angle() * turn.axis();
}

void append3(io::FieldArray& array, const Vec3& v) {
    array.values.insert(array.values.end(), v.data(), v.data() + 3);
}

/// The contacts as lines, sphere by sphere in order: force chains to colour by normal_force.
io::Block contact_block(const std::vector<std::vector<ContactRecord>>& records) {
    io::Block block;
    block.name = "contacts";
    block.kind = io::Block::Kind::lines;
    io::FieldArray force{"force", 3, {}}, normal{"normal_force", 1, {}};
    io::FieldArray tangential{"tangential_force", 1, {}}, overlap{"overlap", 1, {}};
    io::FieldArray wall{"wall", 1, {}};
    for (const auto& row : records) {
        for (const ContactRecord& contact : row) {
            const auto first = static_cast<Index>(block.points.size());
            block.points.push_back(contact.from);
            block.points.push_back(contact.to);
            block.cells.push_back({first, first + 1, -1, -1});
            const double pressing = contact.force.dot(contact.normal);
            append3(force, contact.force);
            normal.values.push_back(pressing);
            tangential.values.push_back((contact.force - pressing * contact.normal).norm());
            overlap.values.push_back(contact.overlap);
            wall.values.push_back(contact.wall ? 1.0 : 0.0);
        }
    }
    block.cell_arrays = {force, normal, tangential, overlap, wall};
    return block;
}

} // namespace

void DemModel::append_blocks(io::Frame& frame) const {
    const GrainSet& g = grains_;
    const SphereSet& s = spheres_;
    // A clump shows as its spheres, each with its grain's motion and id.
    for (std::size_t b = 0; b < body_names_.size(); ++b) {
        io::Block block;
        block.name = body_names_[b];
        io::FieldArray radius{"radius", 1, {}}, velocity{"velocity", 3, {}};
        io::FieldArray spin{"angular_velocity", 3, {}}, orientation{"orientation", 3, {}};
        io::FieldArray contacts{"contact_count", 1, {}}, body{"body_id", 1, {}};
        io::FieldArray grain{"grain_id", 1, {}};
        for (Index i = 0; i < s.size(); ++i) {
            const auto k = static_cast<std::size_t>(s.grain[i]);
            if (g.body_id[k] != static_cast<int>(b)) {
                continue;
            }
            block.points.push_back(s.position[i]);
            radius.values.push_back(s.radius[i]);
            append3(velocity, g.velocity[k] + g.angular_velocity[k].cross(s.arm[i]));
            append3(spin, g.angular_velocity[k]);
            append3(orientation, rotation_vector(g.orientation[k]));
            contacts.values.push_back(s.contacts[i]);
            body.values.push_back(g.body_id[k]);
            grain.values.push_back(static_cast<double>(g.id[k]));
        }
        block.point_arrays = {radius, velocity, spin, orientation, contacts, body, grain};
        frame.blocks.push_back(std::move(block));
    }
    if (settings_.contact_forces) {
        frame.blocks.push_back(contact_block(scratch_.records));
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
             << wall.force.z() << ',' << wall.normal_force << '\n';
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
    // Where the grains' mass stands: a deposit's spread, a rolling grain's stop.
    if (g.size() > 0) {
        Vec3 moment = Vec3::Zero();
        for (Index i = 0; i < g.size(); ++i) {
            moment += g.mass[i] * g.position[i];
        }
        const Vec3 centre = moment / g.total_mass();
        for (int a = 0; a < 3; ++a) {
            results.push_back({std::string("grains_centre_of_mass_") + static_cast<char>('x' + a),
                               centre[a], "m", std::nullopt, ""});
        }
    }
    parts_.append_results(results);
    const DemEnergy e = energy();
    results.push_back({"kinetic_energy", e.translational + e.rotational, "J", std::nullopt, ""});
    results.push_back({"contact_energy", e.elastic, "J", std::nullopt, ""});
    results.push_back({"gravity_work", -e.gravity, "J", std::nullopt, ""});
    // What the dashpots, the sliders and cohesion's partings took: the books' balance, where
    // no sink carries energy out of the scene, no source brings it in and no wall moves (a
    // coupled shell's follows the shell).
    if (sinks_->empty() && sources_->empty() &&
        std::none_of(walls_.begin(), walls_.end(),
                     [](const PlaneWall& w) { return w.moves() || w.follows(); })) {
        results.push_back({"dissipated_energy", start_energy_ - e.total(), "J", std::nullopt, ""});
    }
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
        results.push_back(
            {"wall_" + wall.name + "_normal_force", wall.normal_force, "N", std::nullopt, ""});
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
    if (settings_.integrator == Integrator::predictor_corrector) {
        char text[160];
        std::snprintf(text, sizeof text,
                      "predictor-corrector (Lazarevic, Dvornik & Fresl 2002), up to %d corrector "
                      "pass%s a step, tolerance %g g",
                      settings_.corrector_passes, settings_.corrector_passes == 1 ? "" : "es",
                      settings_.corrector_tolerance);
        choices.push_back({"dem integrator", text});
    } else {
        choices.push_back({"dem integrator", "velocity Verlet"});
    }
    if (settings_.law.rolling_friction > 0.0 || settings_.law.wall_rolling_friction > 0.0) {
        choices.push_back(
            {"dem rolling resistance", "elastic-plastic spring-dashpot (Ai et al. 2011, model C)"});
    }
    for (std::size_t b = 0; b < body_names_.size(); ++b) {
        choices.push_back(
            {"dem body " + body_names_[b], "spheres of material " + body_materials_[b]});
    }
    for (const PlaneWall& wall : walls_) {
        const std::string triangles = std::to_string(wall.faces.size()) + " triangles";
        std::string what = wall.follows() ? "mesh of " + triangles + " that follows a shell"
                           : wall.mesh()  ? "rigid mesh of " + triangles
                                          : std::string("rigid plane faces");
        if (wall.removal_phase >= 0) {
            what +=
                ", removed when phase \"" +
                phases_->sequence().phases()[static_cast<std::size_t>(wall.removal_phase)].name +
                "\" begins";
        }
        choices.push_back({"dem wall " + wall.name, what});
    }
}

} // namespace grainload::dem
