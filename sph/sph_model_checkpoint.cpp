// SphModel's checkpoint: what a restart needs beyond the case (created and removed particles,
// every particle array, the walls' state, the solver's scalars and books, the outlets and the
// scene parts). The rest of SphModel is in sph_model.cpp.
#include "io/binary_stream.hpp"
#include "sph/sph_model.hpp"

#include <stdexcept>
#include <string>

namespace grainload::sph {

void SphModel::write_checkpoint(std::ostream& out) const {
    write_created(out);
    io::write_array(out, origin_);
    const auto& p = particles();
    io::write_array(out, p.position);
    io::write_array(out, p.velocity);
    io::write_array(out, p.acceleration);
    io::write_array(out, p.density);
    io::write_array(out, p.internal_energy);
    io::write_array(out, p.stress);
    io::write_array(out, p.plastic_strain);
    io::write_array(out, p.state);
    io::write_array(out, p.clamped);
    if (solver_) {
        for (const Wall& wall : solver_->walls()) {
            io::write_array(out, std::vector<Vec3>{wall.centre});
            io::write_array(out, wall.normals);
            io::write_array(out, wall.angular_velocities);
            if (wall.driver) {
                wall.driver->write_state(out);
            }
        }
        const std::vector<double> scalars{
            solver_->last_time_step(), solver_->wall_contact().friction_work(),
            solver_->forces_valid() ? 1.0 : 0.0, solver_->wall_contact().damping_work()};
        io::write_array(out, scalars);
        const auto reference = solver_->neighbour_reference();
        io::write_array(out, std::vector<Vec3>(reference.begin(), reference.end()));
        io::write_array(out, solver_->energy_ledger().state());
    }
    parts_.write_checkpoint(out);
}

namespace {

/// Each rigid wall's centre, normals, angular velocities and driver, as write_checkpoint wrote
/// them.
void read_wall_states(std::istream& in, std::vector<Wall>& walls) {
    for (Wall& wall : walls) {
        std::vector<Vec3> centre;
        io::read_array(in, centre);
        if (centre.size() != 1) {
            throw std::runtime_error("checkpoint: wall '" + wall.name + "' has no centre");
        }
        wall.centre = centre.front();
        const auto normals = wall.normals.size();
        io::read_array(in, wall.normals, normals, "wall normals");
        io::read_array(in, wall.angular_velocities);
        if (!wall.angular_velocities.empty() &&
            wall.angular_velocities.size() != static_cast<std::size_t>(wall.count)) {
            throw std::runtime_error("checkpoint: wall '" + wall.name +
                                     "' has angular velocities of another particle count");
        }
        if (wall.driver) {
            wall.driver->read_state(in);
        }
    }
}

/// The solver's scalars (last step, the walls' friction and dashpot work, whether its forces
/// were valid), the neighbour list's reference positions of `n` particles and the energy books.
void read_solver_books(std::istream& in, SphSolver& solver, std::size_t n) {
    std::vector<double> scalars;
    io::read_array(in, scalars);
    if (scalars.size() != 4) {
        throw std::runtime_error("checkpoint: expected 4 solver scalars, found " +
                                 std::to_string(scalars.size()));
    }
    solver.set_last_time_step(scalars[0]);
    solver.wall_contact().set_friction_work(scalars[1]);
    solver.wall_contact().set_damping_work(scalars[3]);
    std::vector<Vec3> reference;
    io::read_array(in, reference);
    if (!reference.empty() && reference.size() != n) {
        throw std::runtime_error("checkpoint: the neighbour list's reference positions do "
                                 "not match the particles");
    }
    solver.restart(reference, scalars[2] != 0.0);
    std::vector<double> ledger;
    io::read_array(in, ledger);
    solver.energy_ledger().set_state(ledger);
}

} // namespace

void SphModel::read_checkpoint(std::istream& in) {
    read_created(in);
    read_removals(in);
    auto& p = solver_ ? solver_->particles() : particles_;
    const auto n = p.position.size();
    io::read_array(in, p.position, n, "particles");
    // Every array must keep the length the case gave it: the solver indexes them by particle.
    const auto state_size = p.state.size();
    io::read_array(in, p.velocity, n, "velocities");
    io::read_array(in, p.acceleration, n, "accelerations");
    io::read_array(in, p.density, n, "densities");
    io::read_array(in, p.internal_energy, n, "internal energies");
    io::read_array(in, p.stress, n, "stresses");
    io::read_array(in, p.plastic_strain, n, "plastic strains");
    io::read_array(in, p.state, state_size, "material state values");
    io::read_array(in, p.clamped, n, "clamp flags");
    if (solver_) {
        read_wall_states(in, solver_->walls());
        read_solver_books(in, *solver_, n);
    }
    parts_.read_checkpoint(in);
}

} // namespace grainload::sph
