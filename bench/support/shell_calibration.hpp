#pragma once
// What a shell's factorisations and solves cost on this machine.

namespace grainload::bench {

/// What a shell's steps cost on this machine, in CPU seconds of this process
/// (app/resources/calibration.hpp, the shell_* figures; app/resources/shell_cost.hpp says what each
/// is paid for).
struct ShellCosts {
    double factorisation_seconds = 0.0; ///< one factorisation of the plate's tangent
    double factorisation_dofs = 0.0;    ///< its free DOFs
    double per_dof_solved_step = 0.0;
    double per_dof_settled_step = 0.0;
    double per_element_assembly = 0.0;
    double per_dof_back_substitution = 0.0;
    double factorisations = 0.0; ///< the ShellModel's own counts over its windows
    double back_substitutions = 0.0;
};

/// A simply supported square steel plate of `n` x `n` MITC4 elements under gravity: its
/// tangent assembled, factorised and back-substituted once each through ShellAnalysis and
/// SparseSolver, then the plate as a ShellModel built from a case file (as `grainload run`
/// builds it) advanced window by window as the coupling advances it: windows whose load changes
/// (a new nodal force each) and windows whose load stays, each followed by the element
/// stresses the coupling reads.
ShellCosts measure_shell_costs(int n);

/// measure_shell_costs `rounds` times, each cost the least of them (other processes only add
/// to a CPU time).
ShellCosts least_shell_costs(int n, int rounds);

} // namespace grainload::bench
