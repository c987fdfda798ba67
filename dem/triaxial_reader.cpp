#include "dem/triaxial_reader.hpp"

#include "io/case_table.hpp"
#include "particles/phase_sequence.hpp"

#include <string>

namespace grainload::dem {

namespace dim = io::dimension;

bool TriaxialSettings::consolidates(double t) const {
    return consolidation_friction && !particles::reaches(t, shear_start);
}

std::optional<TriaxialSettings> read_triaxial(const io::CaseTable& dem, int up,
                                              std::vector<PlaneWall>& walls) {
    const std::optional<io::CaseTable> found = dem.optional_table("triaxial");
    if (!found) {
        return std::nullopt;
    }
    const io::CaseTable& table = *found;
    if (up != 2) {
        table.fail("", "the cell's axis is the scene's up axis: expected a 3D case (z up)");
    }
    TriaxialSettings cell;
    cell.min = table.vector("min", dim::kLength);
    cell.max = table.vector("max", dim::kLength);
    if (!(cell.min.array() < cell.max.array()).all()) {
        table.fail("max", "expected max above min on every axis");
    }
    cell.confining_stress = table.positive_quantity("confining_stress", dim::kPressure);
    cell.axial_strain_rate = table.positive_quantity("axial_strain_rate", dim::kFrequency);
    cell.shear_start = table.positive_quantity_or(
        "shear_start", dim::kTime, io::default_value(kDemTriaxialKeys, "shear_start"), true);
    cell.shear_end =
        table.quantity_or("shear_end", dim::kTime, std::numeric_limits<double>::infinity());
    if (!(cell.shear_end > cell.shear_start)) {
        table.fail("shear_end", "expected a time after shear_start");
    }
    cell.servo_gain =
        table.number_or("servo_gain", io::default_value(kDemTriaxialKeys, "servo_gain"));
    if (!(cell.servo_gain > 0.0 && cell.servo_gain <= 1.0)) {
        table.fail("servo_gain", "expected a number in (0, 1]: above 1 a servo overshoots");
    }
    const double height = cell.max[up] - cell.min[up];
    cell.servo_speed_limit = table.positive_quantity_or("servo_speed_limit", dim::kVelocity,
                                                        cell.axial_strain_rate * height);
    if (table.has("consolidation_friction")) {
        cell.consolidation_friction = table.number("consolidation_friction");
        if (!(*cell.consolidation_friction >= 0.0)) {
            table.fail("consolidation_friction", "expected a number >= 0");
        }
    }
    cell.first_wall = walls.size();
    const std::vector<PlaneWall::Face> faces = PlaneWall::box_faces(cell.min, cell.max, up, false);
    for (std::size_t k = 0; k < faces.size(); ++k) {
        for (const PlaneWall& other : walls) {
            if (other.name == kTriaxialWallNames[k]) {
                table.fail("", "the cell's walls are named cell_x_min ... cell_platen: expected "
                               "no [[dem.wall]] named " +
                                   other.name);
            }
        }
        PlaneWall wall;
        wall.name = kTriaxialWallNames[k];
        wall.faces = {faces[k]};
        // The base stays; the side walls and the platen follow the cell's servos.
        wall.controlled = k != 4;
        walls.push_back(std::move(wall));
    }
    return cell;
}

} // namespace grainload::dem
