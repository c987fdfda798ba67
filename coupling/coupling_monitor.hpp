#pragma once
// The coupling's books: interface energy error, momentum balance, sub-cycles, solve time.

#include "io/output_streams.hpp"
#include "io/reporter.hpp"
#include "io/types.hpp"

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace grainload::coupling {

/// The resultant force of a nodal load vector of 6 entries per node (3 forces, 3 moments).
Vec3 load_resultant(const Eigen::VectorXd& load);

/// Relative size of a load change, ||next - previous|| / ||next||; zero when both loads vanish.
double relative_change(const Eigen::VectorXd& next, const Eigen::VectorXd& previous);

/// shell_impulse_AXIS, what the shell's nodes received, beside what the sand put into the
/// coupled walls (`wall`, the particle side's own sum) as its reference: momentum crosses the
/// interface unchanged (the staggered exchange lags it by a window's load, an iterated one by
/// its tolerance). `magnitude`: the interface impulse's.
io::ResultFigure shell_impulse_figure(const std::string& axis, double shell, double wall,
                                      double magnitude);

class CouplingMonitor;

/// interface_force_AXIS (the last window's load, `load` its resultant), interface_impulse_AXIS
/// (what the particles put into the coupled walls) and shell_impulse_AXIS (what the shell's nodes
/// received, the former its reference) of axis a (0: x) from `monitor`'s books.
void append_interface_figures(int a, const Vec3& load, const CouplingMonitor& monitor,
                              std::vector<io::ResultFigure>& results);

/// One coupling window as the monitor books it.
struct WindowRecord {
    double time = 0.0;                ///< end of the window [s]
    double length = 0.0;              ///< [s]
    int subcycles = 0;                ///< SPH steps of the (last) pass through the window
    int iterations = 1;               ///< passes through the window
    double load_change = 0.0;         ///< ||F(k+1) - F(k)|| / ||F(k+1)|| of the last pass (0: none)
    double sand_work = 0.0;           ///< work of the sand on the coupled walls in the window [J]
    double shell_work = 0.0;          ///< work of the applied interface load on the shell [J]
    Vec3 wall_impulse = Vec3::Zero(); ///< impulse of the sand on the coupled walls [N s]
    Vec3 shell_impulse = Vec3::Zero(); ///< impulse of the interface load on the shell [N s]
    double sand_seconds = 0.0;         ///< wall time of the SPH or DEM sub-steps (of every pass)
    /// Wall time of the shell solve(s) and of the element stresses the extremes read.
    double fem_seconds = 0.0;
    double map_seconds = 0.0; ///< wall time of interpolation and force mapping (every pass)
};

/// The coupling's books (interface energy error, momentum balance, sub-cycles, FEM solve
/// time per window). The interface energy error is the work the sand did on the wall particles
/// minus the work the shell received from the mapped loads, summed over the windows: zero for
/// an exact transfer. The staggered scheme's lag makes it, for a static shell of compliance C
/// taking load increments d(n), 1/2 sum d(n).C d(n) + 1/omega sum d(n+1).C d(n)
/// (docs/theory/coupling.md, "Monitors"): positive while the load changes smoothly or settles
/// (the interface dissipates what a static shell cannot hold as vibration), negative and
/// growing when the exchange's period-two oscillation grows. The watchdog therefore watches
/// the energy the interface creates, the fall of the error below its largest value.
class CouplingMonitor {
  public:
    void add(const WindowRecord& record);
    const std::vector<WindowRecord>& windows() const { return windows_; }

    double sand_work() const { return sand_work_; }
    double shell_work() const { return shell_work_; }
    double energy_error() const { return sand_work_ - shell_work_; }
    /// |energy_error| / max(largest |sand work| so far, `scale`).
    double relative_energy_error(double scale) const;
    /// The energy the interface created since its error was largest: the shell received that
    /// much more than the sand's work since then [J] (0 while the interface only dissipates).
    double created_energy() const { return largest_error_ - energy_error(); }
    /// created_energy() / max(largest |sand work| so far, `scale`).
    double relative_created_energy(double scale) const;
    const Vec3& wall_impulse() const { return wall_impulse_; }
    const Vec3& shell_impulse() const { return shell_impulse_; }
    long long subcycles() const { return subcycles_; }
    int largest_subcycles() const { return largest_subcycles_; }
    double sand_seconds() const { return sand_seconds_; }
    double fem_seconds() const { return fem_seconds_; }
    double map_seconds() const { return map_seconds_; }

    /// A diagnosis naming the window and the quantity when the relative created energy exceeds
    /// `limit` (scale as in relative_energy_error) and has grown in each of the last
    /// kGrowthWindows windows: an unstable exchange pumps energy window after window, while a
    /// noisy load's creation stops within a few windows. Dissipation (sand landing on a static
    /// plate, the added mass' springs) is no diagnosis. A non-finite error always is. The
    /// caller adds what makes its exchange stable (CoupledModel::instability_remedy).
    std::optional<std::string> check(double limit, double scale) const;
    static constexpr int kGrowthWindows = 10;

    /// Appends the windows not yet written to coupling.csv, streamed into the run's output.
    void write_csv(io::OutputStreams& output) const;

    /// The checkpoint's part: the works, impulses and counts, not the wall-clock seconds
    /// (a restarted run times its own windows).
    std::vector<double> state() const;
    void set_state(const std::vector<double>& state);

  private:
    /// `energy` / max(largest |sand work| so far, `scale`).
    double relative_to_work(double energy, double scale) const;

    std::vector<WindowRecord> windows_;
    double sand_work_ = 0.0;
    double shell_work_ = 0.0;
    double largest_work_ = 0.0;
    double largest_error_ = 0.0;      ///< largest energy_error() so far [J]
    double largest_error_time_ = 0.0; ///< the end of the window that reached it [s]
    int growing_windows_ = 0;
    Vec3 wall_impulse_ = Vec3::Zero();
    Vec3 shell_impulse_ = Vec3::Zero();
    long long subcycles_ = 0;
    int largest_subcycles_ = 0;
    double sand_seconds_ = 0.0;
    double fem_seconds_ = 0.0;
    double map_seconds_ = 0.0;
    mutable std::size_t written_ = 0;
};

} // namespace grainload::coupling
