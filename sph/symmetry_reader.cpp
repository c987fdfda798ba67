// [[sph.symmetry]]: the mirror planes of half and quarter models.
#include "io/case_table.hpp"
#include "sph/sph_case_reader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace grainload::sph {

namespace {

constexpr const char* kAxisNames[] = {"x", "y", "z"};

std::string plane_text(const SymmetryPlane& plane) {
    std::ostringstream text;
    text << kAxisNames[plane.axis] << " = " << plane.at << " m";
    return text.str();
}

/// Signed distances (material side positive once the side is known) of a range of particles.
struct Extent {
    double low = std::numeric_limits<double>::infinity();
    double high = -std::numeric_limits<double>::infinity();
    void add(double value) {
        low = std::min(low, value);
        high = std::max(high, value);
    }
    bool empty() const { return low > high; }
};

/// The side of the plane that holds the bodies; refuses a body on both sides or on the plane.
int material_side(const io::CaseTable& table, const SymmetryPlane& plane,
                  const ParticleSet& particles, const std::vector<std::string>& body_names,
                  double spacing) {
    std::vector<Extent> extent(body_names.size());
    for (Index i = 0; i < particles.size(); ++i) {
        if (particles.is_wall(i)) {
            continue;
        }
        extent[static_cast<std::size_t>(particles.body_id[i])].add(
            particles.position[i][plane.axis] - plane.at);
    }
    // A particle within a quarter spacing of the plane would nearly coincide with its own image
    // (twice its mass in one place); lattices put the first layer half a spacing off a face.
    const double on_plane = 0.25 * spacing;
    int side = table.has("side") ? (table.choice("side", {"+", "-"}) == "+" ? 1 : -1) : 0;
    for (std::size_t b = 0; b < extent.size(); ++b) {
        const Extent& e = extent[b];
        if (e.empty()) {
            continue;
        }
        std::ostringstream where;
        where << "body \"" << body_names[b] << "\" spans " << kAxisNames[plane.axis] << " from "
              << e.low + plane.at << " to " << e.high + plane.at << " m";
        if (e.low < on_plane && e.high > -on_plane) {
            table.fail("at", where.str() + ": it straddles or touches the plane " +
                                 plane_text(plane) +
                                 "; expected every body on one side, at least a quarter "
                                 "spacing off the plane (cut the body at the plane)");
        }
        const int body_side = e.low > 0.0 ? 1 : -1;
        if (side == 0) {
            side = body_side;
        } else if (side != body_side) {
            table.fail(table.has("side") ? "side" : "at",
                       where.str() + ", on the other side of the plane " + plane_text(plane) +
                           " than the material side: expected every body on side " +
                           (side > 0 ? "+" : "-"));
        }
    }
    return side == 0 ? 1 : side;
}

/// A wall that reaches the plane is either mirrored (it ends at the plane: a floor or a shell
/// cut there) or runs on past it far enough for the particles near the plane to see it as in
/// the full model (then it is not mirrored, which would double it); between the two it is
/// refused.
void check_walls(const io::CaseTable& table, const SymmetryPlane& plane,
                 const ParticleSet& particles, std::vector<Wall>& walls, double spacing,
                 double support_radius) {
    for (Wall& wall : walls) {
        Extent e;
        for (Index k = wall.first; k < wall.first + wall.count; ++k) {
            e.add(plane.side * (particles.position[k][plane.axis] - plane.at));
        }
        if (e.empty() || e.low >= support_radius || e.high < 0.0) {
            continue; // clear of the plane, or wholly on the empty side
        }
        const double past = -e.low; // how far the wall runs on past the plane
        const double needed = support_radius - spacing;
        // A quarter spacing: lattice points on the plane itself (they get no image) or half a
        // wall spacing before it count as ending at the plane.
        if (past <= 0.25 * spacing) {
            wall.mirror_planes = static_cast<std::uint8_t>(wall.mirror_planes | (1U << plane.axis));
        } else if (past < needed) {
            std::ostringstream message;
            message << "wall \"" << wall.name << "\" runs " << past << " m past the plane "
                    << plane_text(plane)
                    << ": expected it to end at the plane (it is then mirrored) or to run at "
                       "least "
                    << needed << " m past it (the kernel support " << support_radius
                    << " m less one spacing; it is then not mirrored)";
            table.fail("at", message.str());
        }
    }
}

} // namespace

std::vector<SymmetryPlane>
read_symmetry_planes(const io::CaseTable& sph, const ParticleSet& particles,
                     std::vector<Wall>& walls, const std::vector<std::string>& body_names,
                     int dimension, double spacing, double support_radius) {
    std::vector<SymmetryPlane> planes;
    const auto tables = sph.array_of_tables("symmetry");
    for (const auto& table : tables) {
        SymmetryPlane plane;
        const std::string axis = dimension == 3 ? table.choice("axis", {"x", "y", "z"})
                                                : table.choice("axis", {"x", "y"});
        plane.axis = axis == "x" ? 0 : (axis == "y" ? 1 : 2);
        for (const SymmetryPlane& other : planes) {
            if (other.axis == plane.axis) {
                table.fail("axis", "a symmetry plane normal to " + axis +
                                       " is already declared: expected at most one plane per "
                                       "axis (three in all)");
            }
        }
        plane.at =
            table.quantity_or("at", io::dimension::kLength, io::default_value(kSymmetryKeys, "at"));
        plane.side = material_side(table, plane, particles, body_names, spacing);
        check_walls(table, plane, particles, walls, spacing, support_radius);
        planes.push_back(plane);
    }
    return planes;
}

} // namespace grainload::sph
