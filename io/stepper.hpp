#pragma once
// One physics module as the driver's time loop steps it: stable step, advance, health, restart.

#include "io/types.hpp"

#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace grainload::io {

/// One physics module as the time loop steps it (SPH, shell FEM, a coupled pair). The driver in
/// app/ owns the only time loop: it asks for the stable step, advances, checks health, and
/// writes checkpoints at the same instants for every module. What a module reports (frames,
/// figures, events, logs) is its io::Reporter (io/reporter.hpp), which the same object
/// implements.
class Stepper {
  public:
    virtual ~Stepper() = default;
    virtual std::string_view name() const = 0;
    /// Largest stable step (CFL for explicit SPH; +infinity for an implicit solver).
    virtual double stable_time_step() const = 0;
    /// Advance from t to t + dt.
    virtual void advance(double t, double dt) = 0;
    /// Number of computational points (particles, nodes) for particle-steps per second.
    virtual Index point_count() const = 0;
    /// Steps its own integrator has taken so far when they are not the driver's (a coupled
    /// model's SPH sub-steps of every window and pass): particle-steps per second count those.
    /// 0 by default: the module steps with the driver.
    virtual long long inner_steps() const { return 0; }
    /// std::nullopt when every field is finite and bounded; otherwise a diagnosis naming the
    /// particle/element and quantity ("particle 812 (body sand): velocity is NaN").
    virtual std::optional<std::string> diagnose() const = 0;
    /// Binary restart state; read_checkpoint must restore exactly what write_checkpoint saved.
    virtual void write_checkpoint(std::ostream& out) const = 0;
    virtual void read_checkpoint(std::istream& in) = 0;
};

} // namespace grainload::io
