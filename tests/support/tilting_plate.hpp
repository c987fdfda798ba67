#pragma once
// A body on the tilting plate read from the run's frames.

#include "support/frame_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <iostream>
#include <numbers>
#include <numeric>
#include <string>
#include <vector>

namespace grainload::testing {

// A body on the turning plate of cases/tilting_plate/ (docs/validation/tilting_plate.md), read
// from the run's frames: block 0 is the body, block 1 the plate hinged at the origin.

struct PlateFrame {
    double angle = 0.0;    ///< plate rotation since frame 0, rad
    double position = 0.0; ///< block centroid along the plate, in the plate's frame, m
};

/// The plate turns rigidly about the hinge at the origin: its angle is that of its particle
/// farthest from the hinge.
inline double plate_angle(const std::string& vtm) {
    const auto plate = read_particle_block(vtm, 1);
    double far[3] = {0.0, 0.0, 0.0};
    for (vtkIdType k = 0; k < plate->GetNumberOfPoints(); ++k) {
        double x[3];
        plate->GetPoint(k, x);
        if (std::hypot(x[0], x[1]) > std::hypot(far[0], far[1])) {
            std::copy(x, x + 3, far);
        }
    }
    return std::atan2(far[1], far[0]);
}

/// The body's particles (block 0) in the plate's frame: s along the plate from the hinge, n
/// normal to it.
struct BodyFrame {
    double angle = 0.0; ///< plate rotation since frame 0, rad
    std::vector<double> s, n;
};

inline BodyFrame read_body(const std::string& vtm, double angle_zero) {
    BodyFrame frame;
    frame.angle = plate_angle(vtm) - angle_zero;
    const double c = std::cos(frame.angle);
    const double sn = std::sin(frame.angle);
    const auto body = read_particle_block(vtm, 0);
    for (vtkIdType k = 0; k < body->GetNumberOfPoints(); ++k) {
        double x[3];
        body->GetPoint(k, x);
        frame.s.push_back(x[0] * c + x[1] * sn);
        frame.n.push_back(-x[0] * sn + x[1] * c);
    }
    return frame;
}

/// The block's position: its centroid projected on the plate.
inline PlateFrame read_plate_frame(const std::string& vtm, double angle_zero) {
    const BodyFrame body = read_body(vtm, angle_zero);
    const double sum = std::accumulate(body.s.begin(), body.s.end(), 0.0);
    return {body.angle, sum / static_cast<double>(body.s.size())};
}

struct Onset {
    double angle = std::nan(""); ///< deg: first frame sliding faster than 1 mm/s
    double held_slip = 0.0;      ///< m: largest slip while more than 1 deg below atan(mu_s)
};

/// The body's slip along the plate read from the frames of the run in `out` of case `name`
/// (every 0.02 s, 0.1 deg near the onset).
inline Onset onset_from_frames(const std::string& out, const std::string& name,
                               double friction_angle) {
    const double angle_zero = plate_angle(frame_path(out, name, 0));
    const double interval = 0.02;
    std::vector<PlateFrame> frames;
    for (int k = 0; std::filesystem::exists(frame_path(out, name, k)); ++k) {
        frames.push_back(read_plate_frame(frame_path(out, name, k), angle_zero));
    }
    EXPECT_GT(frames.size(), 100u);
    Onset onset;
    for (std::size_t k = 1; k < frames.size(); ++k) {
        const double degrees = frames[k].angle * 180.0 / std::numbers::pi;
        const double speed = (frames[k - 1].position - frames[k].position) / interval;
        if (degrees < friction_angle - 1.0) {
            onset.held_slip =
                std::max(onset.held_slip, std::abs(frames[k].position - frames[0].position));
        }
        if (std::isnan(onset.angle) && speed > 1e-3) {
            onset.angle = degrees;
        }
    }
    std::cout << name << ": onset of sliding at " << onset.angle
              << " deg, atan(mu_s) = " << friction_angle << " deg; slip before "
              << friction_angle - 1.0 << " deg: " << onset.held_slip * 1e3 << " mm\n";
    return onset;
}

} // namespace grainload::testing
