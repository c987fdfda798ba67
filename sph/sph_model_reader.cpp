#include "sph/sph_model_reader.hpp"

#include "io/case_table.hpp"
#include "io/named_index.hpp"
#include "particles/particles_case_reader.hpp"
#include "sph/body_shape_reader.hpp"
#include "sph/probes.hpp"
#include "sph/scene_limits.hpp"
#include "sph/scene_monitors.hpp"
#include "sph/source_case_reader.hpp"
#include "sph/sph_case_reader.hpp"
#include "sph/wall_map_reader.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace grainload::sph {

namespace dim = io::dimension;

/// Reads the [sph] tables into the model it builds: each function reads and refuses at the
/// keys, and hands what it read to the model's own set-up (SphModel's private build steps).
class SphModelReader {
  public:
    static std::unique_ptr<SphModel> read_bodies(const io::CaseTable& root,
                                                 const io::SceneSettings& scene,
                                                 const materials::MaterialLibrary& materials);
    static void build(SphModel& model, const io::CaseTable& root);

  private:
    static void read_body(SphModel& model, const io::CaseTable& body);
    static void refuse_without_solver(const SphModel& model, const io::CaseTable& root);
    static void build_solver(SphModel& model, const io::CaseTable& sph);
    static void read_ghost_boundaries(const SphModel& model, const io::CaseTable& sph,
                                      std::vector<Wall>& walls, double support_radius,
                                      SphOptions& options);
    static void build_outlets(SphModel& model, const io::CaseTable& sph);
    static void build_settle(SphModel& model, const io::CaseTable& sph, bool walls_wait);
    static void build_sources(SphModel& model, const io::CaseTable& sph);
    static void check_phase_conditions(const SphModel& model, const io::CaseTable& root);
    static void build_monitors(SphModel& model, const io::CaseTable& sph);
};

std::unique_ptr<SphModel> SphModelReader::read_bodies(const io::CaseTable& root,
                                                      const io::SceneSettings& scene,
                                                      const materials::MaterialLibrary& materials) {
    const io::CaseTable sph = root.table("sph");
    SphModel::Settings settings;
    settings.gravity = scene.gravity;
    settings.dimension = scene.dimension;
    // Absent: the CFL limit, which 0 stands for in SphModel.
    settings.time_step =
        sph.has("time_step") ? sph.positive_quantity("time_step", dim::kTime) : 0.0;
    settings.interactions =
        sph.boolean_or("interactions", io::default_value(kSphKeys, "interactions") != 0.0);
    if (!settings.interactions && settings.time_step == 0.0) {
        sph.fail("time_step", "free flight (interactions = false) has no CFL limit: expected a "
                              "fixed time_step, e.g. \"1 ms\"");
    }
    std::unique_ptr<SphModel> model(new SphModel(materials, settings));
    const auto bodies = sph.array_of_tables("body");
    if (bodies.empty()) {
        sph.fail("", "expected at least one [[sph.body]]");
    }
    for (const auto& body : bodies) {
        read_body(*model, body);
    }
    if (model->interactions_) {
        model->options_ =
            read_sph_options(sph, model->dimension_, model->spacing_, model->gravity_);
    }
    return model;
}

void SphModelReader::read_body(SphModel& model, const io::CaseTable& body) {
    BodySettings settings = read_body_settings(body, *model.materials_, model.dimension_);
    io::refuse_repeated_name(body, model.body_names_, settings.name, "body");
    const double spacing = settings.spacing;
    if (model.spacing_ > 0.0 && std::abs(spacing - model.spacing_) > 1e-9 * model.spacing_) {
        body.fail("spacing", "every body must use the same particle spacing (one smoothing "
                             "length for the scene); the first body uses " +
                                 std::to_string(model.spacing_) + " m");
    }
    std::vector<RoundedSize> rounded;
    const auto points = fill_shape(settings.shape, spacing, model.dimension_, &rounded);
    if (const std::string note = model.record_rounding(settings.name, rounded, spacing);
        !note.empty()) {
        body.notify(note);
    }
    if (body.has("clamp") && !model.interactions_) {
        body.fail("clamp", "clamped particles need the SPH solver: expected interactions = true");
    }
    const Index first = model.add_body(std::move(settings.name), settings.material, points,
                                       settings.velocity, spacing);
    read_clamps(body, model.particles_, first, model.dimension_);
    read_initial_stress(body, model.particles_, first, model.gravity_, spacing);
}

