#pragma once

#include "fem/newmark_integrator.hpp"
#include "fem/shell_case_reader.hpp"
#include "io/stepper.hpp"
#include "materials/material_library.hpp"

#include <memory>
#include <string>
#include <vector>

namespace grainload::fem {

/// Convergence record of one time step: the Newton iterations of its load increments.
struct ShellStepLog {
    double time = 0.0;
    double load_factor = 0.0;
    StepReport report;
};

/// The shell FEM side of a scene, as the app's time loop sees it. The analysis is driven by the
/// time t: loads and prescribed values without a time function follow the load factor
/// min(t / load_time, 1), the others their [[fem.time_function]]. Static analysis: every
/// advance() solves the incremental-iterative equilibrium problem of thesis Table 5.2.2 at
/// t + dt (cut-backs halve the time increment), so "time" only orders the load steps. Dynamic
/// analysis: implicit Newmark or HHT-alpha steps of at most [fem].time_step. Built from the case's
/// [fem] table and its one [[fem.shell]] table.
class ShellModel final : public io::Stepper {
  public:
    static std::unique_ptr<ShellModel> from_case(const io::CaseTable& root,
                                                 const materials::MaterialLibrary& materials);

    std::string_view name() const override { return "fem"; }
    double stable_time_step() const override;
    void advance(double t, double dt) override;
    Index point_count() const override { return analysis_->mesh().node_count(); }
    std::optional<std::string> diagnose() const override;
    void append_blocks(io::Frame& frame) const override;
    void append_results(double t, std::vector<io::ResultFigure>& results) const override;
    /// DIRECTORY/fem_convergence.csv: one row per Newton iteration of every step.
    void write_logs(const std::string& directory) const override;
    void write_checkpoint(std::ostream& out) const override;
    void read_checkpoint(std::istream& in) override;

    const ShellAnalysis& analysis() const { return *analysis_; }
    /// For the coupling: wall node positions, set_additional_forces(), equilibrate().
    ShellAnalysis& analysis() { return *analysis_; }
    const std::vector<ShellStepLog>& convergence_log() const { return log_; }

  private:
    ShellModel() = default;

    std::string shell_name_;
    std::unique_ptr<ShellAnalysis> analysis_;
    std::vector<ShellMonitor> monitors_;
    NewtonSettings settings_;
    double load_time_ = 1.0;
    bool dynamic_ = false;
    double time_step_ = 0.0; ///< dynamic analysis: largest implicit step [s]
    std::unique_ptr<NewmarkIntegrator> newmark_;
    int increments_per_step_ = 1;
    std::vector<ShellStepLog> log_;
    mutable std::size_t logged_steps_ = 0; ///< steps of log_ already in the convergence CSV
    bool restarted_ = false;
    Eigen::VectorXd reactions_;
    std::optional<std::string> failure_;
};

} // namespace grainload::fem
