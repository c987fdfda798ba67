#include "sph/sph_case_reader.hpp"

#include "io/case_table.hpp"
#include "io/named_index.hpp"
#include "io/surface_mesh_reader.hpp"
#include "particles/particles_case_reader.hpp"
#include "sph/initial_stress.hpp"
#include "sph/surface_mesh_wall.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grainload::sph {

namespace dim = io::dimension;

namespace {

/// [sph.artificial_viscosity]: alpha, beta and the sound speed.
ArtificialViscosity read_artificial_viscosity(const io::CaseTable& table) {
    ArtificialViscosity viscosity;
    viscosity.alpha =
        table.number_or("alpha", io::default_value(kArtificialViscosityKeys, "alpha"));
    viscosity.beta = table.number_or("beta", io::default_value(kArtificialViscosityKeys, "beta"));
    if (viscosity.alpha < 0.0 || viscosity.beta < 0.0) {
        table.fail("", "expected alpha >= 0 and beta >= 0");
    }
    // Absent: each material's own wave speed, which 0 stands for in ArtificialViscosity.
    viscosity.sound_speed =
        table.has("sound_speed") ? table.quantity("sound_speed", dim::kVelocity) : 0.0;
    if (!(viscosity.sound_speed >= 0.0)) {
        table.fail("sound_speed", "expected a speed >= 0 (0: the materials' own)");
    }
    return viscosity;
}

/// [sph.artificial_stress]: epsilon and exponent; refused with the total-Lagrangian formulation.
ArtificialStress read_artificial_stress(const io::CaseTable& table, Formulation formulation) {
    if (formulation == Formulation::total_lagrangian) {
        table.fail("", "artificial stress counters the tensile instability of the "
                       "updated-Lagrangian kernel, which total_lagrangian does not have: "
                       "expected no [sph.artificial_stress] table");
    }
    ArtificialStress stress;
    stress.epsilon =
        table.number_or("epsilon", io::default_value(kArtificialStressKeys, "epsilon"));
    stress.exponent =
        table.number_or("exponent", io::default_value(kArtificialStressKeys, "exponent"));
    if (stress.epsilon < 0.0 || stress.exponent <= 0.0) {
        table.fail("", "expected epsilon >= 0 and exponent > 0");
    }
    return stress;
}

/// [sph.contact]: stiffness, exponent and damping ratio.
ContactPotential read_contact_potential(const io::CaseTable& table) {
    ContactPotential contact;
    contact.stiffness = table.positive_quantity("stiffness", dim::kPressure);
    contact.exponent = table.number_or("exponent", io::default_value(kContactKeys, "exponent"));
    if (!(contact.exponent >= 1.0)) {
        table.fail("exponent", "expected n >= 1");
    }
    contact.damping_ratio =
        table.number_or("damping_ratio", io::default_value(kContactKeys, "damping_ratio"));
    if (!(contact.damping_ratio >= 0.0 && contact.damping_ratio <= 10.0)) {
        table.fail("damping_ratio", "expected a fraction of critical damping zeta in [0, 10]");
    }
    return contact;
}

} // namespace

