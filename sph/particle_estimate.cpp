#include "sph/particle_estimate.hpp"

#include "io/case_table.hpp"
#include "io/keyword_deck.hpp"
#include "io/surface_mesh_reader.hpp"
#include "sph/kernels.hpp"
#include "sph/sph_case_reader.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace grainload::sph {

namespace dim = io::dimension;

namespace {

std::string text(double value) {
    std::ostringstream out;
    out.precision(3);
    out << value;
    return out.str();
}

/// Box: the lattice of fill_box, max(1, round(edge / spacing)) cells per axis.
ParticleCount box_body(const io::CaseTable& shape, double spacing, int dimension) {
    const Vec3 lower = shape.vector("min", dim::kLength);
    const Vec3 upper = shape.vector("max", dim::kLength);
    ParticleCount count;
    count.particles = 1.0;
    std::string edges;
    for (int a = 0; a < dimension; ++a) {
        const double edge = std::abs(upper[a] - lower[a]);
        count.particles *= std::max(1.0, std::round(edge / spacing));
        edges += (a == 0 ? "" : " x ") + text(edge);
    }
    count.basis = edges + " m box / spacing^" + std::to_string(dimension);
    return count;
}

/// Cylinder and cone: the frustum's volume (3D) or its axial section (2D; a disc for a 2D
/// cylinder).
ParticleCount round_body(const io::CaseTable& shape, const std::string& type, double spacing,
                         int dimension) {
    ParticleCount count;
    if (type == "cylinder" && dimension == 2) {
        const double r = shape.positive_quantity("radius", dim::kLength);
        count.particles = std::numbers::pi * r * r / (spacing * spacing);
        count.basis = "disc of radius " + text(r) + " m / spacing^2";
        return count;
    }
    const double height = shape.positive_quantity("height", dim::kLength);
    double r0 = 0.0;
    double r1 = 0.0;
    if (type == "cylinder") {
        r0 = r1 = shape.positive_quantity("radius", dim::kLength);
    } else {
        r0 = shape.positive_quantity("base_radius", dim::kLength);
        r1 = std::max(0.0, shape.quantity_or("top_radius", dim::kLength, 0.0));
    }
    const double measure = dimension == 3
                               ? std::numbers::pi * height * (r0 * r0 + r0 * r1 + r1 * r1) / 3.0
                               : height * (r0 + r1);
    count.particles = measure / std::pow(spacing, dimension);
    count.basis = type + " of height " + text(height) + " m / spacing^" + std::to_string(dimension);
    return count;
}

/// Volume enclosed by a closed surface (divergence theorem over its triangles, quadrangles
/// split along a diagonal): sum of a . (b x c) / 6.
double enclosed_volume(const io::SurfaceMesh& mesh) {
    double six_volume = 0.0;
    for (const auto& t : mesh.triangles) {
        six_volume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]]));
    }
    for (const auto& q : mesh.quads) {
        const Vec3& a = mesh.vertices[q[0]];
        six_volume += a.dot(mesh.vertices[q[1]].cross(mesh.vertices[q[2]]));
        six_volume += a.dot(mesh.vertices[q[2]].cross(mesh.vertices[q[3]]));
    }
    return std::abs(six_volume) / 6.0;
}

