#pragma once
// The SPH side of a scene: its bodies and walls advanced by SphSolver, as one Stepper.

#include "io/reporter.hpp"
#include "io/scene_settings.hpp"
#include "io/stepper.hpp"
#include "materials/material_library.hpp"
#include "particles/phase_part.hpp"
#include "particles/scene_part_list.hpp"
#include "particles/settle_watch.hpp"
#include "particles/sink.hpp"
#include "sph/body_generator.hpp"
#include "sph/particle_set.hpp"
#include "sph/rigid_wall.hpp"
#include "sph/scene_places.hpp"
#include "sph/source.hpp"
#include "sph/sph_solver.hpp"

#include <fstream>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace grainload::sph {

/// The SPH side of a scene: particles of every [[sph.body]] and [[sph.wall]], advanced
/// explicitly by SphSolver (or, with interactions = false, in free flight under gravity).
/// Built from the case's [sph] tables by its reader (sph/sph_model_reader.hpp), which reads the
/// keys and hands what it read to the private build steps below; the time loop lives in the
/// app's driver.
class SphModel final : public io::Stepper, public io::Reporter {
  public:
    /// A wall built outside the [sph] tables (the coupling's shell walls): its particles,
    /// their normals into the material and origins, the driver that moves them, and the
    /// Coulomb coefficients of the bodies that touch it by body name.
    struct WallDefinition {
        std::string name;
        std::vector<Vec3> points;
        std::vector<Vec3> normals;
        std::vector<Vec3> velocities; ///< initial velocities of its particles (empty: at rest)
        std::vector<WallSample> samples;
        bool two_sided = false;  ///< see Wall::two_sided
        std::vector<int> bodies; ///< see Wall::bodies (empty: all)
        double spacing = 0.0;
        Vec3 centre = Vec3::Zero(); ///< moment reference
        std::shared_ptr<WallDriver> driver;
        struct Friction {
            std::string body;
            double mu_static = 0.0;
            double mu_kinetic = 0.0;
        };
        std::vector<Friction> friction;
    };

    /// Queue a wall built outside the case reader; it follows the [[sph.wall]] walls. Only
    /// between read_sph_bodies and build_sph_scene (sph/sph_model_reader.hpp).
    void add_wall(WallDefinition wall);
    /// The bodies' particle spacing and the kernel's support radius 2h (3h quintic), which the
    /// layers of an added wall must fill. Valid after read_sph_bodies().
    double spacing() const { return spacing_; }
    double support_radius() const;
    /// The artificial viscosity's alpha, beta and the sound speed of its linear term (pinned, or
    /// each material's own), as summary.json's model block and `grainload check` state it;
    /// empty without viscosity. Valid after build_sph_scene() with interactions.
    std::string viscosity_statement() const;
    /// Index of a body by name, -1 when there is none.
    int body_id(const std::string& name) const;
    /// The [[sph.body]] names, indexed by body id.
    const std::vector<std::string>& body_names() const { return body_names_; }
    int dimension() const { return dimension_; }

    std::string_view name() const override { return "sph"; }
    double stable_time_step() const override;
    /// True when the case fixes the step ([sph] time_step); false: the CFL condition sets it.
    bool fixed_time_step() const { return time_step_ > 0.0; }
    void advance(double t, double dt) override;
    Index point_count() const override { return particles().size(); }
    std::optional<std::string> diagnose() const override;
    void append_blocks(io::Frame& frame) const override;
    void append_results(double t, std::vector<io::ResultFigure>& results) const override;
    /// Dimension, formulation, each body material's model, each wall rigid or driven
    /// (sph/model_report.cpp).
    void describe_model(std::vector<io::ModelChoice>& choices) const override;
    /// Generalized-cap materials whose cap was never reached (sph/model_report.cpp).
    void append_hints(std::vector<std::string>& hints) const override;
    std::vector<std::string> take_events() override;
    /// The [[phase]] table's phases: when each began and ended, and why (sph_model_phases.cpp).
    void append_phases(std::vector<io::PhaseRecord>& records) const override;
    const particles::PhaseSequence& phases() const { return phases_->sequence(); }
    void write_checkpoint(std::ostream& out) const override;
    void read_checkpoint(std::istream& in) override;

