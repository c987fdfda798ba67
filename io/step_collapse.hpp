#pragma once
// The watch on an explicit solver's stable time step that diagnoses its collapse (exit 3).

#include <optional>
#include <sstream>
#include <string>

namespace grainload::io {

/// Watches an explicit solver's stable time step for a collapse. The CFL step of a scene
/// shrinks with the fastest signal (sound speed plus particle speed) and the stiffest contact;
/// no physical motion of a granular scene makes that a thousand times faster than it has
/// been, but a blow-up does, without producing a NaN for a long time: the steps get ever
/// shorter and the run crawls instead of stopping (the coupled plate at CFL factor 1.0 went
/// from 1.0e-3 s to 2.6e-8 s within one window and took 66 000 sub-steps per millisecond).
/// The watch turns that into a diagnosis the watchdog reports (exit 3).
class StepCollapseWatch {
  public:
    /// A step below this fraction of the largest one seen is a collapse.
    static constexpr double kFactor = 1e-3;

    /// The diagnosis when `step` (s) at time `t` (s) has collapsed; nothing otherwise.
    std::optional<std::string> record(double step, double t) {
        largest_ = step > largest_ ? step : largest_;
        if (!(step > 0.0 && step >= kFactor * largest_)) {
            std::ostringstream out;
            out << "the stable time step fell to " << step << " s at t = " << t
                << " s, below a thousandth of the largest so far (" << largest_
                << " s): the particles move or press far faster than any motion of the scene "
                   "allows, a blow-up (a CFL factor or coupling window too large for the scene; "
                   "docs/validation/stability.md)";
            return out.str();
        }
        return std::nullopt;
    }

  private:
    double largest_ = 0.0;
};

} // namespace grainload::io
