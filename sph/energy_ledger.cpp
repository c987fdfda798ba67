#include "sph/energy_ledger.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace grainload::sph {

void EnergyLedger::open(double held, double stored_elastic, double contact) {
    open_ = true;
    initial_held_ = held;
    initial_contact_ = contact;
    initial_scale_ = std::abs(held) + std::abs(stored_elastic) + std::abs(contact);
    gravity_work_ = 0.0;
    wall_work_ = 0.0;
    largest_gravity_work_ = 0.0;
    largest_wall_work_ = 0.0;
    removed_held_ = 0.0;
    removed_contact_ = 0.0;
    created_held_ = 0.0;
    created_contact_ = 0.0;
}

void EnergyLedger::add_gravity_work(double work) {
    gravity_work_ += work;
    largest_gravity_work_ = std::max(largest_gravity_work_, std::abs(gravity_work_));
}

void EnergyLedger::add_wall_work(double work) {
    wall_work_ += work;
    largest_wall_work_ = std::max(largest_wall_work_, std::abs(wall_work_));
}

void EnergyLedger::add_removed(double held, double contact) {
    removed_held_ += held;
    removed_contact_ += contact;
}

void EnergyLedger::add_created(double held, double contact) {
    created_held_ += held;
    created_contact_ += contact;
}

double EnergyLedger::balance_error(double held, double contact) const {
    const double scale = throughput();
    return scale > 0.0 ? (surplus(held) + removed_contact_ + contact - initial_contact_ -
                          created_contact_) /
                             scale
                       : 0.0;
}

double EnergyLedger::throughput() const {
    return initial_scale_ + std::abs(created_held_) + std::abs(created_contact_) +
           largest_gravity_work_ + largest_wall_work_;
}

std::optional<std::string> EnergyLedger::non_finite(double held, double contact) const {
    struct Entry {
        double value;
        const char* name;
        const char* cause;
    };
    const Entry entries[] = {
        {held, "kinetic_energy + internal_energy",
         "a particle in the scene has a non-finite velocity or internal energy"},
        {contact, "contact_energy", "a pair in the contact potential has a non-finite energy"},
        {removed_held_, "removed_energy",
         "a particle that left the scene (a sink, a removed wall) took a non-finite kinetic or "
         "internal energy with it"},
        {removed_contact_, "removed_contact_energy",
         "a pair that a removal released had a non-finite contact potential"},
        {created_held_, "created_energy", "a particle a source created has a non-finite velocity"},
        {created_contact_, "created_contact_energy",
         "a pair a source created has a non-finite contact potential"},
        {gravity_work_, "gravity_work", "a particle's velocity was not finite"},
        {wall_work_, "moving_wall_work", "a wall particle's velocity or load was not finite"},
        {initial_scale_, "the energy at t = 0", "a particle started with a non-finite energy"},
    };
    for (const Entry& entry : entries) {
        if (!std::isfinite(entry.value)) {
            std::ostringstream out;
            out << entry.name << " is " << entry.value << " J: " << entry.cause;
            return out.str();
        }
    }
    return std::nullopt;
}

std::optional<std::string> EnergyLedger::check(double held, double fraction) const {
    if (!open_) {
        return std::nullopt;
    }
    // A NaN surplus fails every comparison with the limit: without this the watchdog would
    // stay silent for the rest of the run.
    if (const auto bad = non_finite(held, 0.0)) {
        return "the energy books are not finite (" + *bad + "): the run is numerically unstable";
    }
    const double excess = surplus(held);
    const double scale = throughput();
    if (!(excess > fraction * scale)) {
        return std::nullopt;
    }
    std::ostringstream out;
    out << "the particles hold " << excess << " J more energy than they started with plus what "
        << "gravity (" << gravity_work_ << " J) and the walls (" << wall_work_
        << " J) put in, more than " << fraction
        << " times all the energy that passed through the run, " << scale
        << " J: energy is being created, the run is numerically unstable (try a smaller "
        << "cfl_safety, more artificial viscosity, or a softer contact stiffness)";
    return out.str();
}

std::vector<double> EnergyLedger::state() const {
    return {open_ ? 1.0 : 0.0, initial_held_,         initial_contact_,     initial_scale_,
            gravity_work_,     largest_gravity_work_, wall_work_,           largest_wall_work_,
            removed_held_,     removed_contact_,      created_held_,        created_contact_,
            plastic_work_,     viscous_heat_,         contact_damping_heat_};
}

void EnergyLedger::set_state(const std::vector<double>& state) {
    if (state.size() != 15) {
        throw std::runtime_error("checkpoint: expected 15 energy-ledger entries, found " +
                                 std::to_string(state.size()));
    }
    open_ = state[0] != 0.0;
    initial_held_ = state[1];
    initial_contact_ = state[2];
    initial_scale_ = state[3];
    gravity_work_ = state[4];
    largest_gravity_work_ = state[5];
    wall_work_ = state[6];
    largest_wall_work_ = state[7];
    removed_held_ = state[8];
    removed_contact_ = state[9];
    created_held_ = state[10];
    created_contact_ = state[11];
    plastic_work_ = state[12];
    viscous_heat_ = state[13];
    contact_damping_heat_ = state[14];
}

} // namespace grainload::sph