    /// Particles leave (sinks, remove_at) and enter (sources) only when exchange_particles()
    /// is called, not after every step: a coupled scene calls it once per window, after the
    /// window's last pass, so that every pass of an iterated window restarts from the same
    /// particles.
    void exchange_particles_per_window() { per_window_ = true; }
    /// The removals and arrivals of the interval [t, t + dt] (see above).
    void exchange_particles(double t, double dt);

    const ParticleSet& particles() const { return solver_ ? solver_->particles() : particles_; }
    const SphSolver* solver() const { return solver_.get(); }
    const particles::SinkSet& sinks() const { return *sinks_; }
    const SourceSet& sources() const { return *sources_; }
    /// Index each current particle had when the case built the scene (particles leave through
    /// sinks and removed walls; the rest keep their order).
    const std::vector<Index>& original_index() const { return origin_; }
    /// Where wall_forces.csv, probes.csv, discharge.csv and the wall maps go: the run's output.
    /// Without it (a model stepped by a test) nothing is written.
    void set_output(io::OutputStreams& output) override;

  private:
    friend class SphModelReader;

    /// What the [sph] table states before its bodies.
    struct Settings {
        Vec3 gravity = Vec3::Zero();
        int dimension = 3;
        double time_step = 0.0; ///< fixed by the case; 0 means "from the CFL condition"
        bool interactions = true;
    };
    SphModel(const materials::MaterialLibrary& materials, const Settings& settings)
        : materials_(&materials), gravity_(settings.gravity), time_step_(settings.time_step),
          interactions_(settings.interactions), dimension_(settings.dimension) {}

    // The build steps, in the order SphModelReader calls them.

    /// A body's particles at `points`, of its material's density and initial state; the index
    /// of its first particle.
    Index add_body(std::string name, int material, const std::vector<Vec3>& points,
                   const Vec3& velocity, double spacing);
    /// Keeps, for summary.json, the sizes of a body that the lattice filled to another size
    /// than drawn, and returns the note that says so ("" when it filled the drawn size).
    std::string record_rounding(const std::string& body, const std::vector<RoundedSize>& rounded,
                                double spacing);
    /// The added walls' particles, after the [[sph.wall]] walls in `walls`.
    void append_added_walls(std::vector<Wall>& walls);
    std::vector<FrictionPair> added_wall_friction(const std::vector<Wall>& walls) const;
    /// The solver over the bodies' and walls' particles.
    void make_solver(const SphOptions& options, std::vector<Wall> walls);
    /// [[sph.sink]] (a part unless empty).
    void set_sinks(std::shared_ptr<particles::SinkSet> sinks);
    /// [sph.settle] as a part; the gates that wait for it read it.
    void set_settle(const particles::SettleWatch& watch);
    /// The walls with remove_at as a part; with the sinks, says whether particles may leave.
    void add_gates();
    /// [[sph.source]] (a part unless empty).
    void set_sources(std::shared_ptr<SourceSet> sources);
    /// The particles as built (original_index(), the materials describe_model names) and, with
    /// a sink, remove_at or a source, the mass audit.
    void open_books();
    /// Once walls, sources and sinks are built: refuses bodies and sources inside walls and a
    /// scene whose sinks take everything at once (sph/scene_limits.hpp), and those that start
    /// so close to a wall that its contact potential throws them off (sph/start_gap.hpp);
    /// returns the warnings of a smaller such push, of thin bodies no source fills, of sinks
    /// that hold a body, and of outlets out of reach (sph/outlet_reach.hpp).
    std::vector<std::string> start_warnings(const ScenePlaces& places) const;
    /// The initial positions and velocities, the escape watch, free flight's accelerations.
    void finish_build();

