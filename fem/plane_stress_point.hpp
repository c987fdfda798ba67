#pragma once
// The through-thickness integration points of a shell: any 3D material under plane stress.

#include "materials/material.hpp"

#include <span>
#include <vector>

namespace grainload::fem {

/// Shell strain/stress in the local orthonormal frame of an integration point, in the order
/// (11, 22, 12, 23, 31) with engineering shear strains; 3 is the shell normal.
using ShellVector = Eigen::Matrix<double, 5, 1>;
using ShellMatrix = Eigen::Matrix<double, 5, 5>;

/// The state of one through-thickness integration point: full 3D strain and stress (Voigt6 of
/// io/types.hpp, local frame) and the material's own state variables.
struct MaterialPoint {
    Voigt6 strain = Voigt6::Zero();
    Voigt6 stress = Voigt6::Zero();
    std::vector<double> state;
};

/// Shear correction factor of the transverse shear strains (Bathe, "Finite Element Procedures",
/// 2nd ed., eq. 5.137: k = 5/6 for a homogeneous section).
inline constexpr double kShearCorrection = 5.0 / 6.0;

/// Updates `point` from `committed` to the new total shell strain under the plane-stress
/// condition sigma_33 = 0, for any 3D material: sigma_33 is driven to zero by Newton iterations
/// on the strain increment d(eps_33) with the tangent the material returns (the condensation of
/// Bathe FEP section 6.6.3 applied incrementally, so that an elasto-plastic material keeps its
/// own return map). Transverse shears are elastic, tau = k G gamma. Returns the stress and the
/// condensed consistent tangent in ShellVector order.
ShellVector plane_stress_update(const materials::Material& material, const ShellVector& strain,
                                const MaterialPoint& committed, MaterialPoint& point,
                                ShellMatrix* tangent);

} // namespace grainload::fem
