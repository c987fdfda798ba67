#pragma once

#include "support/frame_reader.hpp"

#include <algorithm>
#include <cmath>
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

} // namespace grainload::testing