SphOptions read_sph_options(const io::CaseTable& sph, int dimension, double spacing,
                            const Vec3& gravity) {
    SphOptions options; // its defaults are the case file's
    options.dimension = dimension;
    options.gravity = gravity;
    options.particle_spacing = spacing;
    const std::string kernel =
        sph.choice_or("kernel", {"cubic_spline", "quintic_spline", "wendland_c2"},
                      io::default_text(kSphKeys, "kernel"));
    options.kernel = kernel_type_from_name(kernel);
    const double ratio = sph.number_or("smoothing_length_ratio",
                                       io::default_value(kSphKeys, "smoothing_length_ratio"));
    if (!(ratio >= 0.8 && ratio <= 3.0)) {
        sph.fail("smoothing_length_ratio", "expected h / spacing in [0.8, 3]");
    }
    options.smoothing_length_ratio = ratio;
    options.smoothing_length = ratio * spacing;
    options.cfl_safety = sph.number_or("cfl_safety", io::default_value(kSphKeys, "cfl_safety"));
    if (!(options.cfl_safety > 0.0 && options.cfl_safety <= 1.0)) {
        sph.fail("cfl_safety", "expected a safety factor in (0, 1]");
    }
    options.verlet_skin_factor =
        sph.number_or("verlet_skin", io::default_value(kSphKeys, "verlet_skin"));
    if (!(options.verlet_skin_factor >= 0.0 && options.verlet_skin_factor <= 1.0)) {
        sph.fail("verlet_skin", "expected the Verlet skin as a fraction of h in [0, 1]");
    }
    options.fluidity_interval = sph.quantity_or("fluidity_interval", io::dimension::kTime,
                                                io::default_value(kSphKeys, "fluidity_interval"));
    if (!(options.fluidity_interval >= 0.0) || !std::isfinite(options.fluidity_interval)) {
        sph.fail("fluidity_interval", "expected a time >= 0 (0: solve every step)");
    }
    options.kernel_gradient_correction =
        sph.boolean_or("kernel_gradient_correction",
                       io::default_value(kSphKeys, "kernel_gradient_correction") != 0.0);
    const std::string formulation =
        sph.choice_or("formulation", {"updated_lagrangian", "total_lagrangian"},
                      io::default_text(kSphKeys, "formulation"));
    if (formulation == "total_lagrangian") {
        options.formulation = Formulation::total_lagrangian;
        // F = I + grad0 u must be exact for rigid rotations, which needs the corrected gradient.
        if (!options.kernel_gradient_correction) {
            sph.fail("kernel_gradient_correction",
                     "the total-Lagrangian formulation always corrects its reference gradient: "
                     "expected true or no key");
        }
    }
    if (const auto viscosity = sph.optional_table("artificial_viscosity")) {
        options.viscosity = read_artificial_viscosity(*viscosity);
    }
    if (const auto stress = sph.optional_table("artificial_stress")) {
        options.artificial_stress = read_artificial_stress(*stress, options.formulation);
    }
    if (const auto contact = sph.optional_table("contact")) {
        options.contact = read_contact_potential(*contact);
    }
    return options;
}

namespace {

/// A wall's particles and, for planes and boxes, which know their geometry exactly, the
/// surface normal at each; mesh walls leave the normals empty and their contact normal comes
/// from the colour function.
struct WallSurface {
    std::vector<Vec3> points;
    std::vector<Vec3> normals;
    std::vector<WallSample> samples;
};

WallSurface wall_surface(const io::CaseTable& wall, int dimension, double spacing, int layers) {
    const std::string type = wall.choice("type", {"plane", "box", "mesh"});
    if (type == "mesh") {
        MeshWallSamples mesh = read_mesh_wall_points(
            wall, dimension, spacing, layers,
            wall.boolean_or("flip_normals", io::default_value(kWallKeys, "flip_normals") != 0.0));
        return {std::move(mesh.points), {}, std::move(mesh.samples)};
    }
    if (type == "box") {
        const Vec3 lower = wall.vector("min", dim::kLength);
        const Vec3 upper = wall.vector("max", dim::kLength);
        auto points = box_wall_points(
            lower, upper, spacing, layers, dimension,
            wall.boolean_or("open_top", io::default_value(kWallKeys, "open_top") != 0.0));
        auto normals = box_wall_normals(points, lower, upper, dimension);
        return {std::move(points), std::move(normals), {}};
    }
    const Vec3 origin = wall.vector("origin", dim::kLength);
    const Vec3 u = wall.vector("edge_u", dim::kLength);
    const Vec3 v = dimension == 3 ? wall.vector("edge_v", dim::kLength) : Vec3::Zero();
    const Vec3 normal = wall.vector("normal", dim::kNone);
    if (!(normal.norm() > 0.0)) {
        wall.fail("normal", "expected a non-zero normal pointing into the material");
    }
    auto points = plane_wall_points(origin, u, v, normal, spacing, layers, dimension);
    std::vector<Vec3> normals(points.size(), normal.normalized());
    return {std::move(points), std::move(normals), {}};
}

/// `<key>_history` of a wall: [[time, vector], ...] with non-decreasing times, an alternative
/// to the constant `<key>`. The wall starts with the history's value at t = 0.
std::vector<std::pair<double, Vec3>> motion_history(const io::CaseTable& wall,
                                                    const std::string& key, io::Dimension value) {
    const std::string name = key + "_history";
    if (!wall.has(name)) {
        return {};
    }
    if (wall.has(key)) {
        wall.fail(name, "give either " + key + " (constant) or " + name + ", not both");
    }
    auto history = wall.vector_pairs(name, dim::kTime, value);
    for (std::size_t k = 1; k < history.size(); ++k) {
        if (history[k].first < history[k - 1].first) {
            wall.fail(name, "expected non-decreasing times");
        }
    }
    return history;
}

/// remove_at: a time, "settled" ([sph.settle]) or "phase:NAME" (that phase's start).
void read_removal(const io::CaseTable& table, const particles::PhaseSequence* phases, Wall& wall) {
    if (!table.has("remove_at")) {
        return;
    }
    if (const auto phase = particles::read_phase_reference(table, "remove_at", phases)) {
        wall.removal_phase = *phase;
    } else if (table.string("remove_at") == "settled") {
        wall.removal_on_settle = true;
    } else {
        wall.removal_time = table.positive_quantity("remove_at", dim::kTime, true);
    }
}

/// The wall's prescribed motion: constant velocities, or histories that count from t = 0 or
/// from `history_start` (a time, or a phase's start, placed once known). Before its start a
/// history holds its first value, so the wall starts with that.
void attach_motion(const io::CaseTable& table, const particles::PhaseSequence* phases,
                   ParticleSet& particles, Wall& wall) {
    auto velocity_history = motion_history(table, "velocity", dim::kVelocity);
    auto angular_history = motion_history(table, "angular_velocity", dim::kAngularVelocity);
    const bool shifted = table.has("history_start");
    if (shifted && velocity_history.empty() && angular_history.empty()) {
        table.fail("history_start", "expected a velocity_history or angular_velocity_history "
                                    "for history_start to start");
    }
    // A shifted history holds its first value until its start.
    const double now = shifted ? -std::numeric_limits<double>::infinity() : 0.0;
    const Vec3 velocity =
        velocity_history.empty()
            ? table.vector_or("velocity", dim::kVelocity, io::default_vector(kWallKeys, "velocity"))
            : history_value(velocity_history, now);
    const Vec3 angular_velocity =
        angular_history.empty() ? table.vector_or("angular_velocity", dim::kAngularVelocity,
                                                  io::default_vector(kWallKeys, "angular_velocity"))
                                : history_value(angular_history, now);
    RigidMotion& motion = attach_rigid_motion(particles, wall, velocity, angular_velocity);
    if (!shifted) {
        motion.velocity_history = std::move(velocity_history);
        motion.angular_velocity_history = std::move(angular_history);
        return;
    }
    motion.relative_velocity_history = std::move(velocity_history);
    motion.relative_angular_velocity_history = std::move(angular_history);
    if (const auto phase = particles::read_phase_reference(table, "history_start", phases)) {
        motion.history_phase = *phase;
    } else {
        motion.start_histories(table.positive_quantity("history_start", dim::kTime, true));
    }
}

} // namespace

