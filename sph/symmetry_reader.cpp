// [[sph.symmetry]] and [[sph.periodic]]: the mirror planes of half and quarter models, and the
// periodic directions of repeated ones.
#include "io/case_table.hpp"
#include "sph/sph_case_reader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace grainload::sph {

namespace {

constexpr const char* kAxisNames[] = {"x", "y", "z"};

/// The table's `axis`: x, y or (in 3D) z, as 0, 1, 2.
int read_axis(const io::CaseTable& table, int dimension) {
    const std::string name =
        dimension == 3 ? table.choice("axis", {"x", "y", "z"}) : table.choice("axis", {"x", "y"});
    return name == "x" ? 0 : (name == "y" ? 1 : 2);
}

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

/// The particles of one body or one wall along a periodic axis: where they start and end, and
/// the smallest step between two of their coordinates (0: all at one coordinate).
struct AxisLattice {
    Extent extent;
    double step = 0.0;
};

AxisLattice axis_lattice(std::vector<double> coordinates) {
    AxisLattice lattice;
    std::sort(coordinates.begin(), coordinates.end());
    for (std::size_t k = 0; k < coordinates.size(); ++k) {
        lattice.extent.add(coordinates[k]);
        const double step = k > 0 ? coordinates[k] - coordinates[k - 1] : 0.0;
        if (step > 1e-9 * std::abs(coordinates[k]) + 1e-15 &&
            (lattice.step == 0.0 || step < lattice.step)) {
            lattice.step = step;
        }
    }
    return lattice;
}

/// Every body and wall inside [min, max) along the axis, and a lattice that reaches both ends
/// continued across them: its particles at the two ends no closer across the seam than half its
/// step (closer, they would overlap in the repeated scene).
void check_periodic_lattices(const io::CaseTable& table, const PeriodicAxis& axis,
                             const ParticleSet& particles, const std::vector<Wall>& walls,
                             const std::vector<std::string>& body_names) {
    std::vector<std::vector<double>> body_x(body_names.size());
    for (Index i = 0; i < particles.size(); ++i) {
        if (!particles.is_wall(i)) {
            body_x[static_cast<std::size_t>(particles.body_id[i])].push_back(
                particles.position[i][axis.axis]);
        }
    }
    auto check = [&](const std::string& what, std::vector<double> x) {
        const AxisLattice lattice = axis_lattice(std::move(x));
        const Extent& e = lattice.extent;
        if (e.empty()) {
            return;
        }
        std::ostringstream where;
        where << what << " spans " << kAxisNames[axis.axis] << " from " << e.low << " to " << e.high
              << " m";
        if (e.low < axis.min || e.high >= axis.max) {
            table.fail("min", where.str() + ": expected it inside the period [" +
                                  std::to_string(axis.min) + ", " + std::to_string(axis.max) +
                                  ") m");
        }
        const double seam = (e.low - axis.min) + (axis.max - e.high);
        if (lattice.step > 0.0 && seam < 0.5 * lattice.step) {
            std::ostringstream message;
            message << where.str() << " in steps of " << lattice.step
                    << " m: its particles at the two ends are " << seam
                    << " m apart across the periodic seam; expected at least half a step (draw "
                       "it from min + step/2 to max - step/2, so that its lattice continues "
                       "across the seam)";
            table.fail("max", message.str());
        }
    };
    for (std::size_t b = 0; b < body_names.size(); ++b) {
        check("body \"" + body_names[b] + "\"", body_x[b]);
    }
    for (const Wall& wall : walls) {
        std::vector<double> x;
        for (Index k = wall.first; k < wall.first + wall.count; ++k) {
            x.push_back(particles.position[k][axis.axis]);
        }
        check("wall \"" + wall.name + "\"", std::move(x));
    }
}

} // namespace

std::vector<PeriodicAxis> read_periodic_axes(const io::CaseTable& sph, const ParticleSet& particles,
                                             const std::vector<Wall>& walls,
                                             const std::vector<std::string>& body_names,
                                             const std::vector<SymmetryPlane>& planes,
                                             int dimension, double search_radius) {
    std::vector<PeriodicAxis> periodic;
    for (const auto& table : sph.array_of_tables("periodic")) {
        PeriodicAxis axis;
        axis.axis = read_axis(table, dimension);
        const std::string name = kAxisNames[axis.axis];
        for (const PeriodicAxis& other : periodic) {
            if (other.axis == axis.axis) {
                table.fail("axis", "a periodic axis " + name +
                                       " is already declared: expected at most one per axis");
            }
        }
        for (const SymmetryPlane& plane : planes) {
            if (plane.axis == axis.axis) {
                table.fail("axis", "a symmetry plane normal to " + name +
                                       " is declared: expected a periodic axis without one");
            }
        }
        axis.min = table.quantity("min", io::dimension::kLength);
        axis.max = table.quantity("max", io::dimension::kLength);
        // No particle may be near both ends, whose images it would need at once.
        if (!(axis.period() > 2.0 * search_radius)) {
            std::ostringstream message;
            message << "the period max - min = " << axis.period()
                    << " m: expected more than twice the neighbour search radius, "
                    << 2.0 * search_radius << " m";
            table.fail("max", message.str());
        }
        check_periodic_lattices(table, axis, particles, walls, body_names);
        periodic.push_back(axis);
    }
    return periodic;
}

std::vector<SymmetryPlane>
read_symmetry_planes(const io::CaseTable& sph, const ParticleSet& particles,
                     std::vector<Wall>& walls, const std::vector<std::string>& body_names,
                     int dimension, double spacing, double support_radius) {
    std::vector<SymmetryPlane> planes;
    const auto tables = sph.array_of_tables("symmetry");
    for (const auto& table : tables) {
        SymmetryPlane plane;
        plane.axis = read_axis(table, dimension);
        const std::string axis = kAxisNames[plane.axis];
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
