#pragma once
// The material particles' energy account (held, put in, taken out) that reveals an instability.

#include <optional>
#include <string>
#include <vector>

namespace grainload::sph {

/// The material particles' energy account (wall particles excluded).
///
/// Held: kinetic plus internal energy, where the internal energy books the stress power
/// (elastic and plastic), the viscous heating and the heat of wall friction and of the contact
/// dashpot. Put in: the work of gravity, sum m g . v dt (which also covers a gravity that
/// turns), and the work of moving walls on the particles. The semi-discrete equations balance
/// the two up to what the books leave out: the energy stored in the contact potential (held
/// there, so missing from the particles: a deficit, never a surplus), the kernel gradient
/// correction's and artificial stress's small departures from a conservative form, and
/// leapfrog's O(dt^2) error. A numerical instability creates energy, which shows as a surplus
/// of the same order as all the energy that has passed through the run; that is the check.
/// Taken out: particles that leave the scene (a sink, a removed wall) take their kinetic and
/// internal energy with them, and the contact potential between them and what stays is
/// released; both are booked as removed, so a departure is not a deficit (docs/theory/sph.md,
/// "Sinks"). Brought in: particles a source creates bring their kinetic and internal energy and
/// the contact potential they start with, booked as created (docs/theory/sph.md, "Sources").
class EnergyLedger {
  public:
    /// Starts the account from the particles' energy at t = 0 and the energy stored at t = 0
    /// in their stresses and in the contact potential (sources the run may release).
    void open(double held, double stored_elastic, double contact);
    bool is_open() const { return open_; }
    void add_gravity_work(double work);
    void add_wall_work(double work);
    /// Particles left: `held` their kinetic plus internal energy, `contact` the contact
    /// potential of their pairs with each other and with what stays.
    void add_removed(double held, double contact);
    /// Particles entered: `held` their kinetic plus internal energy, `contact` the contact
    /// potential of their pairs with what was there.
    void add_created(double held, double contact);

    /// The dissipation booked inside the internal energy, by mechanism, over a step (J): the
    /// plastic work (the stress power less the elastic strain energy it stores), the artificial
    /// viscosity's heat and the heat of the dashpot between bodies. The walls' dashpot and
    /// friction keep their own books (WallContact). Reported, not part of the balance.
    void add_dissipation(double plastic, double viscous, double contact_damping) {
        plastic_work_ += plastic;
        viscous_heat_ += viscous;
        contact_damping_heat_ += contact_damping;
    }

    double gravity_work() const { return gravity_work_; }
    double plastic_work() const { return plastic_work_; }
    double viscous_heat() const { return viscous_heat_; }
    double contact_damping_heat() const { return contact_damping_heat_; }
    double wall_work() const { return wall_work_; }
    double removed_held() const { return removed_held_; }
    double removed_contact() const { return removed_contact_; }
    double created_held() const { return created_held_; }
    double created_contact() const { return created_contact_; }
    /// Energy held now, plus what left with removed particles, minus what was held at t = 0,
    /// what created particles brought and what gravity and the walls put in.
    double surplus(double held) const {
        return held + removed_held_ - initial_held_ - created_held_ - gravity_work_ - wall_work_;
    }
    /// (held + contact + removed - everything at t = 0 - work put in) / throughput: what the
    /// books miss, counting the contact potential's energy both now and at t = 0.
    double balance_error(double held, double contact) const;
    /// The scale of the run's energy: the initial kinetic, internal and stored energy, what
    /// created particles brought, plus the largest work gravity and the walls have done so far.
    double throughput() const;
    /// A diagnosis when the surplus exceeds `fraction` of the throughput, or when the books
    /// are not finite (non_finite), which no comparison with a limit would catch.
    std::optional<std::string> check(double held, double fraction) const;
    /// Which entry of the books is not finite, by its summary.json name and what put it there,
    /// with `held` and `contact` the particles' energies now; nullopt when all are finite.
    /// A single non-finite particle energy makes its entry, and energy_balance_error, NaN or
    /// infinite for the rest of the run.
    std::optional<std::string> non_finite(double held, double contact) const;

    /// For checkpoints: a restarted run keeps its account.
    std::vector<double> state() const;
    void set_state(const std::vector<double>& state);

  private:
    bool open_ = false;
    double initial_held_ = 0.0;
    double initial_contact_ = 0.0;
    double initial_scale_ = 0.0;
    double gravity_work_ = 0.0;
    double wall_work_ = 0.0;
    double largest_gravity_work_ = 0.0;
    double largest_wall_work_ = 0.0;
    double removed_held_ = 0.0;
    double removed_contact_ = 0.0;
    double created_held_ = 0.0;
    double created_contact_ = 0.0;
    double plastic_work_ = 0.0;
    double viscous_heat_ = 0.0;
    double contact_damping_heat_ = 0.0;
};

} // namespace grainload::sph
