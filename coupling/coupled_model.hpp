#pragma once
// The SPH-shell coupling as the time loop sees it: the shell master, SPH its slave, per window.

#include "coupling/coupled_part.hpp"
#include "coupling/coupling_monitor.hpp"
#include "coupling/coupling_settings.hpp"
#include "coupling/interface_accelerator.hpp"
#include "coupling/interface_pressure.hpp"
#include "coupling/model_hints.hpp"
#include "coupling/shell_wall.hpp"
#include "fem/shell_model.hpp"
#include "io/reporter.hpp"
#include "io/step_collapse.hpp"
#include "io/stepper.hpp"
#include "sph/sph_model.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace grainload::coupling {

struct WindowLimits;

/// The SPH-shell coupling as the time loop sees it (thesis sections 5.3 and 9.1): the FEM is
/// master, SPH its slave. advance(t, dt) is one window:
///  1. the shell is solved from t to t + dt under the sand's mean load of the previous window
///     (Kratos' DEM-structure order: structure first, one-window lag);
///  2. the walls of the coupled parts follow the shell from its state at t to that at t + dt,
///     linearly in time;
///  3. SPH sub-cycles through the window at its own CFL step (uniform steps, the last landing
///     on t + dt), adding up every wall particle's impulse;
///  4. the impulses divided by dt, mapped to the nodes by the transpose of the wall's
///     interpolation, are the shell's load for the next window.
/// The next window's load is this window's moved towards the produced one by a relaxation
/// factor. With max_iterations > 1 the window is instead repeated from its start with the
/// load it produced, relaxed by Aitken's method, until the load stops changing (a fixed-point
/// iteration on the interface load).
class CoupledModel final : public io::Stepper, public io::Reporter {
  public:
    CoupledModel(std::unique_ptr<sph::SphModel> sph, std::unique_ptr<fem::ShellModel> fem,
                 std::vector<CoupledPart> parts, CouplingSettings settings);

    std::string_view name() const override { return "coupling"; }
    /// The window, cut to max_subcycles SPH steps when it would need more.
    double stable_time_step() const override;
    void advance(double t, double dt) override;
    Index point_count() const override { return sph_->point_count() + fem_->point_count(); }
    long long inner_steps() const override { return monitor_.subcycles(); }
    std::optional<std::string> diagnose() const override;
    void append_blocks(io::Frame& frame) const override;
    void append_results(double t, std::vector<io::ResultFigure>& results) const override;
    /// The SPH side's choices, each coupled part as an elastic shell wall and its material.
    void describe_model(std::vector<io::ModelChoice>& choices) const override;
    /// The SPH side's hints, and the coupled shell's (coupling/model_hints.hpp).
    void append_hints(std::vector<std::string>& hints) const override;
    /// The SPH side's events (a phase ended, the scene settled) and phases.
    std::vector<std::string> take_events() override { return sph_->take_events(); }
    void append_phases(std::vector<io::PhaseRecord>& records) const override {
        sph_->append_phases(records);
    }
    void write_logs() const override;
    void set_output(io::OutputStreams& output) override;
    void write_checkpoint(std::ostream& out) const override;
    void read_checkpoint(std::istream& in) override;

    const sph::SphModel& sph() const { return *sph_; }
    const fem::ShellModel& fem() const { return *fem_; }
    const CouplingMonitor& monitor() const { return monitor_; }
    /// True when some coupled part sends the sand's load to the shell (not every part rigid).
    bool loads_shell() const { return !parts_.empty(); }
    const CouplingSettings& settings() const { return settings_; }
    /// The estimated stable windows of the staggered exchange, reported in summary.json.
    void set_window_limits(const WindowLimits& limits);
    /// How long the static shell with the added mass takes to follow a load change
    /// (window_limits.hpp, added_mass_lag); 0 without it.
    double added_mass_lag() const { return added_mass_lag_; }
    /// What makes this scene's staggered exchange stable, for the watchdog's diagnosis.
    std::string instability_remedy() const;
    /// The estimate summary.json reports as coupling_window_limit: the longest stable window
    /// of a dynamic shell, the shortest of a static one [s].
    double window_limit() const {
        return fem_->dynamic() ? stable_window_max_ : stable_window_min_;
    }
    /// The shell load of the next window (6 per node).
    const Eigen::VectorXd& interface_load() const { return load_; }
    /// The interfaces that are rigid walls where the shell was built (`rigid = true`): the
    /// sand's load on them is the walls' forces, not the shell's.
    void set_rigid_interfaces(std::vector<std::string> names) {
        rigid_interfaces_ = std::move(names);
    }

  private:
    /// SPH sub-steps from t to t + dt, walls accumulating (their time booked in `record`);
    /// returns their number.
    int subcycle(double t, double dt, WindowRecord& record);
    /// The window's mean load of every coupled part, mapped to the nodes.
    Eigen::VectorXd collect_load(double dt);
    void run_window(double t, double dt, const Eigen::VectorXd& applied);
    void iterate_window(double t, double dt);
    /// The shell's extremes after a window, for the hints.
    void track_extremes();

    std::unique_ptr<sph::SphModel> sph_;
    std::unique_ptr<fem::ShellModel> fem_;
    std::vector<CoupledPart> parts_;
    std::vector<std::string> rigid_interfaces_;
    CouplingSettings settings_;
    Eigen::VectorXd load_;
    /// The shell's load at the window's start and end (its integrator's view; see run_window).
    Eigen::VectorXd start_load_;
    Eigen::VectorXd end_load_;
    InterfacePressure pressure_; ///< the load's pressure and traction on the shell, for frames
    CouplingMonitor monitor_;
    /// The SPH step within windows: a collapse ends the window and is the diagnosis.
    io::StepCollapseWatch step_watch_;
    std::optional<std::string> collapse_;
    WindowRecord pending_;
    ShellExtremes extremes_;              ///< over the run, for the hints
    io::OutputStreams* output_ = nullptr; ///< the run's, for coupling.csv
    std::size_t windows_before_restart_ = 0;
    double stable_window_max_ = 0.0; ///< dynamic shell: the staggered window's upper limit
    double stable_window_min_ = 0.0; ///< static shell: its lower limit
    double added_mass_lag_ = 0.0;    ///< static shell with the added mass: added_mass_lag [s]
};

} // namespace grainload::coupling
