#pragma once
// One feature of a particle scene (a monitor, a watch, a wall map) behind one seam.

#include "io/frame.hpp"
#include "particles/arrival.hpp"
#include "particles/particle_view.hpp"

#include <iosfwd>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace grainload::io {
class OutputStreams;
}

namespace grainload::particles {

/// One feature of a scene that acts around a particle method's step, as Kratos' processes act
/// around a solution step (Dadvand, Rossi & Oñate 2010, Arch. Comput. Methods Eng. 17): it
/// observes the particles it was built on (each part holds what it reads), acts at the defined
/// points of a step below, writes its rows at the output instants, reports its figures and
/// carries its own checkpoint state. The particle method holds a ScenePartList and calls the
/// points in the order documented there; a part overrides only the points it acts at.
class ScenePart {
  public:
    virtual ~ScenePart() = default;
    /// The case table it comes from ("sph.wall_map"): names its checkpoint section and messages.
    virtual std::string_view name() const = 0;
    /// After the step [t, t + dt]: the particles hold the step's positions and forces, before
    /// any particle leaves or enters.
    virtual void after_step(double t, double dt) {
        (void)t;
        (void)dt;
    }
    /// After a step ending at `time`: flag (gone[i] = 1) the particles that leave the scene
    /// through this part and book them; a particle another part flagged already is not this
    /// part's. Returns how many it flagged. May be called more than once after a step (a phase
    /// that ends on the mass that left lets the next phase's gates go at once).
    virtual Index collect_departures(const ParticleView& particles, double time,
                                     std::vector<char>& gone) {
        (void)particles;
        (void)time;
        (void)gone;
        return 0;
    }
    /// After a step [t, t + dt] and its departures: the particles that enter through this part,
    /// appended to `arrivals`, given the particles there now.
    virtual void collect_arrivals(const ParticleView& particles, double t, double dt,
                                  std::vector<Arrival>& arrivals) {
        (void)particles;
        (void)t;
        (void)dt;
        (void)arrivals;
    }
    /// At the end of a step ending at `time`, once particles left and entered.
    virtual void end_step(double time) { (void)time; }
    /// Particles left the scene: `new_index` maps each old index to its new one (-1: gone).
    virtual void after_removal(std::span<const Index> new_index) { (void)new_index; }
    /// At an output instant of a run: its rows to the run's streamed files and directory (a
    /// scene stepped without a run, e.g. by a test, has no output instants).
    virtual void at_output(double time, io::OutputStreams& output) {
        (void)time;
        (void)output;
    }
    /// Its figures for summary.json.
    virtual void append_results(std::vector<io::ResultFigure>& results) const { (void)results; }
    /// Its events since the last call ("settled at t = 2.1 s ..."), one line each, for the log.
    virtual void take_events(std::vector<std::string>& events) { (void)events; }
    /// A diagnosis when the run must stop (the watchdog's), std::nullopt while sound.
    virtual std::optional<std::string> diagnose() const { return std::nullopt; }
    /// Restart state; read_checkpoint restores exactly what write_checkpoint saved, and drops
    /// the events not yet taken (a coupling pass that goes back to a state did not have them).
    virtual void write_checkpoint(std::ostream& out) const { (void)out; }
    virtual void read_checkpoint(std::istream& in) { (void)in; }
};

} // namespace grainload::particles
