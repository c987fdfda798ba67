#pragma once

#include "io/stepper.hpp"
#include "materials/material_library.hpp"
#include "sph/particle_set.hpp"

#include <memory>
#include <string>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::sph {

/// The SPH side of a scene: particles of every [[sph.body]], advanced explicitly. Built from
/// the case's [sph] and [[sph.body]] tables; the time loop lives in the app's driver.
class SphModel final : public io::Stepper {
  public:
    static std::unique_ptr<SphModel> from_case(const io::CaseTable& root,
                                               const materials::MaterialLibrary& materials);

    std::string_view name() const override { return "sph"; }
    double stable_time_step() const override;
    void advance(double t, double dt) override;
    Index point_count() const override { return particles_.size(); }
    std::optional<std::string> diagnose() const override;
    void append_blocks(io::Frame& frame) const override;
    void append_results(double t, std::vector<io::ResultFigure>& results) const override;
    void write_checkpoint(std::ostream& out) const override;
    void read_checkpoint(std::istream& in) override;

    const ParticleSet& particles() const { return particles_; }

  private:
    SphModel(const materials::MaterialLibrary& materials) : materials_(&materials) {}
    void add_body(const io::CaseTable& body, int dimension);
    void compute_accelerations();

    const materials::MaterialLibrary* materials_;
    ParticleSet particles_;
    std::vector<std::string> body_names_;
    std::vector<Vec3> initial_position_;
    std::vector<Vec3> initial_velocity_;
    Vec3 gravity_ = Vec3::Zero();
    double time_step_ = 0.0; ///< fixed by the case; 0 means "from the CFL condition"
    bool interactions_ = true;
};

} // namespace grainload::sph
