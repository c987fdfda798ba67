#pragma once
// [dem.triaxial]: a sample's triaxial cell, its keys declared once, read into typed settings.

#include "dem/plane_wall.hpp"
#include "io/key_spec.hpp"
#include "io/types.hpp"

#include <array>
#include <limits>
#include <optional>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::dem {

/// The keys of [dem.triaxial] (docs/user-guide/dem.md).
inline constexpr std::array<io::KeySpec, 9> kDemTriaxialKeys{{
    {"min", "length vector", "",
     "the sample's lower corner: the cell's six walls start on the box"},
    {"max", "length vector", "", "its upper corner; the axis is the scene's up axis (z)"},
    {"confining_stress", "pressure", "",
     "sigma_3, held by servos on the four side walls (and on the platen before shear_start)"},
    {"axial_strain_rate", "frequency", "",
     "the platen's speed over the sample's height at shear_start, towards the base"},
    {"shear_start", "time", "0 s",
     "when the platen starts to move; before, it is held at confining_stress too (isotropic "
     "consolidation)"},
    {"shear_end", "time", "never", "when the platen stops and holds its place"},
    {"servo_gain", "number in (0, 1]", "0.5",
     "the share of a wall's force error a servo corrects in a step, over its contacts' stiffness",
     0.5},
    {"servo_speed_limit", "velocity", "axial_strain_rate × the height",
     "the fastest a servo wall moves; its speed towards the grains before it touches them"},
    {"consolidation_friction", "number >= 0", "friction",
     "the grains' Coulomb coefficient with each other until shear_start: 0 packs a dense "
     "sample, the contact's friction a loose one"},
}};

/// [dem.triaxial] as read: the cell's box, its stress and strain rate, and its six walls, the
/// planes of the box's faces appended to the scene's walls from `first_wall` on in the order of
/// PlaneWall::box_faces (x min, x max, y min, y max, base, platen).
struct TriaxialSettings {
    Vec3 min = Vec3::Zero();
    Vec3 max = Vec3::Zero();
    double confining_stress = 0.0;
    double axial_strain_rate = 0.0;
    double shear_start = 0.0;
    double shear_end = std::numeric_limits<double>::infinity();
    double servo_gain = 0.0;
    double servo_speed_limit = 0.0;
    /// The grains' friction with each other until shear_start (none: the contact's).
    std::optional<double> consolidation_friction;
    std::size_t first_wall = 0;
    /// Whether a step from `t` consolidates the sample with consolidation_friction: it starts
    /// before shear_start (the step that ends there is the last).
    bool consolidates(double t) const;
};

/// The cell's walls' names, in the order of its faces.
inline constexpr std::array<const char*, 6> kTriaxialWallNames{
    {"cell_x_min", "cell_x_max", "cell_y_min", "cell_y_max", "cell_base", "cell_platen"}};

/// Reads [dem.triaxial] of the [dem] table (none: std::nullopt) and appends its six walls to
/// `walls`; `up` is the scene's up axis, which must be z. Bad input throws io::CaseError
/// naming the key.
std::optional<TriaxialSettings> read_triaxial(const io::CaseTable& dem, int up,
                                              std::vector<PlaneWall>& walls);

} // namespace grainload::dem
