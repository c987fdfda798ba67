#pragma once
// The DEM-shell coupling as the time loop sees it: the shell master, the DEM its slave, per
// window.

#include "coupling/coupling_monitor.hpp"
#include "coupling/coupling_settings.hpp"
#include "coupling/dem_shell_wall.hpp"
#include "coupling/interface_pressure.hpp"
#include "coupling/model_hints.hpp"
#include "dem/dem_model.hpp"
#include "fem/shell_model.hpp"
#include "io/reporter.hpp"
#include "io/stepper.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace grainload::coupling {

/// A coupled shell part as the DEM holds it: its wall in the DEM's list and what moves it.
struct DemCoupledPart {
    std::string name;
    std::size_t wall_index = 0; ///< in the DEM model's walls
    DemShellWall wall;
    std::vector<Index> elements;
    ContactSide side = ContactSide::positive; ///< the grains' side, for the contact pressure
};

/// The DEM-shell coupling (thesis section 9.1's staggered scheme, as the SPH-shell coupling
/// runs it, docs/theory/coupling.md): advance(t, dt) is one window:
///  1. the shell is solved from t to t + dt under the grains' mean load of the previous window
///     (a dynamic shell under 2 F - F(start), so that its trapezoidal rule sees the mean F);
///  2. each coupled part's DEM wall follows the shell from its state at t to that at t + dt,
///     linearly in time;
///  3. the DEM sub-cycles through the window in uniform steps no longer than its own stable
///     step, adding up the impulse of every wall vertex's load;
///  4. the window's mean vertex loads, mapped to the nodes, move the next window's load by the
///     relaxation factor; or, with max_iterations > 1, the window is repeated from its start
///     under the load it produced, accelerated (Aitken or IQN-ILS), until that load stops
///     changing.
class DemCoupledModel final : public io::Stepper, public io::Reporter {
  public:
    DemCoupledModel(std::unique_ptr<dem::DemModel> dem, std::unique_ptr<fem::ShellModel> fem,
                    std::vector<DemCoupledPart> parts, std::vector<std::string> rigid,
                    const CouplingSettings& settings);

    std::string_view name() const override { return "coupling"; }
    /// The window, cut to max_subcycles DEM steps when it would need more.
    double stable_time_step() const override;
    void advance(double t, double dt) override;
    Index point_count() const override { return dem_->point_count() + fem_->point_count(); }
    long long inner_steps() const override { return monitor_.subcycles(); }
    std::optional<std::string> diagnose() const override;
    void write_checkpoint(std::ostream& out) const override;
    void read_checkpoint(std::istream& in) override;

    void append_blocks(io::Frame& frame) const override;
    void append_results(double t, std::vector<io::ResultFigure>& results) const override;
    void describe_model(std::vector<io::ModelChoice>& choices) const override;
    void append_hints(std::vector<std::string>& hints) const override;
    std::vector<std::string> take_events() override { return dem_->take_events(); }
    void write_logs() const override;
    void set_output(io::OutputStreams& output) override;

    const dem::DemModel& dem() const { return *dem_; }
    const fem::ShellModel& fem() const { return *fem_; }
    const CouplingMonitor& monitor() const { return monitor_; }
    /// True when some coupled part sends the grains' load to the shell (not every part rigid).
    bool loads_shell() const { return !parts_.empty(); }
    const CouplingSettings& settings() const { return settings_; }
    /// The shell load of the next window (6 per node).
    const Eigen::VectorXd& interface_load() const { return load_; }

  private:
    /// DEM sub-steps from t to t + dt, the walls accumulating; returns their number.
    int subcycle(double t, double dt, WindowRecord& record);
    /// One pass through the window under the load `applied`: the shell solved, the walls moved,
    /// the DEM sub-cycled; `end_load` the shell's load at the window's end. Its books' record.
    WindowRecord run_window(double t, double dt, const Eigen::VectorXd& applied,
                            Eigen::VectorXd& end_load);
    /// The window's mean load of every coupled part, mapped to the nodes.
    Eigen::VectorXd collect_load(double dt);
    /// The window repeated from its start until the load it produces stops changing
    /// (max_iterations > 1); its last pass's record.
    WindowRecord iterate_window(double t, double dt);

    std::unique_ptr<dem::DemModel> dem_;
    std::unique_ptr<fem::ShellModel> fem_;
    std::vector<DemCoupledPart> parts_;
    std::vector<std::string> rigid_;
    CouplingSettings settings_;
    Eigen::VectorXd load_;
    Eigen::VectorXd start_load_; ///< the shell's load at the window's start (its integrator's)
    InterfacePressure pressure_;
    CouplingMonitor monitor_;
    ShellExtremes extremes_;
    std::optional<std::string> problem_; ///< a DEM diagnosis within a window
    /// The scale of the interface energy error: the largest of the grains' energy throughput,
    /// |gravity's work| + kinetic + elastic, at a window's end so far (grains that leave
    /// through a sink take theirs with them) [J].
    double energy_scale_ = 0.0;
    io::OutputStreams* output_ = nullptr;
    std::size_t windows_before_restart_ = 0;
};

} // namespace grainload::coupling
