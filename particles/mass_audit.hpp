#pragma once
// The books of the material's mass in a scene that particles leave or enter.

#include "particles/scene_part.hpp"

#include <functional>

namespace grainload::particles {

/// The mass audit of a scene with sinks, sources or gates: mass in the scene + mass discharged
/// = initial mass + mass created, which holds to round-off when no particle is lost or made
/// twice. A scene part that reports the books at the end (summary.json's mass_audit_error,
/// whose reference is 0) and checkpoints the initial mass.
class MassAudit final : public ScenePart {
  public:
    /// What the books read when they report: the material's mass in the scene, the mass the
    /// sinks took and the mass the sources made, each since the scene was built.
    struct Books {
        std::function<double()> scene_mass;
        std::function<double()> discharged;
        std::function<double()> created;
    };
    /// `initial_mass`: the material's mass as the case built it; `dimension` 2: masses per metre.
    MassAudit(double initial_mass, int dimension, Books books)
        : initial_mass_(initial_mass), dimension_(dimension), books_(std::move(books)) {}

    /// (mass in the scene + mass discharged - initial mass - mass created) / (initial mass +
    /// mass created); 0 for a scene that never held any mass.
    static double error(double scene_mass, double discharged, double initial, double created);

    std::string_view name() const override { return "mass_audit"; }
    /// scene_mass, discharged_mass, initial_mass, created_mass and mass_audit_error.
    void append_results(std::vector<io::ResultFigure>& results) const override;
    void write_checkpoint(std::ostream& out) const override;
    void read_checkpoint(std::istream& in) override;

  private:
    double initial_mass_;
    int dimension_;
    Books books_;
};

} // namespace grainload::particles
