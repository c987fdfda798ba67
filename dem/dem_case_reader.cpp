#include "dem/dem_case_reader.hpp"

#include "io/case_error.hpp"
#include "io/case_table.hpp"
#include "io/named_index.hpp"
#include "io/scene_settings.hpp"
#include "io/surface_mesh_reader.hpp"
#include "materials/material_case_reader.hpp"
#include "materials/material_library.hpp"
#include "particles/particles_case_reader.hpp"
#include "particles/wall_map_reader.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

namespace grainload::dem {

namespace dim = io::dimension;

namespace {

double coefficient(const io::CaseTable& table, std::string_view key, double fallback) {
    const double value = table.number_or(key, fallback);
    if (!(value >= 0.0 && std::isfinite(value))) {
        table.fail(key, "expected a coefficient >= 0, got " + std::to_string(value));
    }
    return value;
}

/// Lazarevic, Dvornik & Fresl's capped cohesive spring: N_c per kilogram of the lighter grain,
/// p_N g, between grains and with walls; the linear law only (the cap is a reach N_c / k_n).
void read_cohesion(const io::CaseTable& table, double gravity, ContactLaw& law) {
    const auto share = [&table](std::string_view key, double fallback) {
        const double value = coefficient(table, key, fallback);
        if (value > 1.0) {
            table.fail(key, "expected a share of the lighter grain's weight in [0, 1]: a grain "
                            "could hang from another");
        }
        return value;
    };
    const double grains = share("cohesion_share", 0.0);
    const double walls = share("wall_cohesion_share", grains);
    if (grains > 0.0 || walls > 0.0) {
        const std::string_view key =
            table.has("cohesion_share") ? "cohesion_share" : "wall_cohesion_share";
        if (law.model != ContactLaw::Model::linear) {
            table.fail(key, "the capped cohesive spring is the linear law's: expected law = "
                            "\"linear\"");
        }
        if (!(gravity > 0.0)) {
            table.fail(key, "the cohesive pull is a share of the grains' weight: expected "
                            "gravity in [case]");
        }
    }
    law.cohesion_pull = grains * gravity;
    law.wall_cohesion_pull = walls * gravity;
}

ContactLaw read_contact_law(const io::CaseTable& dem, double gravity) {
    const io::CaseTable table = dem.table("contact");
    ContactLaw law;
    const std::string model = table.choice("law", {"linear", "hertz_mindlin"});
    law.model = model == "linear" ? ContactLaw::Model::linear : ContactLaw::Model::hertz_mindlin;
    law.gamma_n = table.positive_quantity_or("gamma_n", dim::kFrequency,
                                             io::default_value(kDemContactKeys, "gamma_n"), true);
    law.gamma_t = table.positive_quantity_or("gamma_t", dim::kFrequency,
                                             io::default_value(kDemContactKeys, "gamma_t"), true);
    law.friction = coefficient(table, "friction", 0.0);
    law.wall_friction = coefficient(table, "wall_friction", law.friction);
    law.rolling_friction = coefficient(table, "rolling_friction", 0.0);
    law.wall_rolling_friction = coefficient(table, "wall_rolling_friction", law.rolling_friction);
    law.rolling_damping =
        table.number_or("rolling_damping", io::default_value(kDemContactKeys, "rolling_damping"));
    if (!(law.rolling_damping >= 0.0 && law.rolling_damping <= 1.0)) {
        table.fail("rolling_damping", "expected a damping ratio in [0, 1]");
    }
    if (law.model == ContactLaw::Model::linear) {
        law.normal_stiffness = table.positive_quantity("normal_stiffness", dim::kForcePerLength);
        law.tangential_stiffness_ratio =
            table.number_or("tangential_stiffness_ratio",
                            io::default_value(kDemContactKeys, "tangential_stiffness_ratio"));
        if (!(law.tangential_stiffness_ratio >= 0.0 && law.tangential_stiffness_ratio <= 1.0)) {
            table.fail("tangential_stiffness_ratio", "expected a number in [0, 1]");
        }
    } else {
        for (const char* key : {"normal_stiffness", "tangential_stiffness_ratio"}) {
            if (table.has(key)) {
                table.fail(key, "the hertz_mindlin law takes its stiffness from the grains' E "
                                "and nu: expected no " +
                                    std::string(key));
            }
        }
    }
    if (table.has("restitution")) {
        if (table.has("gamma_n")) {
            table.fail("restitution", "expected either restitution or gamma_n, not both");
        }
        const double e = table.number("restitution");
        if (!(e > 0.0 && e <= 1.0)) {
            table.fail("restitution", "expected a coefficient of restitution in (0, 1]");
        }
        law.restitution = e;
        if (law.model == ContactLaw::Model::hertz_mindlin) {
            law.hertz_alpha = hertz_restitution_damping(e);
        }
    }
    read_cohesion(table, gravity, law);
    return law;
}

PlaneWall::Face read_rectangle(const io::CaseTable& table) {
    PlaneWall::Face face;
    face.shape = PlaneWall::Shape::rectangle;
    face.point = table.vector("origin", dim::kLength);
    face.edge_u = table.vector("edge_u", dim::kLength);
    face.edge_v = table.vector("edge_v", dim::kLength);
    const double u = face.edge_u.norm();
    const double v = face.edge_v.norm();
    if (!(u > 0.0 && v > 0.0)) {
        table.fail(u > 0.0 ? "edge_v" : "edge_u", "expected an edge of non-zero length");
    }
    // Right angles to round-off of the written digits: 1e-6 of the edges' lengths.
    if (std::abs(face.edge_u.dot(face.edge_v)) > 1e-6 * u * v) {
        table.fail("edge_v", "expected edge_v at right angles to edge_u");
    }
    face.normal = face.edge_u.cross(face.edge_v).normalized();
    return face;
}

/// A wall's prescribed translation: velocity, move_start, move_end.
void read_motion(const io::CaseTable& table, PlaneWall& wall) {
    wall.velocity =
        table.vector_or("velocity", dim::kVelocity, io::default_vector(kDemWallKeys, "velocity"));
    wall.move_start = table.positive_quantity_or(
        "move_start", dim::kTime, io::default_value(kDemWallKeys, "move_start"), true);
    wall.move_end = table.quantity_or("move_end", dim::kTime, wall.move_end);
    if (!(wall.move_end > wall.move_start)) {
        table.fail("move_end", "expected a time after move_start");
    }
}

PlaneWall read_wall(const io::CaseTable& table, int up, const particles::PhaseSequence& phases) {
    PlaneWall wall;
    wall.name = table.string("name");
    if (const auto phase = particles::read_phase_reference(table, "remove_at", &phases)) {
        // Its time is the phase's start, which DemModel hands over once it is known.
        wall.removal_phase = *phase;
    } else if (table.has("remove_at")) {
        wall.remove_at = table.positive_quantity("remove_at", dim::kTime, true);
    }
    read_motion(table, wall);
    const std::string type = table.choice("type", {"plane", "rectangle", "box", "mesh"});
    if (type == "mesh") {
        const io::SurfaceMesh mesh = io::read_surface_mesh(table);
        if (mesh.triangles.empty() && mesh.quads.empty()) {
            table.fail("file", "expected a surface mesh of triangles or quads");
        }
        wall.set_mesh(mesh);
        return wall;
    }
    if (type == "rectangle") {
        wall.faces.push_back(read_rectangle(table));
        return wall;
    }
    if (type == "plane") {
        const Vec3 normal = table.vector("normal", dim::kNone);
        if (!(normal.norm() > 0.0)) {
            table.fail("normal", "expected a non-zero vector");
        }
        wall.faces.push_back({table.vector("point", dim::kLength), normal.normalized()});
        return wall;
    }
    const Vec3 min = table.vector("min", dim::kLength);
    const Vec3 max = table.vector("max", dim::kLength);
    if (!(min.array() < max.array()).all()) {
        table.fail("max", "expected max above min on every axis");
    }
    wall.faces = PlaneWall::box_faces(
        min, max, up,
        table.boolean_or("open_top", io::default_value(kDemWallKeys, "open_top") != 0.0));
    return wall;
}

/// start and end: times, or "phase:NAME" (the phase's start, which DemModel hands over once it
/// is known). An end before the start is refused where the case fixes both: two times, or two
/// phases (which begin in the order of the table).
void read_window(const io::CaseTable& table, const particles::PhaseSequence& phases,
                 SourceSettings& source) {
    // A phase whose start the case does not fix counts from 0 s (start) or to the run's end
    // (end) in the estimates; the run takes the start when the phase begins.
    if (const auto phase = particles::read_phase_reference(table, "start", &phases)) {
        source.start_phase = *phase;
        source.start = std::isfinite(phases.start(*phase)) ? phases.start(*phase) : 0.0;
    } else {
        source.start = table.positive_quantity_or("start", dim::kTime,
                                                  io::default_value(kDemSourceKeys, "start"), true);
    }
    if (const auto phase = particles::read_phase_reference(table, "end", &phases)) {
        source.end_phase = *phase;
        source.end = phases.start(*phase);
    } else {
        source.end =
            table.positive_quantity_or("end", dim::kTime, std::numeric_limits<double>::infinity());
    }
    if (!particles::window_in_order(source.start, source.end, source.start_phase,
                                    source.end_phase)) {
        table.fail("end", "expected an end after the start");
    }
}

SourceSettings read_source(const io::CaseTable& table, const std::vector<BodySettings>& bodies,
                           const particles::PhaseSequence& phases) {
    SourceSettings source;
    source.name = table.string("name");
    source.body = io::index_by_name(
        table, "body", bodies, [](const BodySettings& b) { return b.name; }, "[[dem.body]]");
    const BodySettings& body = bodies[static_cast<std::size_t>(source.body)];
    source.min = table.vector("min", dim::kLength);
    source.max = table.vector("max", dim::kLength);
    // A clump is drawn turned any way: the box must hold its length along every axis.
    const double length = 2.0 * body.radius_max * body.reach();
    if (!((source.max - source.min).array() >= length).all()) {
        table.fail("max", body.spheres == 1
                              ? "the box must hold a grain of the body's largest radius: expected "
                                "max - min >= 2 radius_max on every axis"
                              : "the box must hold a clump of the body's largest radius turned "
                                "any way: expected max - min >= 2 radius_max (its farthest "
                                "sphere's reach from its centre of mass, in radii) on every "
                                "axis");
    }
    source.rate = table.positive_quantity("rate", dim::kFrequency);
    if (table.has("count")) {
        source.count = table.integer("count");
        if (*source.count < 1) {
            table.fail("count", "expected at least one grain");
        }
    }
    read_window(table, phases, source);
    source.velocity =
        table.vector_or("velocity", dim::kVelocity, io::default_vector(kDemSourceKeys, "velocity"));
    const std::int64_t seed = table.integer_or(
        "seed", static_cast<std::int64_t>(io::default_value(kDemSourceKeys, "seed")));
    if (seed < 0) {
        table.fail("seed", "expected an integer >= 0");
    }
    source.seed = static_cast<std::uint64_t>(seed);
    return source;
}

/// The sources of [[dem.source]]; a body with no grains at the start needs one.
void read_sources(const io::CaseTable& dem, DemSettings& settings) {
    for (const io::CaseTable& table : dem.array_of_tables("source")) {
        SourceSettings source = read_source(table, settings.bodies, settings.phases);
        io::refuse_repeated_name(table, settings.sources, source.name, "source",
                                 &SourceSettings::name);
        settings.sources.push_back(std::move(source));
    }
    for (std::size_t b = 0; b < settings.bodies.size(); ++b) {
        const bool filled = std::any_of(
            settings.sources.begin(), settings.sources.end(),
            [b](const SourceSettings& source) { return source.body == static_cast<int>(b); });
        if (settings.bodies[b].count == 0 && !settings.bodies[b].centre && !filled) {
            throw io::CaseError(settings.bodies[b].where +
                                ": a body without grains at the start: expected a centre, or "
                                "min, max and count, or a [[dem.source]] that fills it");
        }
    }
}

/// A phase that ends on the mass the sinks took needs a sink.
void check_phase_ends(const io::CaseTable& root, const DemSettings& settings) {
    const auto tables = root.array_of_tables("phase");
    const auto& phases = settings.phases.phases();
    for (std::size_t k = 0; k < phases.size(); ++k) {
        if (phases[k].end == particles::PhaseSequence::End::discharged && settings.sinks->empty()) {
            tables[k].fail("end", "the discharged condition counts the mass the sinks take: "
                                  "expected a [[dem.sink]]");
        }
    }
}

/// [dem] integrator and the predictor-corrector's passes and tolerance.
void read_integrator(const io::CaseTable& dem, DemSettings& settings) {
    settings.integrator =
        dem.choice_or("integrator", {"velocity_verlet", "predictor_corrector"},
                      io::default_text(kDemKeys, "integrator")) == "predictor_corrector"
            ? Integrator::predictor_corrector
            : Integrator::velocity_verlet;
    const std::int64_t passes =
        dem.integer_or("corrector_passes",
                       static_cast<std::int64_t>(io::default_value(kDemKeys, "corrector_passes")));
    if (passes < 1 || passes > 100) {
        dem.fail("corrector_passes", "expected an integer in [1, 100]");
    }
    settings.corrector_passes = static_cast<int>(passes);
    settings.corrector_tolerance =
        dem.number_or("corrector_tolerance", io::default_value(kDemKeys, "corrector_tolerance"));
    if (!(settings.corrector_tolerance > 0.0)) {
        dem.fail("corrector_tolerance", "expected a number > 0");
    }
}

} // namespace

/// The sinks of [[dem.sink]], each body's grain size the mean diameter of its radii.
std::shared_ptr<particles::SinkSet> read_sinks(const io::CaseTable& dem,
                                               const DemSettings& settings,
                                               const materials::MaterialLibrary& materials,
                                               const io::SceneSettings& scene) {
    particles::BodyNames bodies{"[[dem.body]]", {}};
    std::vector<particles::SinkSet::BodyGrain> grains;
    for (const BodySettings& body : settings.bodies) {
        bodies.names.push_back(body.name);
        grains.push_back({materials.name(body.material), body.radius_min + body.radius_max});
    }
    return std::make_shared<particles::SinkSet>(
        particles::read_sinks(dem, bodies, 3, scene.gravity.norm(), 1.0, grains));
}

DemSettings read_dem_settings(const io::CaseTable& root,
                              const materials::MaterialLibrary& materials,
                              const io::SceneSettings& scene) {
    const int up = scene.up_axis();
    if (root.spatial_dimension() != 3) {
        root.table("case").fail("dimension", "the DEM's grains are spheres: expected dimension = 3 "
                                             "with a [dem] table");
    }
    const io::CaseTable dem = root.table("dem");
    DemSettings settings;
    settings.phases = particles::read_phases(root);
    if (dem.has("time_step")) {
        settings.time_step = dem.positive_quantity("time_step", dim::kTime);
        settings.time_step_where = dem.where("time_step");
    }
    settings.steps_per_contact =
        dem.number_or("steps_per_contact", io::default_value(kDemKeys, "steps_per_contact"));
    if (!(settings.steps_per_contact >= 10.0 && settings.steps_per_contact <= 1e4)) {
        dem.fail("steps_per_contact", "expected a number in [10, 10000]");
    }
    read_integrator(dem, settings);
    settings.impact_velocity = dem.positive_quantity_or(
        "impact_velocity", dim::kVelocity, io::default_value(kDemKeys, "impact_velocity"));
    settings.contact_forces =
        dem.boolean_or("contact_forces", io::default_value(kDemKeys, "contact_forces") != 0.0);
    if (dem.has("skin")) {
        settings.skin = dem.positive_quantity("skin", dim::kLength);
    }
    settings.law = read_contact_law(dem, scene.gravity.norm());
    const io::CaseTable contact = dem.table("contact");
    settings.damping_where = contact.where(contact.has("gamma_n") ? "gamma_n" : "law");
    for (const io::CaseTable& table : dem.array_of_tables("body")) {
        BodySettings body = read_dem_body(table, materials);
        io::refuse_repeated_name(table, settings.bodies, body.name, "body", &BodySettings::name);
        if (settings.contact_forces && body.name == "contacts") {
            table.fail("name", "with contact_forces the frames' contacts block is called "
                               "\"contacts\": expected another name");
        }
        settings.bodies.push_back(std::move(body));
    }
    if (settings.bodies.empty()) {
        dem.fail("body", "expected at least one [[dem.body]]");
    }
    for (const io::CaseTable& table : dem.array_of_tables("wall")) {
        PlaneWall wall = read_wall(table, up, settings.phases);
        io::refuse_repeated_name(table, settings.walls, wall.name, "wall", &PlaneWall::name);
        settings.walls.push_back(std::move(wall));
    }
    settings.triaxial = read_triaxial(dem, up, settings.walls);
    read_sources(dem, settings);
    std::vector<std::string> wall_names;
    for (const PlaneWall& wall : settings.walls) {
        wall_names.push_back(wall.name);
    }
    settings.wall_maps = particles::read_wall_maps(dem, wall_names, 3);
    settings.sinks = read_sinks(dem, settings, materials, scene);
    check_phase_ends(root, settings);
    return settings;
}

} // namespace grainload::dem
