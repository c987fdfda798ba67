#pragma once
// The [sph.settle] watch: the step whose kinetic energy falls below a fraction of its largest.

#include "io/key_spec.hpp"

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::particles {

/// The keys of [sph.settle] (docs/user-guide/sph.md, "Settling: `[sph.settle]`").
inline constexpr std::array<io::KeySpec, 2> kSettleKeys{{
    {"kinetic_energy_fraction", "number", "",
     "settled: the material's kinetic energy below this fraction of its peak so far"},
    {"after", "time", "0 s", "the watch starts (e.g. when the sources stop)"},
}};

/// A settle phase that ends itself: from `after` on, the first step whose material kinetic
/// energy falls below `fraction` of the largest it has had since t = 0 is the settle time,
/// after which walls with remove_at = "settled" leave. Checkpointed.
class SettleWatch {
  public:
    SettleWatch() = default;
    SettleWatch(double fraction, double after) : fraction_(fraction), after_(after) {}
    explicit SettleWatch(const io::CaseTable& settle);

    /// After a step ending at `time` with kinetic energy `kinetic`: true on the step that
    /// settles.
    bool record(double time, double kinetic);
    bool settled() const { return settle_time_ < std::numeric_limits<double>::infinity(); }
    double settle_time() const { return settle_time_; }
    double peak() const { return peak_; }
    double fraction() const { return fraction_; }
    /// Move the watch's start (a phase's start, known only once the phase before it ended).
    void set_after(double after) { after_ = after; }

    std::vector<double> state() const { return {peak_, settle_time_}; }
    void set_state(const std::vector<double>& state);

  private:
    double fraction_ = 0.0;
    double after_ = 0.0;
    double peak_ = 0.0;
    double settle_time_ = std::numeric_limits<double>::infinity();
};

} // namespace grainload::particles
