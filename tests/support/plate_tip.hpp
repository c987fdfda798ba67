#pragma once
// The oscillating plate's tip and root read from its frames.

#include "support/frame_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>
#include <vtkDataArray.h>
#include <vtkPointData.h>

namespace grainload::testing {

/// One frame of the oscillating plate (cases/oscillating_plate/): its tip and its root.
struct TipFrame {
    double tip = 0.0;         ///< mean y-displacement of the last particle column, m
    double root_motion = 0.0; ///< largest displacement of a clamped (x < 0) particle, m
};

/// The plate's tip is the mean y-displacement of the particles that started within one
/// spacing of its free end at x = `length` (as cases/oscillating_plate/analyse.py).
inline TipFrame read_tip_frame(const std::string& vtm, double length, double spacing) {
    const auto plate = read_particle_block(vtm, 0);
    vtkDataArray* displacement = plate->GetPointData()->GetArray("displacement");
    TipFrame frame;
    int tip_count = 0;
    for (vtkIdType k = 0; k < plate->GetNumberOfPoints(); ++k) {
        double x[3];
        double u[3];
        plate->GetPoint(k, x);
        displacement->GetTuple(k, u);
        const double start_x = x[0] - u[0];
        if (start_x > length - spacing) {
            frame.tip += u[1];
            ++tip_count;
        }
        if (start_x < 0.0) {
            frame.root_motion = std::max(frame.root_motion, std::hypot(u[0], u[1]));
        }
    }
    frame.tip /= tip_count;
    return frame;
}

/// Times at which `series` (one value per frame, `interval` apart) crosses `level` going down.
inline std::vector<double> crossings_down(const std::vector<double>& series, double level,
                                          double interval) {
    std::vector<double> found;
    for (std::size_t k = 1; k < series.size(); ++k) {
        if (series[k - 1] > level && series[k] <= level) {
            const double s = (series[k - 1] - level) / (series[k - 1] - series[k]);
            found.push_back((static_cast<double>(k - 1) + s) * interval);
        }
    }
    return found;
}

/// The tip of every frame a run of the case `name` wrote into `out`, and the largest motion of
/// its clamped root over them.
struct TipHistory {
    std::vector<double> tip; ///< m, one per frame
    double root_motion = 0.0;
};

inline TipHistory read_tip_history(const std::string& out, const std::string& name, double length,
                                   double spacing) {
    TipHistory history;
    for (int k = 0; std::filesystem::exists(frame_path(out, name, k)); ++k) {
        const TipFrame frame = read_tip_frame(frame_path(out, name, k), length, spacing);
        history.tip.push_back(frame.tip);
        history.root_motion = std::max(history.root_motion, frame.root_motion);
    }
    return history;
}

/// Thin-plate theory in cylindrical bending (plane strain) for the plate of the oscillating
/// plate cases (Gray, Monaghan & Swift 2001: L = 0.2 m, H = 0.02 m, E = 2 MPa, nu = 0.3975,
/// rho = 1000 kg/m^3) under g = 1 m/s^2: the first-mode period of the cantilever, 2 pi /
/// sqrt(D k^4 / (rho H)) with k L = 1.8751 (1 + cos kL cosh kL = 0), and the static tip
/// deflection -q L^4 / (8 D), q = rho g H, D = E H^3 / (12 (1 - nu^2)); 0.2540 s and 2.526 mm.
struct ThinPlate {
    static constexpr double length = 0.2;     // m
    static constexpr double thickness = 0.02; // m
    double period = 0.0;                      ///< s
    double static_tip = 0.0;                  ///< m, negative: downwards
};

inline ThinPlate oscillating_plate_reference() {
    constexpr double young = 2.0e6;
    constexpr double poisson = 0.3975;
    constexpr double density = 1000.0;
    constexpr double gravity = 1.0;
    const double h = ThinPlate::thickness;
    const double l = ThinPlate::length;
    const double stiffness = young * std::pow(h, 3) / (12.0 * (1.0 - poisson * poisson));
    const double k = 1.8751040687 / l;
    ThinPlate plate;
    plate.period = 2.0 * std::numbers::pi / std::sqrt(stiffness * std::pow(k, 4) / (density * h));
    plate.static_tip = -density * gravity * h * std::pow(l, 4) / (8.0 * stiffness);
    return plate;
}

} // namespace grainload::testing
