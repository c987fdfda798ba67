#pragma once
// Whether the coupled shell was worth modelling: its extreme deflection and stress in a run.

#include "fem/shell_model.hpp"

#include <string>
#include <vector>

namespace grainload::coupling {

/// The extremes of the coupled shell parts over a run, which say whether the shell was worth
/// modelling: a wall whose largest deflection is far below the particle
/// spacing gives the sand the same boundary as a rigid wall, and one that never comes near its
/// yield stress needs no plasticity.
struct ShellExtremes {
    double deflection = 0.0; ///< largest nodal translation of a coupled part [m]
    double von_mises = 0.0;  ///< largest von Mises stress (faces, mid-surface) of any element [Pa]

    /// Take the shell's state at the end of a window into account: the deflection of one
    /// coupled part's `elements` (once per part).
    void add_deflection(const fem::ShellAnalysis& analysis, const std::vector<Index>& elements);
    /// ... and the stress of every element of the shell (once per window, whatever the parts).
    void add_stress(const fem::ShellAnalysis& analysis);
};

/// The hints of the coupled parts: deflection against the particle spacing (skipped when the
/// shell's supports prescribe a motion, which a rigid wall would follow too) and the stress
/// against the parts' yield stress.
/// `names`: the coupled parts, for the text.
void append_shell_hints(const ShellExtremes& extremes, const fem::ShellModel& fem,
                        const std::string& names, double spacing, std::vector<std::string>& hints);

/// The hints of rigid interfaces (`rigid = true`, named in `rigid`): the sand's load on them is
/// their walls' forces (wall_NAME_force_*), not in the shell's stresses and deflections. When
/// `all_rigid`, the shell carries its own loads only: the frames label its arrays and
/// summary.json reports no shell stress or deflection.
void append_rigid_interface_hints(const std::vector<std::string>& rigid, bool all_rigid,
                                  const fem::ShellModel& fem, std::vector<std::string>& hints);

} // namespace grainload::coupling