WallLayout read_wall_layout(const io::CaseTable& wall, double body_spacing, double support_radius) {
    // A finer wall is smoother: see docs/theory/sph.md, "Wall contact".
    WallLayout layout;
    layout.spacing = wall.positive_quantity_or("spacing", dim::kLength, body_spacing);
    if (layout.spacing > body_spacing * (1.0 + 1e-9) || layout.spacing < 0.2 * body_spacing) {
        wall.fail("spacing", "expected a wall particle spacing between 0.2 and 1 times the "
                             "bodies' spacing");
    }
    const auto layers =
        wall.integer_or("layers", static_cast<int>(std::ceil(support_radius / layout.spacing)));
    if (layers < 1 || layers > 20) {
        wall.fail("layers", "expected 1 to 20 layers of wall particles");
    }
    layout.layers = static_cast<int>(layers);
    return layout;
}

std::vector<Wall> read_rigid_walls(const io::CaseTable& sph, ParticleSet& particles, int dimension,
                                   double spacing, double support_radius, int first_body_id,
                                   const particles::PhaseSequence* phases) {
    std::vector<Wall> walls;
    for (const auto& table : sph.array_of_tables("wall")) {
        const WallLayout layout = read_wall_layout(table, spacing, support_radius);
        WallSurface surface = wall_surface(table, dimension, layout.spacing, layout.layers);
        const int index = static_cast<int>(walls.size());
        Wall wall = add_wall(particles, table.string("name"), index, first_body_id + index,
                             surface.points, layout.spacing, 1.0, dimension);
        wall.normals = std::move(surface.normals);
        wall.samples = std::move(surface.samples);
        wall.centre = table.vector_or("centre", dim::kLength, wall.centre);
        read_removal(table, phases, wall);
        attach_motion(table, phases, particles, wall);
        walls.push_back(std::move(wall));
    }
    return walls;
}