/// Surface area of a mesh (3D) or length of its polyline (2D).
double surface_measure(const io::SurfaceMesh& mesh, int dimension) {
    double measure = 0.0;
    if (dimension == 2) {
        for (const auto& s : mesh.segments) {
            measure += (mesh.vertices[s[1]] - mesh.vertices[s[0]]).norm();
        }
        return measure;
    }
    for (const auto& t : mesh.triangles) {
        const Vec3& a = mesh.vertices[t[0]];
        measure += 0.5 * (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
    }
    for (const auto& q : mesh.quads) {
        const Vec3& a = mesh.vertices[q[0]];
        measure += 0.5 * (mesh.vertices[q[1]] - a).cross(mesh.vertices[q[2]] - a).norm();
        measure += 0.5 * (mesh.vertices[q[2]] - a).cross(mesh.vertices[q[3]] - a).norm();
    }
    return measure;
}

/// An LS-DYNA deck's particles: one *ELEMENT_SPH card each (every part; an upper bound when the
/// shape selects some). A deck that cannot be read counts none: the builder reports it.
ParticleCount deck_body(const io::CaseTable& shape) {
    ParticleCount count;
    count.basis = "*ELEMENT_SPH cards of the deck";
    try {
        const io::KeywordDeck deck = io::read_keyword_deck(shape.file_path("file"));
        for (const io::Keyword& keyword : deck.keywords) {
            if (keyword.name.starts_with("ELEMENT_SPH")) {
                count.particles += static_cast<double>(keyword.cards.size());
            }
        }
    } catch (const io::KeywordError&) {
        count.particles = 0.0;
    }
    return count;
}

/// The particles a body's shape holds (or a source's [sph.source.shape] has sites for).
ParticleCount shape_count(const io::CaseTable& shape, double spacing, int dimension) {
    const std::string type = shape.choice("type", {"box", "cylinder", "cone", "mesh", "lsdyna"});
    ParticleCount count;
    if (type == "box") {
        count = box_body(shape, spacing, dimension);
    } else if (type == "mesh" && dimension == 3) {
        const double volume = enclosed_volume(io::read_surface_mesh(shape));
        count.particles = volume / std::pow(spacing, 3);
        count.basis = "closed mesh of " + text(volume) + " m^3 / spacing^3";
    } else if (type == "lsdyna") {
        count = deck_body(shape);
    } else if (type != "mesh") {
        count = round_body(shape, type, spacing, dimension);
    }
    return count;
}

ParticleCount estimate_body(const io::CaseTable& body, int dimension) {
    const double spacing = body.positive_quantity("spacing", dim::kLength);
    ParticleCount count = shape_count(body.table("shape"), spacing, dimension);
    count.table = body.path();
    count.name = body.string("name");
    count.spacing_key = body.key_path("spacing");
    count.spacing = spacing;
    return count;
}

/// A wall's surface measure (area in 3D, length in 2D) and how it was found.
std::pair<double, std::string> wall_measure(const io::CaseTable& wall, int dimension, double layers,
                                            double thickness) {
    const std::string type = wall.choice("type", {"plane", "box", "mesh"});
    if (type == "mesh") {
        const double measure = surface_measure(io::read_surface_mesh(wall), dimension);
        return {measure, "mesh wall of " + text(measure) + (dimension == 3 ? " m^2" : " m")};
    }
    if (type == "plane") {
        // Rows on both edges, as plane_wall_points lays them: (round(|u| / s) + 1) per edge.
        const double spacing = thickness / layers;
        auto rows = [&](const Vec3& edge) {
            return std::max(1.0, std::round(edge.norm() / spacing)) + 1.0;
        };
        const Vec3 u = wall.vector("edge_u", dim::kLength);
        const double cells =
            dimension == 3 ? rows(u) * rows(wall.vector("edge_v", dim::kLength)) : rows(u);
        return {cells * std::pow(spacing, dimension - 1),
                "plane wall of " + text(u.norm()) + " m" +
                    (dimension == 3
                         ? " x " + text(wall.vector("edge_v", dim::kLength).norm()) + " m"
                         : "")};
    }
    // A box wall wraps its box in `thickness`: its cross-section surface is the outer box's
    // volume less the inner one (and less the open top), divided by the thickness.
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
    const double open = wall.boolean_or("open_top", true) ? top : 0.0;
    const double measure = std::max(0.0, outer - inner - open) / thickness;
    return {measure, "box wall of " + text(measure) + (dimension == 3 ? " m^2" : " m")};
}

/// A source's sites (sph/source.cpp): its box (min, max) or shape filled at the bodies'
/// spacing. It creates a particle at each site as its mass flows in, so at least that many.
ParticleCount estimate_source(const io::CaseTable& source, int dimension, double spacing) {
    ParticleCount count = source.has("shape")
                              ? shape_count(source.table("shape"), spacing, dimension)
                              : box_body(source, spacing, dimension);
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
    count.spacing = wall.positive_quantity_or("spacing", dim::kLength, body_spacing);
    count.spacing_key = wall.has("spacing") ? wall.key_path("spacing") : std::string();
    const auto layers = static_cast<double>(
        wall.integer_or("layers", static_cast<int>(std::ceil(support / count.spacing))));
    const auto [measure, basis] = wall_measure(wall, dimension, layers, layers * count.spacing);
    count.particles = layers * measure / std::pow(count.spacing, dimension - 1);
    count.basis =
        basis + " x " + text(layers) + " layers / spacing^" + std::to_string(dimension - 1);
    return count;
}

} // namespace

double ParticleEstimate::total() const {
    double sum = 0.0;
    for (const auto* list : {&bodies, &sources, &walls}) {
        for (const ParticleCount& count : *list) {
            sum += count.particles;
        }
    }
    return sum;
}

const ParticleCount* ParticleEstimate::largest() const {
    const ParticleCount* best = nullptr;
    for (const auto* list : {&bodies, &sources, &walls}) {
        for (const ParticleCount& count : *list) {
            if (best == nullptr || count.particles > best->particles) {
                best = &count;
            }
        }
    }
    return best;
}

ParticleEstimate estimate_particles(const io::CaseTable& root, int dimension) {
    ParticleEstimate estimate;
    if (!root.has("sph")) {
        return estimate;
    }
    const io::CaseTable sph = root.table("sph");
    for (const io::CaseTable& body : sph.array_of_tables("body")) {
        estimate.bodies.push_back(estimate_body(body, dimension));
        estimate.bodies.back().index = static_cast<int>(estimate.bodies.size()) - 1;
    }
    const double body_spacing = estimate.bodies.empty() ? 0.0 : estimate.bodies.front().spacing;
    for (const io::CaseTable& source : sph.array_of_tables("source")) {
        if (body_spacing > 0.0) {
            estimate.sources.push_back(estimate_source(source, dimension, body_spacing));
            estimate.sources.back().index = static_cast<int>(estimate.sources.size()) - 1;
        }
    }
    if (estimate.bodies.empty() || !sph.boolean_or("interactions", true)) {
        return estimate; // free flight builds no walls
    }
    const double spacing = body_spacing;
    const SphOptions options = read_sph_options(sph, dimension, spacing, Vec3::Zero());
    if (options.formulation == Formulation::total_lagrangian) {
        estimate.bytes_per_particle = kTotalLagrangianBytesPerParticle;
    }
    const double support =
        SmoothingKernel(options.kernel, options.smoothing_length, dimension).support_radius();
    for (const io::CaseTable& wall : sph.array_of_tables("wall")) {
        estimate.walls.push_back(estimate_wall(wall, dimension, spacing, support));
        estimate.walls.back().index = static_cast<int>(estimate.walls.size()) - 1;
    }
    return estimate;
}

} // namespace grainload::sph
