#pragma once
// The triaxial cell of a DEM sample as a scene part: servos hold the side walls at the confining
// stress, the platen shears the sample at a constant rate, and the cell reports the test.

#include "dem/plane_wall.hpp"
#include "dem/sphere_set.hpp"
#include "dem/triaxial_reader.hpp"
#include "particles/scene_part.hpp"

#include <array>
#include <vector>

namespace grainload::dem {

/// A drained triaxial compression of a sample of grains in a box of six rigid walls, as a
/// DEM triaxial test runs it (Thornton 2000, Geotechnique 50, "Numerical simulations of
/// deviatoric shear deformation of granular media"; thesis chapter 3.4, where a membrane of
/// particles carries the confining pressure of a 2D sample): the base stays; the four side
/// walls move along their normals so that the grains' normal force on each, over its area (the
/// cell's current extents), is the confining stress sigma_3; the platen does the same until
/// shear_start, then moves towards the base at axial_strain_rate times the height it had then,
/// until shear_end.
///
/// Servo: after each step the wall moves, over the next, by servo_gain (F_target - F) / K,
/// F its contacts' normal springs' force, K their tangent stiffness (a Newton step on the
/// wall's equilibrium, relaxed), at most servo_speed_limit per second; a wall that touches
/// nothing moves towards the grains at that limit (the servo of a DEM code's walls, e.g.
/// Itasca's PFC, with its gain taken from the measured contact stiffness instead of an
/// estimate).
///
/// Reported, as means over each output interval (the stresses of a few hundred grains swing
/// from step to step): the axial stress sigma_1 on the platen and on the base, sigma_3 (the
/// side walls' mean), axial and volumetric strain from the cell at shear_start (compression
/// positive), the mobilised friction angle asin((sigma_1 - sigma_3) / (sigma_1 + sigma_3)) and
/// its peak, and the solid fraction; rows in triaxial.csv at each output instant.
class TriaxialCell final : public particles::ScenePart {
  public:
    /// The cell of `settings` over `walls` (its six from settings.first_wall on; the vector is
    /// not resized while the cell lives) and the grains' `spheres`.
    TriaxialCell(const TriaxialSettings& settings, std::vector<PlaneWall>& walls,
                 const SphereSet& spheres);

    std::string_view name() const override { return "dem.triaxial"; }
    /// Books the step's wall forces, and sets the walls' motion over the next step.
    void after_step(double t, double dt) override;
    void at_output(double time, io::OutputStreams& output) override;
    void append_results(std::vector<io::ResultFigure>& results) const override;
    void take_events(std::vector<std::string>& events) override;
    std::optional<std::string> diagnose() const override;
    void write_checkpoint(std::ostream& out) const override;
    void read_checkpoint(std::istream& in) override;

    /// The cell's state over the last output interval (or, before the first, its last step).
    struct Reading {
        double axial_stress = 0.0; ///< sigma_1 on the platen [Pa]
        double base_stress = 0.0;  ///< on the base [Pa]
        double side_stress = 0.0;  ///< sigma_3, the side walls' mean [Pa]
        double axial_strain = 0.0;
        double volumetric_strain = 0.0;
        double solid_fraction = 0.0;
        /// asin((sigma_1 - sigma_3) / (sigma_1 + sigma_3)) [rad]
        double friction_angle() const;
    };

  private:
    /// The cell's extent along `axis` at the walls' places now.
    double extent(int axis) const;
    /// The area of face k (the extents of the two other axes).
    double area(std::size_t k) const;
    /// The grains' normal stress on face k now [Pa].
    double stress(std::size_t k) const;
    /// The speed along its normal at which face k's servo moves it over the next step `dt`
    /// towards the confining stress.
    double servo_speed(std::size_t k, double dt) const;
    /// The reading of the sums over the interval, or of the step now when it has none.
    Reading read_now() const;
    PlaneWall& wall(std::size_t k) { return walls_[settings_.first_wall + k]; }
    const PlaneWall& wall(std::size_t k) const { return walls_[settings_.first_wall + k]; }

    TriaxialSettings settings_;
    std::vector<PlaneWall>& walls_;
    const SphereSet& spheres_;
    std::array<double, 3> extent_at_shear_{};
    bool sheared_ = false; ///< shear_start reached: the strains count from then
    /// Sums over the output interval of each face's stress times the step, and its time.
    std::array<double, 6> stress_time_{};
    double interval_ = 0.0;
    Reading reading_;
    double peak_angle_ = 0.0;
    double peak_strain_ = 0.0;
    double solid_fraction_at_shear_ = 0.0;
    std::vector<std::string> events_;
};

} // namespace grainload::dem
