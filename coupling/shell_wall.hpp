#pragma once
// A coupled shell part as SPH sees it: wall particles moved by the shell, forces sent back.

#include "fem/shell_analysis.hpp"
#include "sph/wall.hpp"

#include <Eigen/Core>
#include <array>
#include <vector>

namespace grainload::coupling {

/// Which side of a shell part the sand touches, relative to its element normals (the
/// right-hand rule of the node order, as fem::element_normal gives them).
/// `both`: sand on either side, one layer of wall particles on the mid-surface (a two-sided
/// wall, sph::Wall::two_sided).
enum class ContactSide { positive = 1, negative = -1, both = 0 };

/// The sign that turns a part's element normals (or directors) into the normals of its sand
/// side: -1 for the negative side, +1 otherwise (both sides: the orientation only).
inline double normal_sign(ContactSide side) {
    return side == ContactSide::negative ? -1.0 : 1.0;
}

/// How to lay the wall particles of a coupled shell part.
struct ShellWallLayout {
    ContactSide side = ContactSide::positive;
    double spacing = 0.0; ///< wall particle spacing (the bodies' spacing by default)
    int layers = 1;       ///< layers behind the contact face, enough to fill the kernel support
};

/// A coupled shell part as SPH sees it: wall particles on the part's sand side whose motion
/// comes from the shell (kinematics in) and whose forces go back to the shell's nodes (forces
/// out), through one and the same interpolation (thesis section 5.3; the transpose rule of
/// SPHinXsys' shell coupling and of Lindner's consistent data transfer).
///
/// Particle j sits at x_j = sum_a N_a(r, s) (x_a + o_j d_a), N_a the bilinear (triangle:
/// linear) shape functions of its element at its sampled point, x_a the current node
/// positions, d_a the element's current corner directors and o_j its offset along them from
/// the mid-surface: the contact face is at side * t/2 and layer k at side * (t/2 - (k + 1/2)
/// dp), like a plane wall's layers behind its surface. Within a coupling window [t0, t1] the
/// end states of the shell are interpolated linearly in time, so x_j moves at the constant
/// velocity v_j = (x_j(t1) - x_j(t0)) / (t1 - t0) and reaches the shell's state exactly at the
/// window's end. The virtual work F . delta x_j = sum_a N_a (F . delta u_a + o (d_a x F) .
/// delta theta_a) gives the nodal loads of a force F on particle j:
///   f_a = N_a F,  m_a = N_a o (d_a x F)
/// so the work the sand does on the wall particles is the work the shell receives: exactly under
/// linear kinematics (d_a = V_a + theta_a x V_a is linear in the DOFs; d_a in m_a is then the
/// initial V_a), to first order in a window's rotation under large rotations (d_a current).
class ShellWall final : public sph::WallDriver {
  public:
    /// Particles of the part made of `elements` of `analysis`' mesh, at its initial state.
    ShellWall(const fem::ShellAnalysis& analysis, const std::vector<Index>& elements,
              const ShellWallLayout& layout);

    /// The particles the constructor would lay on `elements` of `mesh` at most (the samples
    /// before coincident ones merge), counted without making any.
    static double particle_bound(const fem::ShellMesh& mesh, const std::vector<Index>& elements,
                                 const ShellWallLayout& layout);

    const std::vector<Vec3>& points() const { return points_; }
    const std::vector<Vec3>& normals() const { return normals_; }
    const std::vector<sph::WallSample>& samples() const { return samples_; }

    /// A new window [t0, t1]: its start is the state at the last window's end (the initial
    /// state for the first), its end the shell's current state.
    void begin_window(const fem::ShellAnalysis& analysis, double t0, double t1);
    void move(sph::ParticleSet& particles, sph::Wall& wall, double t, double dt) override;

    /// After every SPH sub-step of length dt: adds the impulse of the forces on the wall's
    /// particles over it, dt (F(t) + F(t + dt)) / 2 (the leapfrog applies each force half a
    /// step on either side of its instant), and the work of that impulse at the particles'
    /// velocities over the step.
    void accumulate(const sph::ParticleSet& particles, const sph::Wall& wall, double dt);
    /// The window's mean force on every particle mapped to the nodes: 6 entries per node
    /// (forces, moments about the mid-surface), added into `loads`; clears the impulses.
    void add_nodal_loads(const fem::ShellAnalysis& analysis, double window, Eigen::VectorXd& loads);
    /// Work of the sand on this wall since the start (J).
    double work() const { return work_; }
    /// Total impulse received since the start, for the momentum monitor.
    const Vec3& impulse() const { return impulse_total_; }

    void write_state(std::ostream& out) const override;
    void read_state(std::istream& in) override;

  private:
    struct Sample {
        Index element = -1;
        std::array<Index, 4> nodes{};
        std::array<double, 4> weights{};
        double offset = 0.0;
    };
    /// Mid-surface point and interpolated director of a sample in the analysis' current state.
    void current_frame(const fem::ShellAnalysis& analysis, const Sample& sample, Vec3& mid,
                       Vec3& director) const;

    ContactSide side_ = ContactSide::positive;
    std::vector<Sample> layout_;
    std::vector<Vec3> points_;
    std::vector<Vec3> normals_;
    std::vector<sph::WallSample> samples_;
    // Window kinematics per particle: mid-surface point and director at its start and end.
    std::vector<Vec3> mid_start_, mid_end_, director_start_, director_end_;
    double window_start_ = 0.0;
    double window_end_ = 0.0;
    // Force accumulation: the force at the last sub-step's end and the impulse since the
    // window's start, per particle.
    std::vector<Vec3> last_force_;
    std::vector<Vec3> impulse_;
    Vec3 impulse_total_ = Vec3::Zero();
    double work_ = 0.0;
};

} // namespace grainload::coupling