void SphModelReader::refuse_without_solver(const SphModel& model, const io::CaseTable& root) {
    if (model.interactions_) {
        return;
    }
    const io::CaseTable sph = root.table("sph");
    if (!model.phases().empty()) {
        root.fail("phase", "phases act on the SPH solver's walls, sources and sinks: expected "
                           "interactions = true");
    }
    for (const char* table : {"symmetry", "periodic"}) {
        if (sph.has(table)) {
            sph.fail(table, std::string("ghost images act through the particle interactions: "
                                        "expected interactions = true with [[sph.") +
                                table + "]]");
        }
    }
    if (!model.added_walls_.empty()) {
        sph.fail("interactions", "walls coupled to shells need the SPH solver: expected "
                                 "interactions = true");
    }
}

void SphModelReader::build(SphModel& model, const io::CaseTable& root) {
    const io::CaseTable sph = root.table("sph");
    const ScenePlaces places = read_scene_places(root);
    model.set_phases(particles::read_phases(root), !sph.has("settle"));
    refuse_without_solver(model, root);
    if (model.interactions_) {
        build_solver(model, sph);
        if (auto probes = ProbeSet::place(read_probe_settings(sph), model.solver_->particles())) {
            model.parts_.add(std::move(probes));
        }
        check_gravity_strain(places, model.particles(), *model.materials_, model.body_names_,
                             model.gravity_, model.spacing_,
                             model.solver_->options().contact.stiffness);
        if (const std::string warning = impact_warning(model.particles(), model.body_names_,
                                                       model.solver_->options().contact.stiffness);
            !warning.empty()) {
            sph.warn(warning);
        }
    }
    build_outlets(model, sph);
    for (const std::string& warning : model.start_warnings(places)) {
        sph.warn(warning);
    }
    check_phase_conditions(model, root);
    model.phases_->apply_starts();
    build_monitors(model, sph);
    model.finish_build();
}

void SphModelReader::build_solver(SphModel& model, const io::CaseTable& sph) {
    SphOptions options = model.options_;
    const SmoothingKernel kernel(options.kernel, options.smoothing_length, model.dimension_);
    const auto bodies = static_cast<int>(model.body_names_.size());
    auto walls = read_rigid_walls(sph, model.particles_, model.dimension_, model.spacing_,
                                  kernel.support_radius(), bodies, &model.phases());
    const auto wall_tables = sph.array_of_tables("wall");
    for (std::size_t k = 0; k < wall_tables.size(); ++k) {
        walls[k].bodies = read_wall_bodies(wall_tables[k], model.body_names_);
    }
    model.append_added_walls(walls);
    options.friction = read_friction_pairs(sph, model.body_names_, walls);
    for (const FrictionPair& pair : model.added_wall_friction(walls)) {
        options.friction.push_back(pair);
    }
    read_ghost_boundaries(model, sph, walls, kernel.support_radius(), options);
    if (!options.friction.empty() && !(options.contact.stiffness > 0.0)) {
        sph.fail("friction", "wall friction acts through the contact force: expected an "
                             "[sph.contact] table with a stiffness");
    }
    model.make_solver(options, std::move(walls));
    if (model.time_step_ > 0.0) {
        const double limit = model.solver_->stable_time_step();
        if (model.time_step_ > limit) {
            std::ostringstream message;
            message << "time step " << model.time_step_ << " s is above the CFL limit " << limit
                    << " s (cfl_safety * h / (c + |v|), c = sqrt((K + 4G/3)/rho)); use at most "
                    << limit << " s or leave time_step out";
            sph.fail("time_step", message.str());
        }
    }
}

void SphModelReader::read_ghost_boundaries(const SphModel& model, const io::CaseTable& sph,
                                           std::vector<Wall>& walls, double support_radius,
                                           SphOptions& options) {
    for (const char* table : {"symmetry", "periodic"}) {
        if (sph.has(table) && options.formulation == Formulation::total_lagrangian) {
            sph.fail(table, std::string("ghost images are found anew as particles move, which "
                                        "the total-Lagrangian reference pairs do not do: "
                                        "expected formulation = \"updated_lagrangian\" with "
                                        "[[sph.") +
                                table + "]]");
        }
    }
    options.symmetry = read_symmetry_planes(sph, model.particles_, walls, model.body_names_,
                                            model.dimension_, model.spacing_, support_radius);
    options.periodic = read_periodic_axes(
        sph, model.particles_, walls, model.body_names_, options.symmetry, model.dimension_,
        support_radius + options.verlet_skin_factor * options.smoothing_length);
}

