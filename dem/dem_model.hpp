#pragma once
// The DEM as the driver steps it: spheres, their contacts and plane walls, velocity Verlet.

#include "dem/contact_pass.hpp"
#include "dem/dem_case_reader.hpp"
#include "dem/grain_set.hpp"
#include "dem/grain_source.hpp"
#include "dem/sphere_set.hpp"
#include "io/reporter.hpp"
#include "io/scene_settings.hpp"
#include "io/stepper.hpp"
#include "particles/neighbour_list.hpp"
#include "particles/phase_part.hpp"
#include "particles/scene_part_list.hpp"

#include <memory>
#include <string>
#include <vector>

namespace grainload::materials {
class MaterialLibrary;
}

namespace grainload::dem {

/// The energy books of the grains: kinetic (translation and rotation), the contacts' springs,
/// and the potential of gravity measured from the start.
struct DemEnergy {
    double translational = 0.0;
    double rotational = 0.0;
    double elastic = 0.0;
    double gravity = 0.0; ///< -sum m g.(x - x0)
    double total() const { return translational + rotational + elastic + gravity; }
};

/// How a move over a step weights the accelerations at its two ends: x(t + dt) = x + dt v +
/// dt^2 (position[0] a(t) + position[1] a(t + dt)), v(t + dt) = v + dt (velocity[0] a(t) +
/// velocity[1] a(t + dt)); a grain's angular momentum moves with its torque as v with m a.
struct MotionWeights {
    double position[2];
    double velocity[2];
};

/// A DEM scene: the grains of the [[dem.body]] tables (spheres, or clumps of spheres), the
/// contact law of [dem.contact], the walls of [[dem.wall]]. Integrates translation and
/// rotation by velocity Verlet (Verlet 1967; Allen & Tildesley 1987): half a kick with the
/// forces of the last evaluation, a drift, the forces at the new positions (their
/// velocity-dependent parts with the half-step velocities), the second half kick. A sphere's
/// inertia is isotropic, so its angular velocity follows the torque with no gyroscopic term; a
/// clump's angular momentum L takes the kicks and omega = R I^-1 R^T L follows from its
/// principal moments as it is turned (Euler's equations in full). The orientation turns by
/// omega dt as a quaternion. With [dem] integrator = "predictor_corrector" the step is the
/// predictor-corrector of Lazarevic, Dvornik & Fresl (dem/predictor_corrector.cpp). After
/// each step the walls due leave and the grains in a sink are removed (the scene parts of
/// particles/: sinks and the mass audit).
class DemModel final : public io::Stepper, public io::Reporter {
  public:
    DemModel(DemSettings settings, const io::SceneSettings& scene,
             const materials::MaterialLibrary& materials);

    std::string_view name() const override { return "dem"; }
    /// The fixed time_step, else the contact time of the scene's fastest contact over
    /// steps_per_contact.
    double stable_time_step() const override;
    void advance(double t, double dt) override;
    Index point_count() const override { return grains_.size(); }
    /// The grains a run to `end_time` holds at most: those at the start and all its sources
    /// make by then (sinks not counted).
    Index most_grains(double end_time) const;
    /// Spheres times steps over a run of `steps` steps to `end_time` (a clump of n spheres
    /// counts n: the neighbour search and the contact pass go sphere by sphere): a source's
    /// grains counted from their mean arrival.
    double sphere_steps(double steps, double end_time) const;
    /// Force evaluations a step makes at most: 1 (velocity Verlet), 1 + corrector_passes (the
    /// predictor-corrector).
    int evaluations_per_step() const {
        return settings_.integrator == Integrator::predictor_corrector
                   ? 1 + settings_.corrector_passes
                   : 1;
    }
    std::optional<std::string> diagnose() const override;
    void write_checkpoint(std::ostream& out) const override;
    void read_checkpoint(std::istream& in) override;

    void append_blocks(io::Frame& frame) const override;
    void append_results(double t, std::vector<io::ResultFigure>& results) const override;
    void describe_model(std::vector<io::ModelChoice>& choices) const override;
    std::vector<std::string> take_events() override;
    /// The [[phase]] tables' phases: when each began and ended, and why.
    void append_phases(std::vector<io::PhaseRecord>& records) const override;
    void set_output(io::OutputStreams& output) override { output_ = &output; }

    const GrainSet& grains() const { return grains_; }
    const SphereSet& spheres() const { return spheres_; }
    const std::vector<PlaneWall>& walls() const { return walls_; }
    /// Wall w, for the coupling to set the interval its vertices follow.
    PlaneWall& wall(std::size_t w) { return walls_[w]; }
    const ContactBooks& books() const { return books_; }
    DemEnergy energy() const;
    /// The shortest contact time of the scene at a normal impact speed `speed`: of the
    /// smallest grains of each pair of bodies, and of each body's smallest on a wall.
    double shortest_contact_time(double speed) const;

