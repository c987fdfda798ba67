#pragma once
// A coupled shell part as the DEM's grains see it: a mesh wall on its mid-surface that follows
// the shell, the grains' loads sent back to its nodes.

#include "dem/plane_wall.hpp"
#include "fem/shell_analysis.hpp"

#include <Eigen/Core>
#include <array>
#include <iosfwd>
#include <string>
#include <vector>

namespace grainload::coupling {

/// A coupled shell part as the DEM sees it: the triangles of its elements' mid-surface (each
/// quadrangle a-b-c-d as a-b-c and a-c-d) as one dem::PlaneWall whose vertices are the part's
/// nodes, a plate of the part's thickness t about them that grains touch from either side at
/// radius + t/2. Within a coupling window [t0, t1] the nodes move linearly in time from the
/// shell's state at t0 to its state at t1 (kinematics in); a contact's force F on the wall at
/// the barycentric weights lambda_a of its point on a triangle, and its moment (t/2 n) x F about
/// the mid-surface (n the triangle's normal on the grain's side, the shell's director: no
/// moment about the director, which a shell does not resist), go to the triangle's nodes as
///   f_a = lambda_a F,  m_a = lambda_a (t/2 n) x F
/// (forces out): the virtual work of F at y = sum lambda_a x_a + (t/2) n, the transpose of the
/// interpolation that moves the faces (thesis section 5.3, as for the SPH side's ShellWall).
/// The forces are integrated over the DEM's sub-steps by the trapezoidal rule, like velocity
/// Verlet's two half kicks, and their window mean is the shell's load.
class DemShellWall {
  public:
    /// The wall of `elements` of `analysis`' mesh (one thickness) at its current state.
    DemShellWall(const fem::ShellAnalysis& analysis, const std::vector<Index>& elements);

    /// The DEM wall of the part's mid-surface called `name`; when `follows`, its vertices at
    /// the shell's current state, ready to follow it; else a rigid mesh where the shell is now.
    dem::PlaneWall make_wall(const fem::ShellAnalysis& analysis, const std::string& name,
                             bool follows) const;
    /// A new window [t0, t1]: the wall's vertices move from the shell's state at the last
    /// window's end to its current state.
    void begin_window(const fem::ShellAnalysis& analysis, dem::PlaneWall& wall, double t0,
                      double t1) const;
    /// After every DEM sub-step of length dt: adds the impulse of the wall's vertex loads over
    /// it, dt (F(t) + F(t + dt)) / 2, and its work at the vertices' velocities.
    void accumulate(const dem::PlaneWall& wall, double dt);
    /// The window's mean vertex loads mapped to the nodes (6 entries per node), added into
    /// `loads`; clears the impulses. A node's moment loses its component along the node's
    /// director (the mean of its elements' corner directors, initial under linear kinematics,
    /// current under large rotations): a turn
    /// about the director moves no point of the faces, so that component does no work, and a
    /// shell holds it only by its drilling spring (a triangle's normal, where the grains' moment
    /// arm lies, leans off the director by the sheet's slope within an element).
    void add_nodal_loads(const fem::ShellAnalysis& analysis, double window, Eigen::VectorXd& loads);
    /// Work of the grains on this wall since the start (J).
    double work() const { return work_; }
    /// Total impulse received since the start, for the momentum books.
    const Vec3& impulse() const { return impulse_total_; }

    /// The window's state and the wall's vertex interval, for the checkpoint.
    void write_state(std::ostream& out, const dem::PlaneWall& wall) const;
    void read_state(std::istream& in, dem::PlaneWall& wall);

  private:
    /// The nodes' current positions, in the wall's vertex order.
    std::vector<Vec3> positions(const fem::ShellAnalysis& analysis) const;

    std::vector<Index> nodes_; ///< the shell node of each wall vertex
    /// Each element corner of the part: its element, corner and wall vertex.
    std::vector<std::array<Index, 3>> corners_;
    io::SurfaceMesh surface_; ///< the part's triangles and quadrangles over its vertices
    double half_thickness_ = 0.0;
    // Per vertex: the loads at the last sub-step's end and the impulses since the window's start.
    std::vector<Vec3> last_force_, last_moment_;
    std::vector<Vec3> impulse_, moment_impulse_;
    Vec3 impulse_total_ = Vec3::Zero();
    double work_ = 0.0;
};

} // namespace grainload::coupling
