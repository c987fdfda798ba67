#pragma once
// Sinks: particles leaving through regions, the books of what left, Beverloo's outlet rate.

#include "io/frame.hpp"
#include "io/region.hpp"
#include "particles/particle_view.hpp"
#include "particles/scene_part.hpp"

#include <optional>
#include <string>
#include <vector>

namespace grainload::particles {

/// Beverloo's discharge rate of a flat-bottomed outlet (Beverloo, Leniger & van de Velde 1961,
/// Chem. Eng. Sci. 15; Nedderman 1992): a slot of width B and
/// length L, W = C' rho sqrt(g) (L - k d) (B - k d)^(3/2) with C' = 1.03 (per metre of depth in
/// plane strain: (B - k d)^(3/2)); a circle of diameter D, W = C rho sqrt(g) (D - k d)^(5/2)
/// with C = 0.58. d is the grain size of the material where it declares one (`grain_size`),
/// k = 1.5; without one (a continuum has no grain) k d = 0.
struct Outlet {
    double width = 0.0;  ///< B, or D for a circle [m]
    double length = 0.0; ///< 3D slot's L [m]; 0: a circle (3D) or per metre (plane strain)
    double bulk_density = 0.0;
    double grain_size = 0.0;    ///< d [m]; 0: none declared
    std::string grain_material; ///< the material that declared d, for the statement
    double rate(double gravity, int dimension) const;
    /// Which form rate() used, with its constants: summary.json's source of the reference.
    std::string form(int dimension) const;
};
inline constexpr double kBeverlooSlot = 1.03;
inline constexpr double kBeverlooCircle = 0.58;
/// Beverloo's k for spheres, 1.4-1.5 (Beverloo et al. 1961; Nedderman 1992 gives 1.5), "usually
/// between 1 and 3" for other grains (Darias, Madrid & Pugnaloni, Powders & Grains 2017).
inline constexpr double kBeverlooGrain = 1.5;

/// Particles leaving the scene through regions (io::Region), and the books of what left: the
/// mass per sink, a history at the output instants (discharge.csv) and the summary figures
/// (discharged mass, steady rate against Beverloo's). A scene part in terms of particles and
/// masses only, so a DEM scene can use it as it stands.
class SinkSet final : public ScenePart {
  public:
    struct Sink {
        std::string name;
        io::Region region;
        int body = -1; ///< -1: every body
        double discharged = 0.0;
        std::optional<Outlet> outlet; ///< outlet_width given
    };

    SinkSet() = default;
    /// A body's material and the grain size it declares (none: k d = 0 in Beverloo's law).
    struct BodyGrain {
        std::string material;
        std::optional<double> size;
    };

    /// `dimension` 2: masses are per unit thickness (kg/m), as the particles' are. `gravity` is
    /// the magnitude Beverloo's rate takes, `share` the part of each outlet the model holds (1/2
    /// per symmetry plane through it); particles/particles_case_reader.hpp reads them from a case.
    SinkSet(std::vector<Sink> sinks, int dimension, double gravity = 0.0, double share = 1.0)
        : sinks_(std::move(sinks)), dimension_(dimension), gravity_(gravity), share_(share) {}

    bool empty() const { return sinks_.empty(); }
    const std::vector<Sink>& sinks() const { return sinks_; }
    std::string_view name() const override { return "sink"; }
    /// Flag (gone[i] = 1) every material particle inside a sink that takes its body, the first
    /// such sink in case order taking it, and book its mass there, whatever the time. Returns
    /// how many were flagged.
    Index collect_departures(const ParticleView& particles, double time,
                             std::vector<char>& gone) override;
    double discharged() const;

    /// Add a row (time, discharged mass per sink) to the history, at an output instant; false
    /// (and nothing added) when the history already reaches `time`.
    bool record(double time);
    /// discharge.csv, streamed into the run's output: its header, and the rows of the history's
    /// last instant, one per sink: time_s, sink, discharged_mass_kg, rate_kg_per_s (the mean
    /// rate since the instant before).
    std::string csv_header() const;
    std::string last_rows() const;
    /// At an output instant: the history's row, and its lines appended to discharge.csv.
    void at_output(double time, io::OutputStreams& output) override;
    /// Per sink: sink_NAME_discharged_mass, sink_NAME_steady_rate (io::steady_rate over the
    /// history, null when it cannot be fitted; with an outlet, Beverloo's rate as its
    /// reference), sink_NAME_steady_window_start/_end.
    void append_results(std::vector<io::ResultFigure>& results) const override;

    /// Beverloo's rate of sink s's outlet, the model's share of it (none without outlet_width).
    std::optional<double> outlet_rate(std::size_t s) const;

    /// For checkpoints: the masses and the history.
    std::vector<double> state() const;
    void set_state(const std::vector<double>& state);
    void write_checkpoint(std::ostream& out) const override;
    void read_checkpoint(std::istream& in) override;

  private:
    std::vector<Sink> sinks_;
    int dimension_ = 3;
    double gravity_ = 0.0;
    double share_ = 1.0;
    std::vector<double> history_times_;
    std::vector<std::vector<double>> history_; ///< per row, the discharged mass per sink
};

} // namespace grainload::particles
