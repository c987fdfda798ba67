#pragma once

#include "io/stepper.hpp"
#include "materials/material_library.hpp"
#include "sph/heap_monitor.hpp"
#include "sph/particle_set.hpp"
#include "sph/rigid_wall.hpp"
#include "sph/sph_solver.hpp"

#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::sph {

/// The SPH side of a scene: particles of every [[sph.body]] and [[sph.wall]], advanced
/// explicitly by SphSolver (or, with interactions = false, in free flight under gravity).
/// Built from the case's [sph] tables; the time loop lives in the app's driver.
class SphModel final : public io::Stepper {
  public:
    static std::unique_ptr<SphModel> from_case(const io::CaseTable& root,
                                               const materials::MaterialLibrary& materials);

    std::string_view name() const override { return "sph"; }
    double stable_time_step() const override;
    void advance(double t, double dt) override;
    Index point_count() const override { return particles().size(); }
    std::optional<std::string> diagnose() const override;
    void append_blocks(io::Frame& frame) const override;
    void append_results(double t, std::vector<io::ResultFigure>& results) const override;
    void write_checkpoint(std::ostream& out) const override;
    void read_checkpoint(std::istream& in) override;

    const ParticleSet& particles() const { return solver_ ? solver_->particles() : particles_; }
    const SphSolver* solver() const { return solver_.get(); }
    /// Where wall_forces.csv and probes.csv go: the run's output directory. Defaults to
    /// out/<case name>, the driver's default; a driver run with --out must set it.
    void set_output_directory(const std::string& directory) override;

  private:
    SphModel(const materials::MaterialLibrary& materials) : materials_(&materials) {}
    void add_body(const io::CaseTable& body, int dimension);
    void compute_accelerations();
    void build_solver(const io::CaseTable& sph, const Vec3& gravity, int dimension);
    const std::string& body_name(int body_id) const;
    void append_wall_blocks(io::Frame& frame) const;
    void read_probes(const io::CaseTable& sph);
    void write_output_rows(double time) const;

    const materials::MaterialLibrary* materials_;
    ParticleSet particles_;
    std::vector<std::string> body_names_;
    std::vector<Vec3> initial_position_;
    std::vector<Vec3> initial_velocity_;
    Vec3 gravity_ = Vec3::Zero();
    double time_step_ = 0.0; ///< fixed by the case; 0 means "from the CFL condition"
    bool interactions_ = true;
    double spacing_ = 0.0;
    std::unique_ptr<SphSolver> solver_;
    std::string output_directory_;
    /// [[sph.probe]]: a name and the particle nearest to the probe's initial position.
    std::vector<std::pair<std::string, Index>> probes_;
    /// Written at each output instant, i.e. when the driver collects a frame.
    mutable std::unique_ptr<WallForceWriter> wall_writer_;
    mutable std::unique_ptr<std::ofstream> probe_writer_;
    mutable double last_row_time_ = -1.0;
    /// [sph.heap]: the measured body's kinetic energy per step and its heap at the end.
    std::optional<HeapMonitor> heap_;
};

} // namespace grainload::sph
