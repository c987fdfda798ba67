#pragma once

#include "io/frame.hpp"
#include "io/key_spec.hpp"
#include "io/region.hpp"
#include "sph/particle_set.hpp"

#include <array>
#include <string>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::sph {

/// The keys of each [[sph.sink]] table (docs/user-guide/sph.md, "Sinks").
inline constexpr std::array<io::KeySpec, 7> kSinkKeys{{
    {"name", "string", "", "names the sink in discharge.csv and summary.json"},
    {"type", "`plane` or `box`", "",
     "plane: the particles beyond a plane leave; box: the particles inside a box leave"},
    {"point", "length vector", "required for a plane", "a point of the plane"},
    {"normal", "vector", "required for a plane",
     "points out of the scene: particles on the side it points to leave"},
    {"min", "length vector", "required for a box", "the box's lower corner"},
    {"max", "length vector", "required for a box",
     "the box's upper corner, above min on every axis"},
    {"body", "string", "every body", "only particles of this [[sph.body]] leave through the sink"},
}};

/// The keys of [[sph.wall]] that open an outlet or time a gate (docs/user-guide/sph.md,
/// "Outlets and gates").
inline constexpr std::array<io::KeySpec, 2> kWallOutletKeys{{
    {"remove_at", "time, `settled` or `phase:NAME`", "never",
     "the wall leaves the scene at the end of the first step that reaches this time, that "
     "settles the scene ([sph.settle]), or that begins the phase ([[phase]])"},
    {"history_start", "time or `phase:NAME`", "0 s",
     "the time velocity_history and angular_velocity_history count from; until then the wall "
     "holds their first values"},
}};

/// Particles leaving the scene through regions (io::Region), and the books of what left: the
/// mass per sink, a history at the output instants (discharge.csv) and the summary figures
/// (discharged mass, steady rate, mass audit). In terms of particles and masses only, so a
/// DEM scene can use it as it stands.
class SinkSet {
  public:
    struct Sink {
        std::string name;
        io::Region region;
        int body = -1; ///< -1: every body
        double discharged = 0.0;
    };

    SinkSet() = default;
    /// The [[sph.sink]] tables of `sph`; body names resolve against `body_names`.
    SinkSet(const io::CaseTable& sph, const std::vector<std::string>& body_names, int dimension);
    /// `dimension` 2: masses are per unit thickness (kg/m), as the particles' are.
    SinkSet(std::vector<Sink> sinks, int dimension)
        : sinks_(std::move(sinks)), dimension_(dimension) {}

    bool empty() const { return sinks_.empty(); }
    const std::vector<Sink>& sinks() const { return sinks_; }
    /// Flag (gone[i] = 1) every material particle inside a sink that takes its body, the first
    /// such sink in case order taking it, and book its mass there. Returns how many were flagged.
    Index collect(const ParticleSet& particles, std::vector<char>& gone);
    double discharged() const;

    /// The mass of the material particles when the scene was built, for the mass audit.
    void set_initial_mass(double mass) { initial_mass_ = mass; }
    /// (mass in the scene + mass discharged - initial mass - mass created) / (initial mass +
    /// mass created).
    double audit_error(double scene_mass, double created) const;

    /// Add a row (time, discharged mass per sink) to the history, at an output instant.
    void record(double time);
    /// DIR/discharge.csv, the whole history, written atomically (io::write_file_atomically):
    /// time_s, sink, discharged_mass_kg, rate_kg_per_s (the mean rate since the last row).
    void write_csv(const std::string& directory) const;
    /// Per sink: sink_NAME_discharged_mass, sink_NAME_steady_rate (io::steady_rate over the
    /// history, null when it cannot be fitted), sink_NAME_steady_window_start/_end; then
    /// discharged_mass, initial_mass, created_mass (by sources) and mass_audit_error.
    void append_results(double scene_mass, double created,
                        std::vector<io::ResultFigure>& results) const;

    /// For checkpoints: the masses, the initial mass and the history.
    std::vector<double> state() const;
    void set_state(const std::vector<double>& state);

  private:
    std::vector<Sink> sinks_;
    int dimension_ = 3;
    double initial_mass_ = 0.0;
    std::vector<double> history_times_;
    std::vector<std::vector<double>> history_; ///< per row, the discharged mass per sink
};

} // namespace grainload::sph