    void compute_accelerations();
    const std::string& body_name(int body_id) const;
    void append_wall_blocks(io::Frame& frame) const;
    void write_output_rows(double time) const;
    /// After a step ending at `time`: the particles in a sink and the walls due to go leave.
    void remove_departed(double time);
    /// Take the flagged particles out of the solver and of every per-particle array here.
    void apply_removal(std::span<const char> gone);
    /// Mass of the material particles now.
    double scene_mass() const;
    /// Replays the checkpoint's removals on the freshly built scene: before the particle arrays.
    void read_removals(std::istream& in);
    /// After a step [t, t + dt] (and its removals): the parts' new particles enter.
    void create_arrivals(double t, double dt);
    /// Append the arrivals' particles to the solver and to every per-particle array here, and
    /// to the creation log; `book_energy` as SphSolver::add_particles.
    void apply_creation(std::span<const particles::Arrival> arrivals, bool book_energy);
    /// Phases (sph_model_phases.cpp): the [[phase]] tables' sequence as a part whose hooks
    /// read the solver's kinetic energy and the sinks' discharged mass and hand the starts to
    /// the walls and sources; `report_settle` when no [sph.settle] reports settle_time.
    void set_phases(particles::PhaseSequence phases, bool report_settle);
    /// Walls' removal times and histories and sources' windows that name a phase get its start.
    void apply_phase_starts(const particles::PhaseSequence& phases);
    /// elastic_strain_energy, plastic_work, viscous_heat, contact_damping_heat and
    /// viscous_share of summary.json.
    void append_dissipation(std::vector<io::ResultFigure>& results) const;
    /// kinetic, internal, contact energy, the works of gravity, moving walls and wall friction,
    /// the energy removed and created, and the balance's error.
    void append_energy_books(std::vector<io::ResultFigure>& results) const;
    /// Free flight: the particles' centre height against the exact parabola, and the largest
    /// distance of any particle from its own.
    void append_free_flight(double t, std::vector<io::ResultFigure>& results) const;
    /// The creation log, so a restart can rebuild the created particles before the removals.
    void write_created(std::ostream& out) const;
    void read_created(std::istream& in);

    const materials::MaterialLibrary* materials_;
    ParticleSet particles_;
    std::vector<std::string> body_names_;
    std::vector<Vec3> initial_position_;
    std::vector<Vec3> initial_velocity_;
    Vec3 gravity_ = Vec3::Zero();
    double time_step_ = 0.0; ///< fixed by the case; 0 means "from the CFL condition"
    bool interactions_ = true;
    double spacing_ = 0.0;
    /// [sph]'s solver settings, read once with the bodies (they need the bodies' spacing).
    SphOptions options_;
    int dimension_ = 3;
    std::vector<WallDefinition> added_walls_;
    std::unique_ptr<SphSolver> solver_;
    io::OutputStreams* output_ = nullptr;
    /// Written at each output instant, i.e. when the driver collects a frame.
    mutable double last_row_time_ = -1.0;
    /// The scene's monitors ([[sph.probe]], [[sph.wall_map]], [sph.heap], the escape watch) as
    /// parts, in the order the case builds them. Mutable because they write their rows at the
    /// output instants, which the driver reaches through the const append_blocks.
    mutable particles::ScenePartList parts_;
    /// [[sph.sink]], shared with parts_ when there is one (empty: none).
    std::shared_ptr<particles::SinkSet> sinks_ = std::make_shared<particles::SinkSet>();
    bool removals_ = false; ///< a sink or a wall with remove_at: particles may leave
    std::vector<Index> origin_;
    /// [[sph.source]]: particles entering the scene (empty: none), shared with parts_.
    std::shared_ptr<SourceSet> sources_ = std::make_shared<SourceSet>();
    /// Every particle a part created, in order: position, velocity, mass, body and material
    /// (kCreationEntry numbers each), so a checkpoint can replay the creations on the freshly
    /// built scene.
    std::vector<double> created_log_;
    /// The number of particles the case built: created particles' original_index() follows.
    Index built_count_ = 0;
    /// The material of each body, for sources.
    std::vector<int> body_material_;
    /// Per body, the thin-body warning of its shape ("" when none), said by start_warnings.
    std::vector<std::string> thin_warnings_;
    /// Per body and axis where its lattice changed its drawn size: the filled size against the
    /// drawn one, for summary.json (body_NAME_size_AXIS).
    std::vector<io::ResultFigure> body_sizes_;
    /// [sph.settle] (null: none), shared with parts_: the gates that wait for it read it.
    std::shared_ptr<const particles::SettlePart> settle_;
    /// [[phase]]: the run's phases, read before the walls and sources that may name them, and
    /// a part of parts_ once built when there are any (empty: none).
    std::shared_ptr<particles::PhasePart> phases_ = std::make_shared<particles::PhasePart>(
        particles::PhaseSequence{}, particles::PhasePart::Hooks{}, false);
    bool per_window_ = false; ///< exchange_particles_per_window() was called
    bool audit_ = false;      ///< a sink, remove_at or a source: the mass audit and energy books
    /// The materials of the particles as the case built them, for describe_model (particles,
    /// and with them a material, may leave through a sink).
    std::vector<int> built_materials_;
};

} // namespace grainload::sph
