#include "sph/particle_estimate_reader.hpp"

#include "io/case_table.hpp"
#include "io/surface_mesh_reader.hpp"
#include "sph/body_shape_reader.hpp"
#include "sph/kernels.hpp"
#include "sph/sph_case_reader.hpp"

#include <algorithm>
#include <cmath>

namespace grainload::sph {

namespace {

namespace dim = io::dimension;

ParticleCount estimate_body(const io::CaseTable& body, const BodySettings& settings,
                            int dimension) {
    ParticleCount count = count_shape(settings.shape, settings.spacing, dimension);
    count.table = body.path();
    count.name = settings.name;
    count.spacing_key = body.key_path("spacing");
    count.spacing = settings.spacing;
    return count;
}

/// A wall's surface measure (area in 3D, length in 2D) and how it was found.
std::pair<double, std::string> wall_measure(const io::CaseTable& wall, int dimension,
                                            const WallLayout& layout) {
    const std::string type = wall.choice("type", {"plane", "box", "mesh"});
    if (type == "mesh") {
        const double measure = surface_measure(io::read_surface_mesh(wall), dimension);
        return {measure,
                "mesh wall of " + estimate_text(measure) + (dimension == 3 ? " m^2" : " m")};
    }
    if (type == "plane") {
        // Rows on both edges, as plane_wall_points lays them: (round(|u| / s) + 1) per edge.
        auto rows = [&](const Vec3& edge) {
            return std::max(1.0, std::round(edge.norm() / layout.spacing)) + 1.0;
        };
        const Vec3 u = wall.vector("edge_u", dim::kLength);
        const Vec3 v = dimension == 3 ? wall.vector("edge_v", dim::kLength) : Vec3::Zero();
        const double cells = dimension == 3 ? rows(u) * rows(v) : rows(u);
        return {cells * std::pow(layout.spacing, dimension - 1),
                "plane wall of " + estimate_text(u.norm()) + " m" +
                    (dimension == 3 ? " x " + estimate_text(v.norm()) + " m" : "")};
    }
    // A box wall wraps its box in its layers' thickness: its cross-section surface is the outer
    // box's volume less the inner one (and less the open top), divided by the thickness.
    const double thickness = layout.layers * layout.spacing;
    const Vec3 lower = wall.vector("min", dim::kLength);
    const Vec3 upper = wall.vector("max", dim::kLength);
    const int up = dimension - 1;
    double outer = 1.0;
    double inner = 1.0;
    double top = thickness;
    for (int a = 0; a < dimension; ++a) {
        const double edge = std::abs(upper[a] - lower[a]);
        outer *= edge + 2.0 * thickness;
        inner *= edge;
        top *= a == up ? 1.0 : edge + 2.0 * thickness;
    }
    const double open =
        wall.boolean_or("open_top", io::default_value(kWallKeys, "open_top") != 0.0) ? top : 0.0;
    const double measure = std::max(0.0, outer - inner - open) / thickness;
    return {measure, "box wall of " + estimate_text(measure) + (dimension == 3 ? " m^2" : " m")};
}

/// A source's sites (sph/source.cpp): its box (min, max) or shape filled at the bodies'
/// spacing. It creates a particle at each site as its mass flows in, so at least that many.
ParticleCount estimate_source(const io::CaseTable& source, int dimension, double spacing,
                              double density) {
    ParticleCount count =
        source.has("shape")
            ? count_shape(read_shape(source.table("shape"), spacing, dimension, density), spacing,
                          dimension)
            : count_box(source.vector("min", dim::kLength), source.vector("max", dim::kLength),
                        spacing, dimension);
    count.table = source.path();
    count.name = source.string("name");
    count.spacing = spacing;
    count.basis = "source's " + count.basis;
    return count;
}

ParticleCount estimate_wall(const io::CaseTable& wall, int dimension, double body_spacing,
                            double support) {
    ParticleCount count;
    count.table = wall.path();
    count.name = wall.string("name");
    const WallLayout layout = read_wall_layout(wall, body_spacing, support);
    count.spacing = layout.spacing;
    count.spacing_key = wall.has("spacing") ? wall.key_path("spacing") : std::string();
    const auto [measure, basis] = wall_measure(wall, dimension, layout);
    count.particles = layout.layers * measure / std::pow(count.spacing, dimension - 1);
    count.basis = basis + " x " + std::to_string(layout.layers) + " layers / spacing^" +
                  std::to_string(dimension - 1);
    return count;
}

} // namespace

ParticleEstimate estimate_particles(const io::CaseTable& root, int dimension,
                                    const materials::MaterialLibrary& materials) {
    ParticleEstimate estimate;
    if (!root.has("sph")) {
        return estimate;
    }
    const io::CaseTable sph = root.table("sph");
    std::vector<std::string> body_names;
    std::vector<double> body_density;
    for (const io::CaseTable& body : sph.array_of_tables("body")) {
        const BodySettings settings = read_body_settings(body, materials, dimension);
        estimate.bodies.push_back(estimate_body(body, settings, dimension));
        estimate.bodies.back().index = static_cast<int>(estimate.bodies.size()) - 1;
        body_names.push_back(settings.name);
        body_density.push_back(materials[settings.material].density());
    }
    const double body_spacing = estimate.bodies.empty() ? 0.0 : estimate.bodies.front().spacing;
    for (const io::CaseTable& source : sph.array_of_tables("source")) {
        if (body_spacing > 0.0) {
            const auto b = static_cast<std::size_t>(body_index(source, "body", body_names));
            estimate.sources.push_back(
                estimate_source(source, dimension, body_spacing, body_density[b]));
            estimate.sources.back().index = static_cast<int>(estimate.sources.size()) - 1;
        }
    }
    if (estimate.bodies.empty() ||
        !sph.boolean_or("interactions", io::default_value(kSphKeys, "interactions") != 0.0)) {
        return estimate; // free flight builds no walls
    }
    const SphOptions options = read_sph_options(sph, dimension, body_spacing, Vec3::Zero());
    if (options.formulation == Formulation::total_lagrangian) {
        estimate.bytes_per_particle = kTotalLagrangianBytesPerParticle;
    }
    const double support =
        SmoothingKernel(options.kernel, options.smoothing_length, dimension).support_radius();
    for (const io::CaseTable& wall : sph.array_of_tables("wall")) {
        estimate.walls.push_back(estimate_wall(wall, dimension, body_spacing, support));
        estimate.walls.back().index = static_cast<int>(estimate.walls.size()) - 1;
    }
    return estimate;
}

} // namespace grainload::sph
