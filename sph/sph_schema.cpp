#include "sph/sph_schema.hpp"

#include "io/surface_mesh_reader.hpp"
#include "particles/particles_case_reader.hpp"
#include "particles/wall_map_reader.hpp"
#include "sph/body_shape_reader.hpp"
#include "sph/heap_monitor.hpp"
#include "sph/keyword_body_reader.hpp"
#include "sph/probes.hpp"
#include "sph/source_case_reader.hpp"
#include "sph/sph_case_reader.hpp"
#include "sph/symmetry.hpp"
#include "sph/wall_map_reader.hpp"

#include <array>

namespace grainload::sph {

namespace {

constexpr std::string_view kGuide = "docs/user-guide/sph.md";
constexpr std::string_view kMeshHeading = "### Surface mesh keys";
constexpr std::string_view kDeckHeading = "## Particles from an LS-DYNA deck";

const std::array<io::KeyTable, 27> kTables{{
    {"sph", false, "the SPH solver: kernel, smoothing length, step", kSphKeys, kGuide,
     "### `[sph]`"},
    {"sph.artificial_viscosity", false, "Monaghan's artificial viscosity", kArtificialViscosityKeys,
     kGuide, "### `[sph.artificial_viscosity]`"},
    {"sph.artificial_stress", false, "artificial stress against the tensile instability",
     kArtificialStressKeys, kGuide, "### `[sph.artificial_stress]`"},
    {"sph.contact", false, "the contact potential between bodies and with walls", kContactKeys,
     kGuide, "### `[sph.contact]`"},
    {"sph.friction", true, "Coulomb friction of one body on one wall", kFrictionKeys, kGuide,
     "### `[[sph.friction]]`"},
    {"sph.heap", false, "the heap figures of one body in summary.json", kHeapKeys, kGuide,
     "### `[sph.heap]`"},
    {"sph.probe", true, "one particle followed in probes.csv", kProbeKeys, kGuide,
     "### `[[sph.probe]]`"},
    {"sph.body", true, "a body of particles: material, spacing, initial velocity", kBodyKeys,
     kGuide, "### `[[sph.body]]`"},
    {"sph.body.shape", false, "the shape a body's lattice fills", kShapeKeys, kGuide,
     "### `[sph.body.shape]`"},
    {"sph.body.shape", false, "a body filling a closed surface mesh", io::kSurfaceMeshKeys, kGuide,
     kMeshHeading},
    {"sph.body.shape", false, "a body from the particles of an LS-DYNA deck", kKeywordBodyKeys,
     kGuide, kDeckHeading},
    {"sph.body.shape.cut", true, "a plane the shape is cut by", kCutKeys, kGuide,
     "### `[[sph.body.shape.cut]]`"},
    {"sph.body.initial_stress", false, "the stress a body starts with", kInitialStressKeys, kGuide,
     "### `[sph.body.initial_stress]`"},
    {"sph.body.clamp", true, "a box whose particles of the body are held", kClampKeys, kGuide,
     "### `[[sph.body.clamp]]`"},
    {"sph.wall", true, "a rigid wall of particles: plane, box or mesh", kWallKeys, kGuide,
     "### `[[sph.wall]]`"},
    {"sph.wall", true, "a mesh wall's surface", io::kSurfaceMeshKeys, kGuide, kMeshHeading},
    {"sph.wall", true, "a wall that leaves the scene or moves on a schedule: an outlet, a gate",
     kWallOutletKeys, kGuide, "## Outlets and gates: `[[sph.wall]]` keys"},
    {"sph.source", true, "particles entering the scene through a region at a mass rate",
     kSourceKeys, kGuide, "## `[[sph.source]]`"},
    {"sph.source.shape", false, "a source's region as a body shape", kShapeKeys, kGuide,
     "### `[sph.body.shape]`"},
    {"sph.source.shape", false, "a source's region inside a closed surface mesh",
     io::kSurfaceMeshKeys, kGuide, kMeshHeading},
    {"sph.source.shape.cut", true, "a plane the source's region is cut by", kCutKeys, kGuide,
     "### `[[sph.body.shape.cut]]`"},
    {"sph.sink", true, "particles leaving the scene beyond a plane or inside a box",
     particles::kSinkKeys, kGuide, "## `[[sph.sink]]`"},
    {"sph.settle", false, "when the scene counts as settled (`settled` in time keys)",
     particles::kSettleKeys, kGuide, "## Settling: `[sph.settle]`"},
    {"sph.symmetry", true, "a mirror plane: the scene is a half or a quarter of the whole",
     kSymmetryKeys, kGuide, "## Symmetry planes: `[[sph.symmetry]]`"},
    {"sph.periodic", true, "a periodic direction: the scene repeats along an axis", kPeriodicKeys,
     kGuide, "## Periodic directions: `[[sph.periodic]]`"},
    {"sph.wall_map", true, "the wall pressure and friction in bins over a wall's surface",
     particles::kWallMapKeys, kGuide, "## `[[sph.wall_map]]`"},
    {"phase", true, "a named stage of the run (fill, settle, discharge) that starts on an event",
     particles::kPhaseKeys, kGuide, "## Phases: `[[phase]]`"},
}};

} // namespace

std::span<const io::KeyTable> sph_key_tables() {
    return kTables;
}

} // namespace grainload::sph
