#pragma once
// The shape of an SPH body or source as its [sph.body.shape] table states it, filled with
// particle centres.

#include "io/key_places.hpp"
#include "io/key_spec.hpp"
#include "io/surface_mesh.hpp"
#include "io/types.hpp"
#include "materials/material_library.hpp"
#include "sph/body_generator.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::sph {

/// The keys of [sph.body.shape] (and of a source's [sph.source.shape]) but a mesh's
/// (io::kSurfaceMeshKeys) and a deck's (kKeywordBodyKeys).
inline constexpr std::array<io::KeySpec, 13> kShapeKeys{{
    {"type", "`box`, `cylinder`, `cone`, `mesh` or `lsdyna`", "", "the shape its lattice fills"},
    {"min", "length vector", "required for a box", "the box's lower corner"},
    {"max", "length vector", "required for a box", "the box's upper corner"},
    {"centre", "length vector", "required for a disc", "a 2D cylinder's centre"},
    {"base", "length vector", "required for a 3D cylinder or a cone",
     "the centre of the base face"},
    {"axis", "vector", "required for a 3D cylinder or a cone", "the direction base to top"},
    {"radius", "length", "required for a cylinder", "its radius"},
    {"height", "length", "required for a 3D cylinder or a cone", "along the axis"},
    {"base_radius", "length", "required for a cone", "the radius at the base"},
    {"top_radius", "length", "0 m", "the radius at the top: > 0 makes a frustum", 0.0},
    {"lattice", "`regular` or `jittered`", "regular",
     "jittered: each particle offset at random within its cell"},
    {"jitter", "number in [0, 0.5)", "0.1", "jittered: the largest offset per axis in spacings",
     0.1},
    {"seed", "integer", "1", "jittered: the same seed, the same particles", 1.0},
}};

/// The keys of each [[sph.body.shape.cut]]: the shape keeps the particles in front of a plane.
inline constexpr std::array<io::KeySpec, 3> kCutKeys{{
    {"point", "length vector", "", "a point of the plane"},
    {"normal", "vector", "", "towards the particles kept (any length)"},
    {"offset", "length", "0 m", "the particles kept are at least this far in front", 0.0},
}};

/// One [sph.body.shape] (or [sph.source.shape]) as read: what its lattice fills, with the
/// places of the keys that a fill which comes out empty is refused at.
struct ShapeSettings {
    enum class Type { box, disc, cylinder, cone, mesh, lsdyna };
    Type type = Type::box;
    Vec3 min = Vec3::Zero(); ///< box
    Vec3 max = Vec3::Zero();
    Vec3 centre = Vec3::Zero(); ///< disc (a 2D cylinder)
    Vec3 base = Vec3::Zero();   ///< cylinder and cone
    Vec3 axis = Vec3::Zero();
    double radius = 0.0; ///< disc and cylinder
    double height = 0.0;
    double base_radius = 0.0; ///< cone
    double top_radius = 0.0;
    io::SurfaceMesh mesh;          ///< mesh: the closed surface
    std::vector<Vec3> deck_points; ///< lsdyna: the deck's particles (read_keyword_particles)
    bool jittered = false;
    double jitter = 0.0;
    std::uint64_t seed = 0;
    struct Cut {
        Vec3 point = Vec3::Zero();
        Vec3 normal = Vec3::Zero(); ///< unit, towards the particles kept
        double offset = 0.0;
        io::KeyPlaces places; ///< its `normal`
    };
    std::vector<Cut> cuts;
    io::KeyPlaces places; ///< the shape's `type` and `file`
};

/// The shape table `shape` of a body or source (type = "box", "cylinder", "cone" or "mesh" (a
/// closed surface mesh, see closed_mesh_fill.hpp), lattice = "regular" or "jittered"; or type =
/// "lsdyna": the *ELEMENT_SPH particles of a deck (keyword_body_reader.hpp), whose masses are
/// checked against the body's `density` [kg/m^3] * spacing^dimension). Every key is checked
/// here; what the fill may still refuse (a shape smaller than a cell) is refused by fill_shape.
ShapeSettings read_shape(const io::CaseTable& shape, double spacing, int dimension, double density);

/// Particle centres filling `shape` on a lattice of `spacing`. In 2D (plane strain) the lattice
/// lies in the x-y plane with z = 0. With `rounded`, the axes along which the lattice (before
/// any jitter) changed the shape's drawn size are added to it (lattice_rounding).
std::vector<Vec3> fill_shape(const ShapeSettings& shape, double spacing, int dimension,
                             std::vector<RoundedSize>* rounded = nullptr);

/// The keys of each [[sph.body]] besides its [sph.body.shape], [sph.body.initial_stress] and
/// [[sph.body.clamp]] tables. All bodies share one spacing.
inline constexpr std::array<io::KeySpec, 4> kBodyKeys{{
    {"name", "string", "", "names the body's block in the frames and its figures"},
    {"material", "string", "", "a [[material]] name"},
    {"spacing", "length", "", "the lattice spacing; particle mass = density x spacing^dimension"},
    {"velocity", "velocity vector", "0 m/s", "the initial velocity"},
}};

/// One [[sph.body]] as read: the keys of kBodyKeys and its shape.
struct BodySettings {
    std::string name;
    int material = 0; ///< index in the material library
    double spacing = 0.0;
    Vec3 velocity = Vec3::Zero();
    ShapeSettings shape;
};

/// The body table `body`: its material among `materials`, its spacing, velocity and shape (the
/// run's bodies and `grainload check`'s estimate read the same). The checks between bodies
/// (one spacing, distinct names) are the scene's.
BodySettings read_body_settings(const io::CaseTable& body,
                                const materials::MaterialLibrary& materials, int dimension);

/// read_shape, then fill_shape.
std::vector<Vec3> generate_body_points(const io::CaseTable& shape, double spacing, int dimension,
                                       double density, std::vector<RoundedSize>* rounded = nullptr);

/// The drawn bounding box (lower, upper corner) of a box, cylinder or cone shape; none for a
/// shape cut by planes, a mesh or a deck, whose drawn extent the case does not state.
std::optional<std::pair<Vec3, Vec3>> drawn_bounds(const ShapeSettings& shape, int dimension);

} // namespace grainload::sph