  private:
    /// The pair properties (E*, G*, friction, rolling friction) of every two bodies' grains
    /// and of each body's grains on a wall.
    void combine_body_pairs();
    /// The contact time of the smallest (or largest) grains of bodies a and b, or of a's on a
    /// wall (b empty).
    double pair_contact_time(std::size_t a, std::optional<std::size_t> b, bool largest,
                             double speed) const;
    /// Whether the linear law's dashpot stops some pair before it rebounds.
    bool over_damped() const;
    /// The forces at the grains' positions and the walls' places at `time`.
    void evaluate(double time);
    /// A step [t, t + dt] by velocity Verlet (the class's comment).
    void verlet_step(double t, double dt);
    /// A step [t, t + dt] by the predictor-corrector of Lazarevic, Dvornik & Fresl (dem/
    /// predictor_corrector.cpp).
    void predictor_corrector_step(double t, double dt);
    /// The grains moved from the step's start `start_` over `dt` with the accelerations
    /// a(t) (of start_) and a(t + dt) (of the grains' forces and torques now) weighted as
    /// `weights` gives them.
    void move_from_start(double dt, const MotionWeights& weights);
    /// After the step [t, t + dt]: the phases whose end it reached end, walls whose remove_at
    /// it reached leave, grains that reached a sink leave (a phase that ends on the mass they
    /// took ends then, and its walls follow at once), and the sources' grains enter.
    void exchange(double t, double dt);
    /// The walls due at `time` leave the scene; one removed at a phase's start leaves with the
    /// step that ends the phase before it.
    void remove_walls(double time);
    /// The grains in a sink at `time` leave.
    void remove_departed(double time);
    /// The [[phase]] tables' sequence as a part of parts_ (none: no phases).
    void add_phases();
    /// The [[dem.wall_map]] tables as a part of parts_, reading the contacts' loads on the
    /// mapped walls (none: no maps).
    void add_wall_maps();
    /// [dem.triaxial]'s cell as a part of parts_ (none: no cell).
    void add_triaxial();
    /// The grains' translational and rotational kinetic energy [J].
    double kinetic_energy() const;
    void add_arrivals(const std::vector<particles::Arrival>& arrivals);
    void remove_grains(const std::vector<char>& gone);
    void write_wall_rows(double time) const;
    void write_part_rows(double time) const;

    DemSettings settings_;
    Vec3 gravity_;
    std::vector<std::string> body_names_;
    std::vector<std::string> body_materials_;
    std::vector<GrainElastic> body_elastic_;
    std::vector<PairProperties> body_pairs_; ///< E*, G*, friction of two bodies' grains
    std::vector<PairProperties> body_walls_; ///< and of a body's grains on a wall
    /// body_pairs_ with [dem.triaxial] consolidation_friction, while the cell consolidates.
    std::vector<PairProperties> consolidation_pairs_;
    bool consolidating_ = false; ///< the step under way uses consolidation_pairs_
    std::vector<double> body_density_;
    GrainSet grains_;
    SphereSet spheres_;
    /// The clumps' angular momentum between a step's two half kicks.
    std::vector<Vec3> momentum_;
    /// The predictor-corrector's step start: each grain's state, force and torque at t, the
    /// spheres' springs (every pass's evaluation advances them from these), and the
    /// acceleration at t + dt the last move assumed.
    struct StepStart {
        std::vector<Vec3> position;
        std::vector<Vec3> velocity;
        std::vector<Vec3> momentum; ///< angular, in the scene's frame
        std::vector<Eigen::Quaterniond> orientation;
        std::vector<Vec3> force;
        std::vector<Vec3> torque;
        std::vector<std::vector<Spring>> springs;
        std::vector<Vec3> assumed;
    };
    StepStart start_;
    std::vector<Vec3> start_position_; ///< by grain id, for the potential of gravity
    double start_energy_ = 0.0;        ///< DemEnergy::total() at the start
    std::vector<PlaneWall> walls_;
    particles::NeighbourList neighbours_;
    ContactBooks books_;
    ContactScratch scratch_;
    /// The scene's parts: the sinks, the sources, with either the mass audit, and the phases.
    mutable particles::ScenePartList parts_;
    std::shared_ptr<particles::SinkSet> sinks_;
    std::shared_ptr<GrainSources> sources_;
    /// [[phase]], the last of parts_ when the case has phases (null: none).
    std::shared_ptr<particles::PhasePart> phases_;
    std::vector<std::string> events_;
    double step_ = 0.0; ///< the step the last evaluation's springs advanced by
    io::OutputStreams* output_ = nullptr;
    mutable double last_row_time_ = -1.0;
    mutable double last_part_time_ = -1.0;
};

} // namespace grainload::dem
