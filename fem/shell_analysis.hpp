#pragma once
// A shell structure: MITC4 elements on a ShellMesh, 6 DOF per node, supports and loads.

#include "fem/mitc4_shell.hpp"
#include "fem/newton_solver.hpp"
#include "fem/shell_directors.hpp"
#include "fem/shell_mesh.hpp"
#include "fem/sparse_solver.hpp"
#include "fem/static_system.hpp"
#include "fem/stored_stiffness.hpp"

#include <Eigen/SparseCore>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace grainload::fem {

/// One shell part of a structure (a [[fem.shell]] table): its elements are those of the mesh
/// with ShellElement::part equal to its index; each part has its own material and through-
/// thickness integration (its thickness is per element, in the mesh).
struct ShellPart {
    std::string name;
    const materials::Material* material = nullptr;
    int thickness_points = 2;
};

/// A shell structure under static loads: MITC4 elements on a ShellMesh, 6 DOF per node
/// (u_x, u_y, u_z, theta_x, theta_y, theta_z; rotations as global rotation vectors), fixed and
/// prescribed DOFs, and a reference load vector scaled by the load factor lambda.
class ShellAnalysis final : public StaticSystem {
  public:
    /// Several parts (silo wall and hopper, a wagon's sheets): one system of equations.
    ShellAnalysis(ShellMesh mesh, std::vector<ShellPart> parts, Kinematics kinematics);
    /// A structure of one part (every element's part 0).
    ShellAnalysis(ShellMesh mesh, const materials::Material& material, Kinematics kinematics,
                  int thickness_points);
    const std::vector<ShellPart>& parts() const { return parts_; }

    const ShellMesh& mesh() const { return mesh_; }
    Kinematics kinematics() const { return kinematics_; }

    /// Load histories: every load and prescribed value belongs to one history h and is scaled by
    /// f_h(lambda). History 0 is f(lambda) = lambda (proportional loading); add_history()
    /// registers another (e.g. a time function when lambda is the time) and use_history()
    /// selects the one that the prescribe/add calls below fill.
    using History = std::function<double(double)>;
    int add_history(History scale);
    void set_history(int index, History scale) {
        histories_.at(static_cast<std::size_t>(index)).scale = std::move(scale);
    }
    void use_history(int index) { active_history_ = index; }
    /// The part whose elements the distributed loads below (area, pressure, follower pressure,
    /// gravity) go to; -1 (the default): every element.
    void use_part(int part) { active_part_ = part; }
    double history_value(int index, double lambda) const {
        return histories_.at(static_cast<std::size_t>(index)).scale(lambda);
    }
    /// True when some history changes between the two load factors.
    bool loads_change(double from, double to) const;
    int history_count() const { return static_cast<int>(histories_.size()); }
    /// True when history `index` scales something: a load, a prescribed value, a rigid
    /// rotation or a follower pressure that is not zero (a history can change while scaling
    /// nothing, and a step then finds the shell in balance).
    bool history_acts(int index) const;

    /// Constrain DOF `dof` (0..5) of `node` to f(lambda) * value.
    void prescribe(Index node, int dof, double value = 0.0);
    void prescribe(const std::vector<Index>& nodes, std::initializer_list<int> dofs,
                   double value = 0.0);
    /// Constrain all six DOFs of `nodes` to the rigid rotation by f(lambda) * angle about the
    /// axis through `point`: exact translations (R - I)(X - point) and the rotation vector.
    void prescribe_rigid_rotation(const std::vector<Index>& nodes, const Vec3& axis,
                                  const Vec3& point, double angle);
    /// Values of all constrained DOFs at load factor `lambda` (zero at free DOFs).
    Eigen::VectorXd prescribed_at(double lambda) const override;
    /// Reference loads (scaled by f(lambda)): a nodal force/moment component; a force per unit
    /// mid-surface area (gravity: rho t g); a pressure along the initial element normal.
    void add_nodal_load(Index node, int dof, double value);
    void add_area_load(const Vec3& force_per_area);
    void add_pressure(double pressure);
    /// A pressure normal to the deformed mid-surface (follower load), positive along the normal
    /// the node order defines. Its load stiffness is not symmetric: the tangent then goes to
    /// UMFPACK.
    void add_follower_pressure(double pressure);
    void add_gravity(const Vec3& acceleration);
    /// Traction (force per unit initial area) as a function of the element and its unit normal.
    using SurfaceTraction = std::function<Vec3(const ShellElement&, const Vec3& normal)>;
    void add_surface_load(const SurfaceTraction& traction);

