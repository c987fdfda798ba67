#pragma once
// A slot silo's wall loads and fill measured against Janssen's profile.

#include "support/csv_rows.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vtkDataSet.h>

namespace grainload::testing {

/// The last row of wall_forces.csv per wall: (F_x, F_y), per metre of slot.
inline std::map<std::string, std::pair<double, double>> final_wall_forces(const std::string& out) {
    std::map<std::string, std::pair<double, double>> forces;
    for (const WallForceRow& row : wall_force_rows(out)) {
        forces[row.wall] = {row.force[0], row.force[1]};
    }
    return forces;
}

/// The fill of a plane-strain slot silo read from its particles (docs/validation/silo.md,
/// "Setup"): every particle carries `particle_mass` (kg/m), the sand's width is its particles'
/// extent plus one spacing and its surface half a spacing above the highest centre.
struct SlotFill {
    double mass = 0.0;              ///< kg/m
    double width = 0.0;             ///< D, m
    double surface = 0.0;           ///< m above the origin
    double weight_per_height = 0.0; ///< gamma D = M g / H, N/m per m
};

inline SlotFill measure_slot_fill(vtkDataSet* sand, double spacing, double particle_mass,
                                  double gravity) {
    double x_min = 1e9, x_max = -1e9, y_min = 1e9, y_max = -1e9;
    for (vtkIdType i = 0; i < sand->GetNumberOfPoints(); ++i) {
        const double* x = sand->GetPoint(i);
        x_min = std::min(x_min, x[0]);
        x_max = std::max(x_max, x[0]);
        y_min = std::min(y_min, x[1]);
        y_max = std::max(y_max, x[1]);
    }
    SlotFill fill;
    fill.mass = particle_mass * static_cast<double>(sand->GetNumberOfPoints());
    fill.width = x_max - x_min + spacing;
    fill.surface = y_max + 0.5 * spacing;
    fill.weight_per_height = fill.mass * gravity / (fill.surface - (y_min - 0.5 * spacing));
    return fill;
}

/// Janssen's p_h for a slot (Janssen 1895, EN 1991-4 Eq. 5.1-5.6; plane strain, A/U = D/2)
/// averaged over the depths [a, b] below the surface: gamma D/(2 mu) (1 - exp(-z/z0)),
/// z0 = D/(2 K mu), with gamma D = the weight per metre of height.
inline double janssen_band(const SlotFill& fill, double k, double mu, double a, double b) {
    const double z0 = fill.width / (2.0 * k * mu);
    const double integral = (b - a) - z0 * (std::exp(-a / z0) - std::exp(-b / z0));
    return fill.weight_per_height / (2.0 * mu) * integral / (b - a);
}

} // namespace grainload::testing