HeapSettings read_heap_settings(const io::CaseTable& heap,
                                const std::vector<std::string>& body_names, const Vec3& gravity) {
    HeapSettings settings;
    settings.body = body_index(heap, "body", body_names);
    if (!(gravity.norm() > 0.0)) {
        heap.fail("", "a heap is measured along gravity: expected a non-zero [case] gravity");
    }
    settings.origin = heap.vector("origin", dim::kLength);
    settings.rest_fraction =
        heap.number_or("rest_fraction", io::default_value(kHeapKeys, "rest_fraction"));
    if (!(settings.rest_fraction > 0.0 && settings.rest_fraction < 1.0)) {
        heap.fail("rest_fraction", "expected a fraction of the peak kinetic energy in (0, 1)");
    }
    return settings;
}

std::vector<ProbeSettings> read_probe_settings(const io::CaseTable& sph) {
    std::vector<ProbeSettings> probes;
    for (const auto& table : sph.array_of_tables("probe")) {
        probes.push_back({table.string("name"), table.vector("position", dim::kLength)});
    }
    return probes;
}

int body_index(const io::CaseTable& table, const std::string& key,
               const std::vector<std::string>& body_names) {
    return io::index_by_name(
        table, key, body_names, [](const std::string& s) { return s; }, "[[sph.body]]");
}

void read_clamps(const io::CaseTable& body, ParticleSet& particles, Index first, int dimension) {
    for (const auto& table : body.array_of_tables("clamp")) {
        const Vec3 lower = table.vector("min", dim::kLength);
        const Vec3 upper = table.vector("max", dim::kLength);
        for (int a = 0; a < dimension; ++a) {
            if (!(upper[a] > lower[a])) {
                table.fail("max", "expected max > min in every direction");
            }
        }
        // Lattice points on a face of the box count as inside: a tolerance of a millionth of the
        // box keeps round-off in the generated positions from deciding.
        const Vec3 slack = 1e-6 * (upper - lower);
        Index held = 0;
        for (Index i = first; i < particles.size(); ++i) {
            const Vec3& x = particles.position[i];
            bool inside = true;
            for (int a = 0; a < dimension; ++a) {
                inside = inside && x[a] >= lower[a] - slack[a] && x[a] <= upper[a] + slack[a];
            }
            if (inside) {
                particles.clamped[i] = 1;
                ++held;
            }
        }
        if (held == 0) {
            table.fail("", "expected a box holding particles of this body (it holds none)");
        }
    }
}

void read_initial_stress(const io::CaseTable& body, ParticleSet& particles, Index first,
                         const Vec3& gravity, double spacing) {
    const auto table = body.optional_table("initial_stress");
    if (!table) {
        return;
    }
    table->choice("type", {"geostatic"});
    const double lateral_ratio = table->number("lateral_ratio");
    if (!(lateral_ratio >= 0.0 && lateral_ratio <= 2.0)) {
        table->fail("lateral_ratio", "expected the at-rest ratio K0 = sigma_h / sigma_v in [0, 2] "
                                     "(Jaky: 1 - sin phi)");
    }
    if (!(gravity.squaredNorm() > 0.0)) {
        table->fail("type", "a geostatic stress is the weight of the body: expected a nonzero "
                            "[case] gravity");
    }
    set_geostatic_stress(particles, first, gravity, spacing, lateral_ratio);
}

CoulombCoefficients read_coulomb_coefficients(const io::CaseTable& table) {
    CoulombCoefficients mu;
    mu.mu_static = table.number("mu_static");
    mu.mu_kinetic = table.number_or("mu_kinetic", mu.mu_static);
    if (!(mu.mu_static >= 0.0)) {
        table.fail("mu_static", "expected a friction coefficient >= 0");
    }
    if (!(mu.mu_kinetic >= 0.0 && mu.mu_kinetic <= mu.mu_static)) {
        table.fail("mu_kinetic", "expected 0 <= mu_kinetic <= mu_static (Coulomb: kinetic "
                                 "friction does not exceed static friction)");
    }
    return mu;
}