    /// Linear analysis in one solve at lambda = 1 (Kinematics::linear), or the full Newton
    /// procedure for other kinematics or inelastic materials.
    StepReport solve_linear();
    /// Newton-Raphson from the current load factor to `target` in `increments` equal steps,
    /// halving an increment that does not converge (thesis Table 5.2.2).
    StepReport advance_load(double target, int increments, const NewtonSettings& settings);

    /// Newton-Raphson at the current load factor, e.g. after set_additional_forces().
    StepReport equilibrate(const NewtonSettings& settings);

    double load_factor() const { return load_factor_; }
    void set_load_factor(double lambda) { load_factor_ = lambda; }
    /// All DOF values: translations and (linear kinematics) rotation vectors / (total
    /// Lagrangian) sums of the rotation increments.
    const Eigen::VectorXd& dofs() const override { return dofs_; }
    Vec3 displacement(Index node) const;
    /// Total rotation vector of the node (log of its rotation matrix).
    Vec3 rotation(Index node) const;
    /// Current director of corner `corner` (0..3) of element `element`: its initial director
    /// (fem/shell_directors.hpp; its own face's normal at a fold node) rotated by the node's
    /// rotation (linear kinematics: V + theta x V).
    Vec3 director(Index element, int corner) const;
    /// The initial director of the corner (fem/shell_directors.hpp).
    const Vec3& initial_director(Index element, int corner) const {
        return initial_directors_[static_cast<std::size_t>(element)]
                                 [static_cast<std::size_t>(corner)];
    }
    /// The displacements (all DOFs, zero where constrained) that `load` (all DOFs) would add
    /// with the tangent of the current state: one linear solve, the state left as it is (the
    /// coupling's estimate of the shell's compliance).
    Eigen::VectorXd tangent_response(const Eigen::VectorXd& load);
    /// tangent_response for many loads: the tangent of the current state factorised once (the
    /// coupling's power iteration for the shell's most compliant mode); the returned function
    /// keeps the factor and does not see later changes of the state.
    std::function<Eigen::VectorXd(const Eigen::VectorXd&)> tangent_inverse();
    /// Internal minus applied force at every DOF (the reactions at constrained DOFs).
    Eigen::VectorXd reactions();
    /// The DOFs neither fixed nor prescribed (counted before the equations are numbered too:
    /// `grainload check` sizes a shell alone before any solve).
    Index free_dof_count() const override;
    /// The elements with their stresses at the committed state (evaluated here first when a
    /// stored stiffness left them behind).
    const std::vector<Mitc4Shell>& elements() const;
    /// Lumped mass per DOF (6 per node).
    Eigen::VectorXd lumped_mass() const;
    /// Consistent mass matrix over all DOFs (6 per node).
    SparseSolver::Matrix consistent_mass() const;
    /// Assemble the tangent (free DOFs) and the full internal force vector at the current state;
    /// with `prescribed` (full-size DOF values) also coupling = K * prescribed over all DOFs
    /// (computed only with the tangent, unless the stiffness is stored).
    void assemble(SparseSolver::Matrix* tangent, Eigen::VectorXd& internal,
                  const Eigen::VectorXd* prescribed = nullptr,
                  Eigen::VectorXd* coupling = nullptr) override;
    /// Keep the stiffness of a linear shell (while constant_tangent() holds): assembled once
    /// over all DOFs (fem/stored_stiffness.hpp), it gives assemble() the internal force K u, the
    /// prescribed DOFs' coupling and the tangent without the element loop, and the element
    /// stresses are then evaluated only when read (elements(), write_state()). For analyses
    /// advanced step after step (ShellModel); off by default, where one solve would only hold
    /// one matrix more.
    void store_stiffness() { store_stiffness_ = true; }
    /// True when assemble() works from the stored stiffness.
    bool uses_stored_stiffness() const override { return store_stiffness_ && constant_tangent(); }
    /// Load factor at which assemble() evaluates the follower loads (they depend on the state,
    /// so they are assembled with the internal forces, with their load stiffness).
    void set_assembly_load_factor(double lambda) override { assembly_load_factor_ = lambda; }
    /// True when the tangent never changes: linear kinematics, linear elastic parts and no
    /// follower or moment loads (a factorisation can then be reused from step to step).
    bool constant_tangent() const override;
    /// True when the supports prescribe a motion (a non-zero prescribed DOF or a rigid rotation
    /// of a node set), which a rigid wall in the shell's place would have to follow too.
    bool prescribes_motion() const;
    /// False when the tangent has a non-symmetric part (moment or follower loads).
    bool tangent_symmetric() const override {
        return !has_moment_loads_ && follower_pressures_.empty();
    }
    /// Add a full-size DOF increment to the state (translations add; rotations compose).
    void update_state(const Eigen::VectorXd& increment) override;
    const std::vector<Index>& equation_numbers() override;
    /// The loads of history 0.
    const Eigen::VectorXd& reference_load() const { return histories_.front().load; }
    /// A spring between a node's translations and their committed values (the state at the
    /// increment's start): internal force K (u - u_committed), tangent K. The coupling's added
    /// mass puts the sand's inertia on a static shell this way (coupling/added_mass.hpp); at
    /// rest (u = u_committed) the springs carry nothing, so an equilibrium is not changed.
    struct NodeSpring {
        Index node = 0;
        Mat3 stiffness = Mat3::Zero();
    };
    /// Replaces the springs; a constant set keeps a constant tangent.
    void set_node_springs(std::vector<NodeSpring> springs);
    /// Forces applied in full, not scaled by the load factor (6 per node), e.g. the contact
    /// forces the SPH side returns to the walls (thesis section 5.3); zero by default.
    void set_additional_forces(const Eigen::VectorXd& forces) { additional_forces_ = forces; }
    /// Everything applied at load factor `lambda`: sum_h f_h(lambda) * loads_h + additional.
    Eigen::VectorXd applied_forces(double lambda) const override;
    void commit();
    void revert_to_committed();
    /// Binary restart state (load factor, DOFs, rotations, integration points); read_state
    /// restores exactly what write_state saved for the same model.
    void write_state(std::ostream& out) const;
    void read_state(std::istream& in);

