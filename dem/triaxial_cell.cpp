#include "dem/triaxial_cell.hpp"

#include "io/binary_stream.hpp"
#include "io/output_streams.hpp"
#include "particles/phase_sequence.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace grainload::dem {

namespace {

constexpr std::size_t kBase = 4;
constexpr std::size_t kPlaten = 5;
constexpr int kAxis = 2;

constexpr std::string_view kHeader =
    "time_s,axial_strain,volumetric_strain,axial_stress_Pa,base_stress_Pa,side_stress_Pa,"
    "friction_angle_deg,solid_fraction\n";

double degrees(double radians) {
    return radians * 180.0 / std::numbers::pi;
}

} // namespace

double TriaxialCell::Reading::friction_angle() const {
    const double sum = axial_stress + side_stress;
    return sum > 0.0 ? std::asin(std::clamp((axial_stress - side_stress) / sum, -1.0, 1.0)) : 0.0;
}

TriaxialCell::TriaxialCell(const TriaxialSettings& settings, std::vector<PlaneWall>& walls,
                           const SphereSet& spheres)
    : settings_(settings), walls_(walls), spheres_(spheres) {
    for (int a = 0; a < 3; ++a) {
        extent_at_shear_[static_cast<std::size_t>(a)] = settings_.max[a] - settings_.min[a];
    }
    sheared_ = !(settings_.shear_start > 0.0);
    solid_fraction_at_shear_ = read_now().solid_fraction;
}

double TriaxialCell::extent(int axis) const {
    const auto a = static_cast<std::size_t>(axis);
    const PlaneWall& low = wall(2 * a);
    const PlaneWall& high = wall(2 * a + 1);
    return (high.faces[0].point + high.displacement)[axis] -
           (low.faces[0].point + low.displacement)[axis];
}

double TriaxialCell::area(std::size_t k) const {
    const int axis = static_cast<int>(k / 2);
    return extent((axis + 1) % 3) * extent((axis + 2) % 3);
}

double TriaxialCell::stress(std::size_t k) const {
    return wall(k).normal_force / area(k);
}

double TriaxialCell::servo_speed(std::size_t k, double dt) const {
    const PlaneWall& w = wall(k);
    const double limit = settings_.servo_speed_limit;
    if (!(w.normal_stiffness > 0.0)) {
        return limit;
    }
    // The springs' force: the dashpots answer the wall's own speed, and a servo that chased
    // them would chatter at its speed limit.
    const double error = settings_.confining_stress * area(k) - w.elastic_normal_force;
    return std::clamp(settings_.servo_gain * error / (w.normal_stiffness * dt), -limit, limit);
}

TriaxialCell::Reading TriaxialCell::read_now() const {
    std::array<double, 6> s{};
    for (std::size_t k = 0; k < 6; ++k) {
        s[k] = interval_ > 0.0 ? stress_time_[k] / interval_ : stress(k);
    }
    Reading r;
    r.axial_stress = s[kPlaten];
    r.base_stress = s[kBase];
    r.side_stress = 0.25 * (s[0] + s[1] + s[2] + s[3]);
    const double volume = extent(0) * extent(1) * extent(2);
    r.axial_strain = 1.0 - extent(kAxis) / extent_at_shear_[kAxis];
    r.volumetric_strain =
        1.0 - volume / (extent_at_shear_[0] * extent_at_shear_[1] * extent_at_shear_[2]);
    double solids = 0.0;
    for (const double radius : spheres_.radius) {
        solids += 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
    }
    r.solid_fraction = solids / volume;
    return r;
}

void TriaxialCell::after_step(double t, double dt) {
    const double time = t + dt;
    for (std::size_t k = 0; k < 6; ++k) {
        stress_time_[k] += stress(k) * dt;
    }
    interval_ += dt;
    if (!sheared_ && particles::reaches(time, settings_.shear_start)) {
        sheared_ = true;
        for (int a = 0; a < 3; ++a) {
            extent_at_shear_[static_cast<std::size_t>(a)] = extent(a);
        }
        const Reading now = read_now();
        solid_fraction_at_shear_ = now.solid_fraction;
        std::ostringstream text;
        text << "triaxial: shearing from t = " << time << " s at solid fraction "
             << now.solid_fraction << ", side stress " << now.side_stress << " Pa";
        events_.push_back(text.str());
    }
    for (std::size_t k = 0; k < 6; ++k) {
        PlaneWall& w = wall(k);
        if (!w.controlled) {
            continue;
        }
        double speed = servo_speed(k, dt);
        if (k == kPlaten && sheared_) {
            speed = particles::reaches(time, settings_.shear_end)
                        ? 0.0
                        : settings_.axial_strain_rate * extent_at_shear_[kAxis];
        }
        w.anchor = w.displacement;
        w.anchor_time = time;
        w.velocity = speed * w.faces[0].normal;
    }
}

