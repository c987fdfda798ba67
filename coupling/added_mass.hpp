#pragma once
// The sand's inertia put on a static shell's coupled nodes as springs (the added mass).

#include "coupling/coupled_part.hpp"
#include "fem/shell_analysis.hpp"

#include <vector>

namespace grainload::coupling {

/// The sand's inertia put on a static shell's coupled nodes (docs/theory/coupling.md, "Added
/// mass"): a Robin condition on the shell's side of the interface, as the added-mass
/// treatment of fluid-structure coupling gives the structure the fluid's inertia (Badia, Nobile
/// & Vergara 2008, "Fluid-structure partitioned procedures based on Robin transmission
/// conditions", J. Comput. Phys. 227; Causin, Gerbeau & Nobile 2005, Comput. Methods Appl.
/// Mech. Engrg. 194, for why the explicit exchange fails without it). A wall that moves by du over
/// a window dt must move the sand behind it, areal mass m_s, which answers with a pressure of order
/// m_s du / dt^2; the staggered exchange sends that answer one window late, and a shell compliant
/// enough (g = m_s C / dt^2 beyond 2 / omega - 1) overshoots window after window. The springs k_i =
/// beta m_s / dt^2 w_i w_i^T / |w_i| (w_i the node's area vector, coupled_area_vectors) between
/// each coupled node and its position at the window's start make the shell feel that answer in the
/// window it moves: the lagged load then meets C / (1 + beta g). They carry nothing once the shell
/// is at rest, so a static equilibrium is the same with or without.
std::vector<fem::ShellAnalysis::NodeSpring>
added_mass_springs(const fem::ShellMesh& mesh, const std::vector<CoupledPart>& parts,
                   double areal_mass, double window, double factor);

} // namespace grainload::coupling
