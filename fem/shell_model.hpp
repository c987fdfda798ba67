#pragma once
// The shell FEM side of a scene as the time loop sees it: static or implicit dynamic steps.

#include "fem/newmark_integrator.hpp"
#include "fem/shell_step_totals.hpp"
#include "io/reporter.hpp"
#include "io/stepper.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace grainload::fem {

/// A displacement or rotation the case asks to report, with its optional reference.
struct ShellMonitor {
    std::string name;
    Index node = -1;
    int dof = 0;
    bool magnitude = false;
    std::optional<double> reference;
    std::string source;
};

/// A support reaction the case asks to report: the total force of the supports on the nodes of
/// a set (reaction_force summed), e.g. the vertical load a silo wall carries at its base.
struct ShellReaction {
    std::string name;
    std::vector<Index> nodes;
};

/// How a scene's shells are analysed, as [fem] states it (fem/shell_model_reader.hpp reads it).
struct ShellModelSettings {
    bool dynamic = false;
    double time_step = 0.0; ///< dynamic: the largest implicit step [s]
    NewtonSettings newton;
    double load_time = 1.0; ///< history 0, the load factor, ramps to 1 at this time [s]
    int increments_per_step = 1;
    /// Dynamic: the integrator's alpha (0: Newmark) and gamma; beta = (gamma + 1/2)^2 / 4.
    double integrator_alpha = 0.0;
    double integrator_gamma = 0.5;
    MassMatrix mass = MassMatrix::lumped;
};

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
/// analysis: implicit Newmark or HHT-alpha steps of at most [fem].time_step. A case's [fem] table
/// and its [[fem.shell]] tables, one per shell part, build it (fem/shell_model_reader.hpp).
class ShellModel final : public io::Stepper, public io::Reporter {
  public:
    /// The model of `analysis` (its loads, supports and time functions in place): its stiffness
    /// stored (linear steps reuse it), history 0 the ramp to `settings.load_time`, and a dynamic
    /// analysis started at rest.
    ShellModel(const ShellModelSettings& settings, std::unique_ptr<ShellAnalysis> analysis,
               std::vector<std::string> part_names, std::vector<ShellMonitor> monitors,
               std::vector<ShellReaction> support_reactions);

    std::string_view name() const override { return "fem"; }
    double stable_time_step() const override;
    void advance(double t, double dt) override;
    Index point_count() const override { return analysis_->mesh().node_count(); }
    std::optional<std::string> diagnose() const override;
    /// One block per shell part, named after it.
    void append_blocks(io::Frame& frame) const override;
    /// The same with extra arrays given on the whole mesh (a value per node or per element,
    /// e.g. the contact pressure the coupling puts on the shell), sliced per part. A non-empty
    /// `label` is put before the names of the shell's own result arrays (displacements,
    /// reactions, stress resultants, von Mises stresses, plastic strain): a coupled shell that
    /// the sand does not load ("without_sand_") must not show them as the sand's effect.
    void append_blocks(io::Frame& frame, const std::vector<io::FieldArray>& node_fields,
                       const std::vector<io::FieldArray>& element_fields,
                       const std::string& label = "") const;
    const std::vector<std::string>& part_names() const { return part_names_; }
    void append_results(double t, std::vector<io::ResultFigure>& results) const override;
    /// DIRECTORY/fem_convergence.csv: one row per Newton iteration of every step.
    void write_logs() const override;
    void set_output(io::OutputStreams& output) override { output_ = &output; }
    void write_checkpoint(std::ostream& out) const override;
    void read_checkpoint(std::istream& in) override;

    /// Advance from t to t + dt under `forces` (6 per node: forces and moments, applied in full,
    /// e.g. the sand's load on the walls) besides the case's own loads; solves even when the
    /// case's loads stay constant, since the forces change.
    void advance_with_forces(double t, double dt, const Eigen::VectorXd& forces);
    /// After read_checkpoint: the forces of the last advance_with_forces before the checkpoint
    /// (the coupling stores them), so that the reactions and the next solve see them again.
    void restore_forces(const Eigen::VectorXd& forces);
    bool dynamic() const { return dynamic_; }
    /// [fem].increments_per_step: load increments of a static step.
    int increments_per_step() const { return increments_per_step_; }
    /// [fem].load_time: when the loads without a time function reach their full value [s].
    double load_time() const { return load_time_; }
    /// Whether the case puts loads on the shell that follow the ramp to load_time (gravity,
    /// pressures, nodal forces without a [[fem.time_function]]).
    bool has_ramped_loads() const { return analysis_->reference_load().squaredNorm() > 0.0; }
    /// Kinetic energy of the shell (dynamic analysis; 0 for a static one).
    double kinetic_energy() const;
    /// u . Fu(u) / 2: the strain energy of a linear elastic shell (for the energy books).
    double strain_energy() const;

    const ShellAnalysis& analysis() const { return *analysis_; }
    /// For the coupling: wall node positions, set_additional_forces(), equilibrate().
    ShellAnalysis& analysis() { return *analysis_; }
    const std::vector<ShellStepLog>& convergence_log() const { return log_; }

  private:
    std::string part_list() const;
    void solve_step(double t, double dt);
    std::string part_of_node(Index node) const;
    void append_node_fields(io::Block& block, const std::vector<Index>& nodes,
                            const std::vector<io::FieldArray>& extra,
                            const std::string& label) const;
    void append_element_fields(io::Block& block, const std::vector<Index>& elements,
                               const std::vector<io::FieldArray>& extra,
                               const std::string& label) const;

    std::vector<std::string> part_names_;
    std::unique_ptr<ShellAnalysis> analysis_;
    std::vector<ShellMonitor> monitors_;
    std::vector<ShellReaction> support_reactions_;
    NewtonSettings settings_;
    double load_time_ = 1.0;
    bool dynamic_ = false;
    double time_step_ = 0.0; ///< dynamic analysis: largest implicit step [s]
    std::unique_ptr<NewmarkIntegrator> newmark_;
    int increments_per_step_ = 1;
    std::vector<ShellStepLog> log_; ///< this process's steps (the convergence CSV's rows)
    ShellStepTotals totals_;        ///< the whole run's, through restarts (summary.json)
    /// Factorisations of the tangent and back-substitutions this process made (summary.json:
    /// what the steps cost). Not in the checkpoint: a restarted process factorises its tangent
    /// anew, and a coupling window repeated from its start (an iterated window's next pass)
    /// restores the state, not the work done.
    double factorisations_ = 0.0;
    double back_substitutions_ = 0.0;
    mutable std::size_t logged_steps_ = 0; ///< steps of log_ already in the convergence CSV
    io::OutputStreams* output_ = nullptr;  ///< the run's, for the convergence CSV
    Eigen::VectorXd reactions_;
    std::optional<std::string> failure_;
};

} // namespace grainload::fem
