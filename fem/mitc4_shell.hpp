#pragma once
// The MITC4 shell element of Dvorkin & Bathe (1984) and its stress resultants.

#include "fem/plane_stress_point.hpp"

#include <array>
#include <vector>

namespace grainload::fem {

using Vector24 = Eigen::Matrix<double, 24, 1>;
using Matrix24 = Eigen::Matrix<double, 24, 24>;

/// How strains follow the nodal motion.
enum class Kinematics {
    /// Small displacements: strains linear in the nodal displacements and rotations.
    linear,
    /// Total Lagrangian (Bathe FEP section 6.5.2; Dvorkin & Bathe 1984): Green-Lagrange strains
    /// of the current geometry against the initial one, work-conjugate 2nd Piola-Kirchhoff
    /// stresses; nodal directors are rotated by the finite incremental rotations.
    total_lagrangian,
};

/// Nodal configuration of one element: positions and unit directors.
struct ShellNodes {
    std::array<Vec3, 4> x;
    std::array<Vec3, 4> director;
};

/// Most Gauss-Legendre points through a shell's thickness (the element's and the case reader's
/// bound on thickness_points).
inline constexpr int kMaxThicknessPoints = 15;

/// Membrane forces, bending moments and surface stresses of an element, averaged over its
/// in-plane integration points, in the local frame of its centre.
struct ShellResultants {
    Eigen::Vector3d membrane = Eigen::Vector3d::Zero(); ///< N11, N22, N12 [N/m]
    Eigen::Vector3d bending = Eigen::Vector3d::Zero();  ///< M11, M22, M12 [N m/m]
    double von_mises_top = 0.0;
    double von_mises_middle = 0.0;
    double von_mises_bottom = 0.0;
    double plastic_strain = 0.0; ///< largest equivalent plastic strain of the element
};

/// The MITC4 shell element of Dvorkin & Bathe (1984): bilinear mid-surface, nodal directors,
/// in-plane covariant strains from the displacement field, transverse shear strains from the
/// assumed (mixed-interpolated) field tied at the edge midpoints, 5 DOF per node plus a small
/// drilling stiffness so that the global system has 6 DOF per node (u_x, u_y, u_z and the
/// rotation-vector components theta_x, theta_y, theta_z).
class Mitc4Shell {
  public:
    /// `thickness_points`: Gauss-Legendre points through the thickness, 2..15 (2 integrate an
    /// elastic section exactly in linear analysis; use >= 5 for plasticity, more for an
    /// accurate fully plastic moment).
    Mitc4Shell(const ShellNodes& initial, double thickness, const materials::Material& material,
               int thickness_points);

    /// Internal force vector and, when `stiffness` is given, the tangent stiffness (material
    /// part plus, for total_lagrangian, the geometric part, plus the drilling spring). With
    /// `drilling` the spring goes there instead of into `stiffness` (tangent = stiffness +
    /// drilling; the internal force is stiffness * dofs for a linear shell). `linear_dofs`:
    /// nodal displacements and rotation vectors (needed for Kinematics::linear only). Updates
    /// the trial state.
    void evaluate(const ShellNodes& current, const Vector24& linear_dofs, Kinematics kinematics,
                  Vector24& force, Matrix24* stiffness, Matrix24* drilling = nullptr);
    /// Linear kinematics: keep every point's strain-displacement derivative, which depends on
    /// the initial geometry only, so that evaluate() and update_stresses() do not form it again
    /// (960 bytes per integration point).
    void keep_strain_operators();
    /// Linear kinematics: the trial state at `linear_dofs` without force or stiffness, by the
    /// same arithmetic as evaluate() (the stresses a stored-stiffness analysis evaluates only
    /// when they are read).
    void update_stresses(const Vector24& linear_dofs);

    /// Accept the trial state of the last evaluate() as converged / forget it.
    void commit() { committed_ = trial_; }
    void revert() { trial_ = committed_; }

    ShellResultants resultants() const;
    /// Converged integration-point states, for checkpoints.
    const std::vector<MaterialPoint>& committed_points() const { return committed_; }
    void restore_points(std::vector<MaterialPoint> points) {
        committed_ = std::move(points);
        trial_ = committed_;
    }
    /// Lumped (row-sum) translational mass and a rotational inertia rho t^3/12 per unit area.
    Vector24 lumped_mass() const;
    /// Consistent mass: the integral of rho h_i h_j over the initial volume (2 x 2 Gauss points,
    /// exact for a parallelogram), translational rho t and rotational rho t^3/12 per unit area
    /// (Bathe FEP eq. 4.25 with the shell kinematics of eq. 5.100; the rotary inertia is
    /// taken isotropic, as in the lumped mass).
    Matrix24 consistent_mass() const;

    /// Fraction of the largest rotational stiffness given to the drilling rotation (tangent
    /// only: the element's internal force has no drilling component, so results do not depend
    /// on it; it only makes the global matrix nonsingular).
    static constexpr double kDrillingFactor = 1e-4;
    /// Corners on a fold line get no drilling spring: there the rotation about this element's
    /// director is a bending rotation of the neighbouring face, which holds it with real
    /// stiffness, and the spring would only make the tangent inexact.
    void set_fold_corners(const std::array<bool, 4>& fold) { fold_corners_ = fold; }

  private:
    using StrainDerivative = Eigen::Matrix<double, 5, 24>;
    struct Basis;
    struct PointFrame {
        ShellMatrix transform; ///< covariant (rr, ss, rs, rt, st) -> local ShellVector
        double weight = 0.0;   ///< Gauss weight times det J
        double z = 0.0;
        Mat3 to_centre; ///< rotation from this point's local frame to the centre frame
    };
    Basis basis(const ShellNodes& nodes, double r, double s, double z) const;
    void covariant_strain(const ShellNodes& current, double r, double s, double z,
                          ShellVector& strain, Eigen::Matrix<double, 5, 24>& derivative,
                          std::array<Basis, 5>& bases) const;
    void add_geometric_stiffness(const ShellNodes& current, const std::array<Basis, 5>& bases,
                                 double r, double s, const ShellVector& weights,
                                 Matrix24& stiffness) const;
    /// The drilling spring of `stiffness` (its rotational blocks scale it).
    Matrix24 drilling_stiffness(const ShellNodes& current, const Matrix24& stiffness) const;
    /// The local strain of point `point` under linear kinematics.
    ShellVector linear_strain(std::size_t point, const StrainDerivative& derivative,
                              const Vector24& linear_dofs) const;

    ShellNodes initial_;
    std::array<bool, 4> fold_corners_{};
    double thickness_;
    const materials::Material* material_;
    std::vector<double> z_points_;
    std::vector<double> z_weights_;
    std::vector<PointFrame> frames_;
    std::vector<StrainDerivative> strain_operators_; ///< kept ones, per point (or none)
    std::vector<MaterialPoint> committed_;
    std::vector<MaterialPoint> trial_;
};

} // namespace grainload::fem