void TriaxialCell::at_output(double time, io::OutputStreams& output) {
    reading_ = read_now();
    stress_time_.fill(0.0);
    interval_ = 0.0;
    if (sheared_ && reading_.axial_strain > 0.0 && reading_.friction_angle() > peak_angle_) {
        peak_angle_ = reading_.friction_angle();
        peak_strain_ = reading_.axial_strain;
    }
    std::ostringstream row;
    row.precision(17);
    row << time << ',' << reading_.axial_strain << ',' << reading_.volumetric_strain << ','
        << reading_.axial_stress << ',' << reading_.base_stress << ',' << reading_.side_stress
        << ',' << degrees(reading_.friction_angle()) << ',' << reading_.solid_fraction << '\n';
    output.open("triaxial.csv", kHeader).append(row.str());
}

void TriaxialCell::append_results(std::vector<io::ResultFigure>& results) const {
    const Reading& r = reading_;
    results.push_back({"triaxial_axial_stress", r.axial_stress, "Pa", std::nullopt, ""});
    // In quasi-static shear the sample is in equilibrium: the base carries what the platen
    // pushes (no gravity in a cell test; with it, the grains' weight over the base's area).
    results.push_back({"triaxial_base_stress", r.base_stress, "Pa", r.axial_stress,
                       "the platen's axial stress (the sample in equilibrium)"});
    results.push_back({"triaxial_side_stress", r.side_stress, "Pa", settings_.confining_stress,
                       "confining_stress, the servos' target"});
    results.push_back({"triaxial_axial_strain", r.axial_strain, "", std::nullopt, ""});
    results.push_back({"triaxial_volumetric_strain", r.volumetric_strain, "", std::nullopt, ""});
    results.push_back(
        {"triaxial_friction_angle", degrees(r.friction_angle()), "deg", std::nullopt, ""});
    results.push_back(
        {"triaxial_peak_friction_angle", degrees(peak_angle_), "deg", std::nullopt, ""});
    results.push_back({"triaxial_peak_axial_strain", peak_strain_, "", std::nullopt, ""});
    results.push_back({"triaxial_solid_fraction", r.solid_fraction, "", std::nullopt, ""});
    results.push_back(
        {"triaxial_solid_fraction_at_shear_start", solid_fraction_at_shear_, "", std::nullopt, ""});
}

void TriaxialCell::take_events(std::vector<std::string>& events) {
    for (std::string& line : events_) {
        events.push_back(std::move(line));
    }
    events_.clear();
}

std::optional<std::string> TriaxialCell::diagnose() const {
    for (int a = 0; a < 3; ++a) {
        if (!(extent(a) > 0.0)) {
            return "the triaxial cell closed along " + std::string(1, static_cast<char>('x' + a)) +
                   ": its walls passed each other (no grains between them, or a servo_speed_limit "
                   "too fast for the step)";
        }
    }
    return std::nullopt;
}

void TriaxialCell::write_checkpoint(std::ostream& out) const {
    for (std::size_t k = 0; k < 6; ++k) {
        io::write_value(out, wall(k).anchor);
        io::write_value(out, wall(k).anchor_time);
        io::write_value(out, wall(k).velocity);
    }
    io::write_value(out, extent_at_shear_);
    io::write_value(out, sheared_);
    io::write_value(out, stress_time_);
    io::write_value(out, interval_);
    io::write_value(out, reading_);
    io::write_value(out, peak_angle_);
    io::write_value(out, peak_strain_);
    io::write_value(out, solid_fraction_at_shear_);
}

void TriaxialCell::read_checkpoint(std::istream& in) {
    for (std::size_t k = 0; k < 6; ++k) {
        PlaneWall& w = wall(k);
        w.anchor = io::read_value<Vec3>(in);
        w.anchor_time = io::read_value<double>(in);
        w.velocity = io::read_value<Vec3>(in);
        w.move_to(w.anchor_time);
    }
    extent_at_shear_ = io::read_value<std::array<double, 3>>(in);
    sheared_ = io::read_value<bool>(in);
    stress_time_ = io::read_value<std::array<double, 6>>(in);
    interval_ = io::read_value<double>(in);
    reading_ = io::read_value<Reading>(in);
    peak_angle_ = io::read_value<double>(in);
    peak_strain_ = io::read_value<double>(in);
    solid_fraction_at_shear_ = io::read_value<double>(in);
    events_.clear();
}

} // namespace grainload::dem