void SphModelReader::build_outlets(SphModel& model, const io::CaseTable& sph) {
    // A symmetry plane through an outlet leaves the model half of it (each [[sph.symmetry]]).
    const double share = std::pow(0.5, static_cast<double>(sph.array_of_tables("symmetry").size()));
    std::vector<particles::SinkSet::BodyGrain> grains;
    for (const int material : model.body_material_) {
        grains.push_back(
            {model.materials_->name(material), model.materials_->grain_size(material)});
    }
    model.set_sinks(std::make_shared<particles::SinkSet>(
        particles::read_sinks(sph, particles::BodyNames{"[[sph.body]]", model.body_names_},
                              model.dimension_, model.gravity_.norm(), share, grains)));
    const std::vector<Wall> none;
    const std::vector<Wall>& walls = model.solver_ ? model.solver_->walls() : none;
    build_settle(model, sph, std::any_of(walls.begin(), walls.end(), [](const Wall& wall) {
                     return wall.removal_on_settle;
                 }));
    model.add_gates();
    build_sources(model, sph);
    if (model.removals_ || !model.sources_->empty()) {
        const char* key = !model.sources_->empty() ? "source"
                          : model.sinks_->empty()  ? "wall"
                                                   : "sink";
        if (!model.solver_) {
            sph.fail(key, "particles leave or enter the scene only in the SPH solver: expected "
                          "interactions = true");
        }
        if (model.solver_->options().formulation == Formulation::total_lagrangian) {
            sph.fail(key, "the total-Lagrangian formulation keeps its reference neighbours for "
                          "ever, so no particle can leave or enter: expected formulation = "
                          "\"updated_lagrangian\" with sinks, sources or remove_at");
        }
    }
    model.open_books();
}

void SphModelReader::build_settle(SphModel& model, const io::CaseTable& sph, bool walls_wait) {
    if (const auto settle = sph.optional_table("settle")) {
        if (!model.solver_) {
            settle->fail("kinetic_energy_fraction",
                         "the settle watch needs the SPH solver: expected interactions = true");
        }
        model.set_settle(particles::read_settle_watch(*settle));
    } else if (walls_wait) {
        sph.fail("wall", "a wall with remove_at = \"settled\" needs an [sph.settle] table "
                         "saying when the scene has settled");
    }
}

void SphModelReader::build_sources(SphModel& model, const io::CaseTable& sph) {
    std::vector<double> density;
    for (const int material : model.body_material_) {
        density.push_back((*model.materials_)[material].density());
    }
    model.set_sources(std::make_shared<SourceSet>(
        read_sources(sph, model.body_names_, model.body_material_, density, model.spacing_,
                     model.dimension_, model.gravity_, &model.phases())));
}

void SphModelReader::check_phase_conditions(const SphModel& model, const io::CaseTable& root) {
    const auto tables = root.array_of_tables("phase");
    const auto& phases = model.phases().phases();
    for (std::size_t k = 0; k < phases.size(); ++k) {
        if (phases[k].end == particles::PhaseSequence::End::settled && !model.solver_) {
            tables[k].fail("end", "the settle condition measures the SPH solver's kinetic "
                                  "energy: expected interactions = true");
        }
        if (phases[k].end == particles::PhaseSequence::End::discharged && model.sinks_->empty()) {
            tables[k].fail("end", "the discharged condition counts the mass the sinks take: "
                                  "expected an [[sph.sink]]");
        }
    }
}

void SphModelReader::build_monitors(SphModel& model, const io::CaseTable& sph) {
    if (model.solver_) {
        particles::WallMapSet maps = read_wall_maps(sph, model.solver_->particles(),
                                                    model.solver_->walls(), model.dimension_);
        if (!maps.empty()) {
            model.parts_.add(
                wall_map_part(std::move(maps), model.solver_->particles(), model.solver_->walls()));
        }
    } else if (sph.has("wall_map")) {
        sph.fail("wall_map", "wall loads come from the SPH solver: expected interactions = true");
    }
    if (const auto heap = sph.optional_table("heap")) {
        model.parts_.add(heap_part(
            HeapMonitor(read_heap_settings(*heap, model.body_names_, model.gravity_),
                        model.particles(), model.spacing_, model.gravity_, model.dimension_),
            model.particles()));
    }
}

std::unique_ptr<SphModel> read_sph_model(const io::CaseTable& root, const io::SceneSettings& scene,
                                         const materials::MaterialLibrary& materials) {
    auto model = SphModelReader::read_bodies(root, scene, materials);
    SphModelReader::build(*model, root);
    return model;
}

std::unique_ptr<SphModel> read_sph_bodies(const io::CaseTable& root, const io::SceneSettings& scene,
                                          const materials::MaterialLibrary& materials) {
    return SphModelReader::read_bodies(root, scene, materials);
}

void build_sph_scene(SphModel& model, const io::CaseTable& root) {
    SphModelReader::build(model, root);
}

} // namespace grainload::sph