std::vector<FrictionPair> read_friction_pairs(const io::CaseTable& sph,
                                              const std::vector<std::string>& body_names,
                                              const std::vector<Wall>& walls) {
    std::vector<FrictionPair> pairs;
    for (const auto& table : sph.array_of_tables("friction")) {
        FrictionPair pair;
        pair.body_id = body_index(table, "body", body_names);
        const int wall = io::index_by_name(
            table, "wall", walls, [](const Wall& w) { return w.name; }, "[[sph.wall]]");
        const Wall& met = walls[static_cast<std::size_t>(wall)];
        pair.wall_body_id = met.body_id;
        if (!met.bodies.empty() &&
            std::find(met.bodies.begin(), met.bodies.end(), pair.body_id) == met.bodies.end()) {
            table.fail("body", "wall \"" + met.name + "\" does not act on this body (its " +
                                   "`bodies`): expected one of them");
        }
        const CoulombCoefficients mu = read_coulomb_coefficients(table);
        pair.mu_static = mu.mu_static;
        pair.mu_kinetic = mu.mu_kinetic;
        for (const FrictionPair& other : pairs) {
            if (other.body_id == pair.body_id && other.wall_body_id == pair.wall_body_id) {
                table.fail("wall", "this body-wall pair already has friction coefficients");
            }
        }
        pairs.push_back(pair);
    }
    return pairs;
}

std::vector<int> read_wall_bodies(const io::CaseTable& table,
                                  const std::vector<std::string>& body_names) {
    std::vector<int> bodies;
    if (!table.has("bodies")) {
        return bodies;
    }
    const std::string known = io::quoted_names(body_names);
    for (const std::string& name : table.name_list("bodies")) {
        const auto found = std::find(body_names.begin(), body_names.end(), name);
        if (found == body_names.end()) {
            table.fail("bodies", "no [[sph.body]] called \"" + name +
                                     "\": expected names of bodies (" + known + ")");
        }
        const auto id = static_cast<int>(found - body_names.begin());
        if (std::find(bodies.begin(), bodies.end(), id) != bodies.end()) {
            table.fail("bodies", "body \"" + name + "\" is listed twice: expected each once");
        }
        bodies.push_back(id);
    }
    return bodies;
}

MeshWallSamples read_mesh_wall_points(const io::CaseTable& wall, int dimension, double spacing,
                                      int layers, bool flip_normals) {
    const io::SurfaceMesh mesh = io::read_surface_mesh(wall);
    const auto faces = mesh.triangles.size() + mesh.quads.size();
    if (dimension == 2 && mesh.segments.empty()) {
        wall.fail("file", "in plane strain (dimension = 2) a mesh wall is a polyline: expected a "
                          "Gmsh .msh file with 2-node line elements (type 1); this mesh has " +
                              std::to_string(faces) + " faces and no lines");
    }
    if (dimension == 3 && faces == 0) {
        wall.fail("file", "a 3D mesh wall needs triangles or quadrangles; this mesh has " +
                              std::to_string(mesh.segments.size()) + " lines and no faces");
    }
    return mesh_wall_points(mesh, spacing, layers, dimension, flip_normals);
}

ScenePlaces read_scene_places(const io::CaseTable& root) {
    const auto shape_places = [](const io::CaseTable& shape) {
        return io::KeyPlaces(shape, {"min", "base", "centre", "file", "type"});
    };
    ScenePlaces places;
    const io::CaseTable sph = root.table("sph");
    for (const io::CaseTable& body : sph.array_of_tables("body")) {
        places.body_shapes.push_back(shape_places(body.table("shape")));
    }
    for (const io::CaseTable& source : sph.array_of_tables("source")) {
        places.sources.emplace_back(source, std::initializer_list<std::string_view>{"min"});
        places.source_shapes.push_back(source.has("shape") ? shape_places(source.table("shape"))
                                                           : io::KeyPlaces());
    }
    for (const io::CaseTable& sink : sph.array_of_tables("sink")) {
        places.sinks.emplace_back(
            sink, std::initializer_list<std::string_view>{"min", "point", "normal"});
    }
    for (const io::CaseTable& wall : sph.array_of_tables("wall")) {
        places.walls.emplace_back(wall, std::initializer_list<std::string_view>{"remove_at"});
    }
    for (const io::CaseTable& material : root.array_of_tables("material")) {
        places.materials.emplace_back(
            material, std::initializer_list<std::string_view>{"stiffness_scale", "from_lsdyna",
                                                              "youngs_modulus", "bulk_modulus"});
        places.deck_units.push_back(material.has("from_lsdyna")
                                        ? material.table("from_lsdyna").string("units")
                                        : std::string());
    }
    if (sph.has("contact")) {
        places.contact = io::KeyPlaces(sph.table("contact"), {"stiffness"});
    }
    return places;
}

} // namespace grainload::sph
