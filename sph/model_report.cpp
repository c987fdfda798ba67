// What an SPH scene modelled and what it could have left out: the
// SphModel members behind io::Reporter::describe_model and append_hints.
#include "materials/generalized_cap.hpp"
#include "sph/rigid_wall.hpp"
#include "sph/sph_model.hpp"

#include <cmath>
#include <cstdio>

namespace grainload::sph {

namespace {

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g %%", 100.0 * share);
    return text;
}

} // namespace

std::string SphModel::viscosity_statement() const {
    const ArtificialViscosity& viscosity = solver_->options().viscosity;
    if (viscosity.alpha == 0.0 && viscosity.beta == 0.0) {
        return "";
    }
    // The c of alpha c mu sets how much the linear term dissipates, and with it run-outs and
    // discharge rates (docs/user-guide/sph.md, "Stiffness and run time"): say which it is.
    char text[160];
    std::snprintf(text, sizeof text, "alpha %g, beta %g, c = ", viscosity.alpha, viscosity.beta);
    std::string statement = text;
    if (viscosity.sound_speed > 0.0) {
        std::snprintf(text, sizeof text, "%.3g m/s (sound_speed)", viscosity.sound_speed);
        return statement + text;
    }
    statement += "each material's P-wave speed before its stiffness_scale:";
    for (const int m : built_materials_) {
        std::snprintf(text, sizeof text, " %s %.3g m/s", materials_->name(m).c_str(),
                      (*materials_)[m].elastic().unscaled_p_wave_speed());
        statement += text;
    }
    return statement;
}

void SphModel::describe_model(std::vector<io::ModelChoice>& choices) const {
    choices.push_back({"dimension", dimension_ == 2 ? "plane strain" : "3D"});
    if (!solver_) {
        choices.push_back({"sph", "free flight (no interactions)"});
        return;
    }
    choices.push_back(
        {"sph formulation", solver_->options().formulation == Formulation::total_lagrangian
                                ? "total Lagrangian"
                                : "updated Lagrangian"});
    for (const int m : built_materials_) {
        choices.push_back(
            {"material " + materials_->name(m), std::string((*materials_)[m].model())});
    }
    if (const std::string viscosity = viscosity_statement(); !viscosity.empty()) {
        choices.push_back({"artificial viscosity", viscosity});
    }
    for (const Wall& wall : solver_->walls()) {
        // A wall without a driver stays where it was built; the coupling's walls follow a shell.
        const bool rigid = !wall.driver || dynamic_cast<const RigidMotion*>(wall.driver.get());
        std::string what = rigid ? "rigid" : "driven by another solver";
        if (wall.removal_phase >= 0) {
            what += ", removed when phase \"" +
                    phases().phases()[static_cast<std::size_t>(wall.removal_phase)].name +
                    "\" begins";
        } else if (std::isfinite(wall.removal_time)) {
            char time[32];
            std::snprintf(time, sizeof time, "%g", wall.removal_time);
            what += std::string(", removed at ") + time + " s";
        }
        choices.push_back({"wall " + wall.name, what});
    }
    for (const SymmetryPlane& plane : solver_->options().symmetry) {
        const char* axis = plane.axis == 0 ? "x" : (plane.axis == 1 ? "y" : "z");
        char text[96];
        std::snprintf(text, sizeof text, "mirror plane %s = %g m, material on the %s side", axis,
                      plane.at, plane.side > 0 ? "+" : "-");
        choices.push_back({std::string("symmetry ") + axis, text});
    }
    for (const PeriodicAxis& periodic : solver_->options().periodic) {
        const char* axis = periodic.axis == 0 ? "x" : (periodic.axis == 1 ? "y" : "z");
        char text[96];
        std::snprintf(text, sizeof text, "repeats from %g to %g m", periodic.min, periodic.max);
        choices.push_back({std::string("periodic ") + axis, text});
    }
    for (const particles::SinkSet::Sink& sink : sinks_->sinks()) {
        choices.push_back({"sink " + sink.name, sink.region.kind == io::Region::Kind::half_space
                                                    ? "half-space beyond a plane"
                                                    : "box"});
    }
}

void SphModel::append_hints(std::vector<std::string>& hints) const {
    // A cap that never hardened: compaction on the cap is what the generalized cap adds to its
    // failure envelope, so without it a Drucker-Prager cone of the same envelope gives the same
    // response for less work per update. eps_v^p > 0 marks net compaction on the cap (MAT_025:
    // it starts at 0 and grows only there; docs/theory/generalized_cap.md).
    const ParticleSet& p = particles();
    for (int m = 0; m < materials_->size(); ++m) {
        if ((*materials_)[m].model() != "generalized_cap") {
            continue;
        }
        Index count = 0;
        Index compacted = 0;
        for (Index i = 0; i < p.size(); ++i) {
            if (p.is_wall(i) || p.material_id[i] != m) {
                continue;
            }
            ++count;
            const double strain = p.state[static_cast<std::size_t>(p.state_offset[i]) +
                                          materials::GeneralizedCap::kPlasticVolumetricStrain];
            compacted += strain > 0.0;
        }
        if (count == 0) {
            continue;
        }
        const std::string name = "material '" + materials_->name(m) + "' (generalized_cap): ";
        if (compacted == 0) {
            hints.push_back(name + "none of its " + std::to_string(count) +
                            " particles compacted on the cap; a drucker_prager material with the "
                            "cap's failure envelope would give the same response at lower cost");
        } else {
            hints.push_back(name + std::to_string(compacted) + " of its " + std::to_string(count) +
                            " particles (" +
                            percent(static_cast<double>(compacted) / static_cast<double>(count)) +
                            ") compacted on the cap: the cap is needed");
        }
    }
}

} // namespace grainload::sph
