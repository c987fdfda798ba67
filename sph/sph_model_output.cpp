#include "io/output_streams.hpp"
#include "sph/sph_model.hpp"
#include "sph/stress_measures.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <span>
#include <sstream>
#include <utility>

// SphModel's output: the frames' particle and wall blocks, the walls' and sinks' rows, and
// the summary's figures (the scene parts write their own).

namespace grainload::sph {

void SphModel::write_output_rows(double time) const {
    if (output_ == nullptr || !(time > last_row_time_)) {
        return;
    }
    last_row_time_ = time;
    if (!solver_->walls().empty()) {
        output_->open("wall_forces.csv", kWallForcesHeader)
            .append(wall_force_rows(time, solver_->walls()));
    }
    parts_.at_output(time, *output_);
}

void SphModel::append_blocks(io::Frame& frame) const {
    const auto& p = particles();
    const std::span<const PeriodicAxis> periodic =
        solver_ ? std::span<const PeriodicAxis>(solver_->options().periodic)
                : std::span<const PeriodicAxis>();
    for (std::size_t b = 0; b < body_names_.size(); ++b) {
        io::Block block;
        block.name = body_names_[b];
        io::FieldArray velocity{"velocity", 3, {}}, displacement{"displacement", 3, {}};
        io::FieldArray stress{"stress", 6, {}}, pressure{"pressure", 1, {}};
        io::FieldArray von_mises{"von_mises", 1, {}}, plastic{"plastic_strain", 1, {}};
        io::FieldArray density{"density", 1, {}}, body{"body_id", 1, {}};
        io::FieldArray material{"material_id", 1, {}};
        // The state entries the body's material shows (the mu(I) material's inertial number).
        const auto state_fields = (*materials_)[body_material_[b]].frame_state();
        std::vector<io::FieldArray> states;
        for (const auto& field : state_fields) {
            states.push_back({field.name, 1, {}});
        }
        for (std::size_t i = 0; i < p.position.size(); ++i) {
            if (p.body_id[i] != static_cast<int>(b)) {
                continue;
            }
            block.points.push_back(p.position[i]);
            const Vec3 u = nearest_image(p.position[i] - initial_position_[i], periodic);
            velocity.values.insert(velocity.values.end(), p.velocity[i].begin(),
                                   p.velocity[i].end());
            displacement.values.insert(displacement.values.end(), u.begin(), u.end());
            stress.values.insert(stress.values.end(), p.stress[i].begin(), p.stress[i].end());
            pressure.values.push_back(pressure_of(p.stress[i]));
            von_mises.values.push_back(von_mises_of(p.stress[i]));
            plastic.values.push_back(p.plastic_strain[i]);
            density.values.push_back(p.density[i]);
            body.values.push_back(p.body_id[i]);
            material.values.push_back(p.material_id[i]);
            const auto offset = static_cast<std::size_t>(p.state_offset[i]);
            for (std::size_t k = 0; k < states.size(); ++k) {
                states[k].values.push_back(
                    p.state[offset + static_cast<std::size_t>(state_fields[k].index)]);
            }
        }
        block.point_arrays = {velocity, displacement, stress, pressure, von_mises,
                              plastic,  density,      body,   material};
        block.point_arrays.insert(block.point_arrays.end(), states.begin(), states.end());
        frame.blocks.push_back(std::move(block));
    }
    append_wall_blocks(frame);
    // Frames are collected exactly at the output instants: wall loads and probes go with them.
    if (solver_) {
        write_output_rows(frame.time);
    }
}

void SphModel::append_wall_blocks(io::Frame& frame) const {
    if (!solver_ || solver_->walls().empty()) {
        return;
    }
    const auto& p = solver_->particles();
    for (const Wall& wall : solver_->walls()) {
        io::Block block;
        block.name = "wall_" + wall.name;
        io::FieldArray velocity{"velocity", 3, {}}, body{"body_id", 1, {}};
        for (Index k = wall.first; k < wall.first + wall.count; ++k) {
            block.points.push_back(p.position[k]);
            velocity.values.insert(velocity.values.end(), p.velocity[k].begin(),
                                   p.velocity[k].end());
            body.values.push_back(wall.body_id);
        }
        block.point_arrays = {velocity, body};
        frame.blocks.push_back(std::move(block));
    }
}

// The energy stored in the stresses and the dissipation by mechanism (docs/theory/sph.md,
// "Energy account"): what the artificial viscosity takes of the dissipation is what a user reads
// to judge whether the numerics set the flow.
void SphModel::append_dissipation(std::vector<io::ResultFigure>& results) const {
    const EnergyLedger& ledger = solver_->energy_ledger();
    const WallContact& walls = solver_->wall_contact();
    const double damping = ledger.contact_damping_heat() + walls.damping_work();
    const double total =
        ledger.plastic_work() + ledger.viscous_heat() + damping + walls.friction_work();
    results.push_back(
        {"elastic_strain_energy", solver_->elastic_strain_energy(), "J", std::nullopt, ""});
    results.push_back({"plastic_work", ledger.plastic_work(), "J", std::nullopt, ""});
    results.push_back({"viscous_heat", ledger.viscous_heat(), "J", std::nullopt, ""});
    results.push_back({"contact_damping_heat", damping, "J", std::nullopt, ""});
    // JSON writes the share of no dissipation (0 / 0) as null.
    results.push_back({"viscous_share", ledger.viscous_heat() / total, "", std::nullopt,
                       "artificial viscosity's heat / (plastic work + viscous heat + contact "
                       "damping + wall friction)"});
}

void SphModel::append_energy_books(std::vector<io::ResultFigure>& results) const {
    results.push_back({"kinetic_energy", solver_->kinetic_energy(), "J", std::nullopt, ""});
    results.push_back({"internal_energy", solver_->internal_energy(), "J", std::nullopt, ""});
    const EnergyLedger& ledger = solver_->energy_ledger();
    results.push_back({"gravity_work", ledger.gravity_work(), "J", std::nullopt, ""});
    results.push_back({"moving_wall_work", ledger.wall_work(), "J", std::nullopt, ""});
    if (audit_) {
        results.push_back({"removed_energy", ledger.removed_held(), "J", std::nullopt, ""});
        results.push_back(
            {"removed_contact_energy", ledger.removed_contact(), "J", std::nullopt, ""});
    }
    if (!sources_->empty()) {
        results.push_back({"created_energy", ledger.created_held(), "J", std::nullopt, ""});
        results.push_back(
            {"created_contact_energy", ledger.created_contact(), "J", std::nullopt, ""});
    }
    const double contact = solver_->contact_energy();
    results.push_back({"contact_energy", contact, "J", std::nullopt, ""});
    // JSON writes a non-finite figure as null: the statement says which entry made it so.
    const double held = solver_->held_energy();
    const auto unbalanced = ledger.non_finite(held, contact);
    results.push_back({"energy_balance_error", ledger.balance_error(held, contact), "",
                       std::nullopt, unbalanced ? "not finite: " + *unbalanced : ""});
    if (!solver_->options().friction.empty()) {
        results.push_back(
            {"wall_friction_work", solver_->wall_contact().friction_work(), "J", std::nullopt, ""});
    }
}

void SphModel::append_free_flight(double t, std::vector<io::ResultFigure>& results) const {
    // Without interactions every particle is a point mass in uniform gravity: its exact path is
    // x0 + v0 t + g t^2 / 2, the reference for the whole pipeline (case free_fall).
    double max_error = 0.0;
    double mean_z = 0.0;
    double mean_z_exact = 0.0;
    const auto n = particles_.position.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 exact = initial_position_[i] + t * initial_velocity_[i] + 0.5 * t * t * gravity_;
        max_error = std::max(max_error, (particles_.position[i] - exact).norm());
        mean_z += particles_.position[i].z() / static_cast<double>(n);
        mean_z_exact += exact.z() / static_cast<double>(n);
    }
    results.push_back({"centre_height", mean_z, "m", mean_z_exact, "z0 + v0 t + g t^2/2"});
    results.push_back({"max_position_error", max_error, "m", std::nullopt, ""});
}

void SphModel::append_results(double t, std::vector<io::ResultFigure>& results) const {
    results.insert(results.end(), body_sizes_.begin(), body_sizes_.end());
    parts_.append_results(results);
    if (!solver_) {
        append_free_flight(t, results);
        return;
    }
    append_energy_books(results);
    append_dissipation(results);
    if (const FluidityUpdate* fluidity = solver_->fluidity()) {
        // The field's iterations per step (sph/fluidity_field.hpp): how hard it was to solve,
        // and whether the cap stopped a solve short of the tolerance.
        results.push_back(
            {"fluidity_iterations_mean", fluidity->mean_iterations(), "", std::nullopt, ""});
        results.push_back({"fluidity_iterations_max",
                           static_cast<double>(fluidity->most_iterations()), "", std::nullopt, ""});
        results.push_back(
            {"fluidity_residual_max", fluidity->worst_residual(), "", std::nullopt, ""});
    }
    for (const Wall& wall : solver_->walls()) {
        for (int a = 0; a < 3; ++a) {
            const std::string axis(1, static_cast<char>('x' + a));
            results.push_back(
                {"wall_" + wall.name + "_force_" + axis, wall.force[a], "N", std::nullopt, ""});
        }
    }
}

} // namespace grainload::sph