  private:
    Eigen::VectorXd& active_load();
    ShellNodes element_nodes(std::size_t element) const;
    Vector24 element_dofs(const ShellElement& element, const Eigen::VectorXd& dofs) const;
    void build_stored_stiffness();
    void assemble_stored(SparseSolver::Matrix* tangent, Eigen::VectorXd& internal,
                         const Eigen::VectorXd* prescribed, Eigen::VectorXd* coupling);
    /// The committed state's element stresses, when the stored stiffness left them behind.
    void refresh_stresses() const;
    bool increment(double from, double to, const NewtonSettings& settings, StepReport& report);
    void number_equations();
    void add_follower_loads(Eigen::VectorXd& internal,
                            std::vector<Eigen::Triplet<double>>* triplets) const;
    void add_moment_load_stiffness(const Eigen::VectorXd& internal,
                                   std::vector<Eigen::Triplet<double>>& triplets);
    /// The node springs' forces, tangent entries (free DOFs) and, with `prescribed`, their
    /// part of `coupling` (the tangent times the prescribed values).
    void add_node_springs(Eigen::VectorXd& internal, std::vector<Eigen::Triplet<double>>* triplets,
                          const Eigen::VectorXd* prescribed, Eigen::VectorXd* coupling) const;

    ShellMesh mesh_;
    Kinematics kinematics_;
    ElementDirectors initial_directors_; ///< per element corner, rotated by the nodal R
    /// Mutable for refresh_stresses(): the stresses are a cache of the committed DOFs then.
    mutable std::vector<Mitc4Shell> elements_;
    struct LoadHistory {
        History scale;
        Eigen::VectorXd load;
    };
    struct RigidRotation {
        std::vector<Index> nodes;
        Vec3 axis;
        Vec3 point;
        double angle = 0.0;
        int history = 0;
    };
    std::vector<LoadHistory> histories_;
    int active_history_ = 0;
    std::vector<RigidRotation> rigid_rotations_;
    struct FollowerPressure {
        double pressure = 0.0;
        int history = 0;
        int part = -1;
    };
    std::vector<ShellPart> parts_;
    int active_part_ = -1;
    std::vector<FollowerPressure> follower_pressures_;
    std::vector<NodeSpring> node_springs_;
    double assembly_load_factor_ = 0.0;
    std::vector<double> prescribed_;      ///< NaN where free
    std::vector<int> prescribed_history_; ///< history of each prescribed value
    std::vector<Index> equation_;         ///< free equation number per DOF or -1
    Index free_count_ = 0;
    bool numbered_ = false;
    bool has_moment_loads_ = false;
    bool store_stiffness_ = false;
    std::optional<StoredStiffness> stored_;
    /// The elements' committed stresses lag behind the committed DOFs (stored stiffness).
    mutable bool stresses_stale_ = false;
    Eigen::VectorXd additional_forces_;
    Eigen::VectorXd dofs_; ///< translations and (linear kinematics) rotation vectors
    std::vector<Mat3> rotations_;
    Eigen::VectorXd committed_dofs_;
    std::vector<Mat3> committed_rotations_;
    double load_factor_ = 0.0;
    /// Solves the increments; keeps a constant tangent's factorisation for the later ones.
    NewtonSolver newton_;
};

} // namespace grainload::fem
