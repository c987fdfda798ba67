#pragma once
// The [dem] tables of a case: their keys, declared once, read into typed settings.

#include "dem/contact_law.hpp"
#include "dem/dem_body_reader.hpp"
#include "dem/plane_wall.hpp"
#include "dem/triaxial_reader.hpp"
#include "io/key_spec.hpp"
#include "io/types.hpp"
#include "particles/phase_sequence.hpp"
#include "particles/sink.hpp"
#include "particles/wall_map.hpp"

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace grainload::io {
class CaseTable;
struct SceneSettings;
} // namespace grainload::io
namespace grainload::materials {
class MaterialLibrary;
}

namespace grainload::dem {

/// The keys of [dem] (docs/user-guide/dem.md).
inline constexpr std::array<io::KeySpec, 8> kDemKeys{{
    {"time_step", "time", "the contact time / steps_per_contact",
     "a fixed step instead of the one from the contact time"},
    {"steps_per_contact", "number in [10, 10000]", "100",
     "steps per contact duration of the smallest grains (t_c / 100 as in Markauskas' hopper study)",
     100.0},
    {"impact_velocity", "velocity", "1 m/s",
     "Hertz: the contact time is taken at the faster of this and twice the fastest grain's speed",
     1.0},
    {"skin", "length", "0.4 × the largest radius",
     "the neighbour list's Verlet skin, rebuilt when a grain has moved half of it"},
    {"contact_forces", "boolean", "false",
     "frames carry a `contacts` block: a line per contact with its force (force chains)"},
    {"integrator", "`velocity_verlet` or `predictor_corrector`", "velocity_verlet",
     "predictor_corrector: Lazarevic, Dvornik & Fresl's constant-acceleration predictor and "
     "linear-acceleration corrector"},
    {"corrector_passes", "integer in [1, 100]", "1",
     "predictor_corrector: the most corrector passes a step makes (1: the explicit form)", 1.0},
    {"corrector_tolerance", "number > 0", "0.1",
     "predictor_corrector: a step stops correcting when no grain's acceleration changed by more "
     "than this fraction of g in its last pass",
     0.1},
}};

/// The keys of [dem.contact].
inline constexpr std::array<io::KeySpec, 13> kDemContactKeys{{
    {"law", "`linear` or `hertz_mindlin`", "",
     "linear: a Kelvin-Voigt spring and dashpot; hertz_mindlin: Hertz's normal and Mindlin's "
     "tangential stiffness from the grains' E and nu"},
    {"normal_stiffness", "force per length", "required for `linear`", "k_n of the linear law"},
    {"tangential_stiffness_ratio", "number in [0, 1]", "2/7", "k_t / k_n of the linear law",
     2.0 / 7.0},
    {"gamma_n", "frequency", "0 1/s", "normal damping per unit effective mass: c_n = gamma_n m*"},
    {"gamma_t", "frequency", "0 1/s", "tangential damping per unit effective mass"},
    {"restitution", "number in (0, 1]", "none",
     "instead of gamma_n: the coefficient of restitution of every pair, at any speed"},
    {"friction", "number >= 0", "0", "Coulomb's coefficient between grains"},
    {"wall_friction", "number >= 0", "friction", "Coulomb's coefficient between grain and wall"},
    {"rolling_friction", "number >= 0", "0",
     "mu_r between grains: a rolling grain meets the torque mu_r R* f_n (Ai et al. 2011, model C)"},
    {"wall_rolling_friction", "number >= 0", "rolling_friction", "mu_r between grain and wall"},
    {"rolling_damping", "number in [0, 1]", "0.3",
     "the rolling dashpot's damping ratio below full mobilisation", 0.3},
    {"cohesion_share", "number in [0, 1]", "0",
     "`linear` only: grains parting pull up to this share of the lighter one's weight "
     "(Lazarevic et al. 2002)"},
    {"wall_cohesion_share", "number in [0, 1]", "cohesion_share",
     "the same between a grain and a wall, of the grain's weight"},
}};

/// The keys of each [[dem.wall]].
inline constexpr std::array<io::KeySpec, 14> kDemWallKeys{{
    {"name", "string", "", "names the wall in wall_forces.csv and summary.json"},
    {"type", "`plane`, `rectangle`, `box` or `mesh`", "",
     "an unbounded plane, a rectangular plate, the inside of a box, or a surface mesh"},
    {"point", "length vector", "required for a plane", "a point of the plane"},
    {"normal", "vector", "required for a plane", "points into the material"},
    {"origin", "length vector", "required for a rectangle", "a corner of the rectangle"},
    {"edge_u", "length vector", "required for a rectangle", "the rectangle is origin + s edge_u"},
    {"edge_v", "length vector", "required for a rectangle",
     "+ t edge_v, s and t in [0, 1], edge_v at right angles to edge_u"},
    {"min", "length vector", "required for a box", "the box's inner lower corner"},
    {"max", "length vector", "required for a box", "the box's inner upper corner"},
    {"open_top", "boolean", "true", "a box without its top face", 1.0},
    {"remove_at", "time or `phase:NAME`", "never",
     "the wall leaves the scene at this time or when that phase begins (a gate that opens)"},
    {"velocity", "velocity vector", "0 m/s",
     "the wall translates at this velocity from move_start to move_end"},
    {"move_start", "time", "0 s", "when the wall starts to move"},
    {"move_end", "time", "never", "when it stops, after move_start"},
}};

/// The keys of each [[dem.source]].
inline constexpr std::array<io::KeySpec, 10> kDemSourceKeys{{
    {"name", "string", "", "names the source in summary.json and the log"},
    {"body", "string", "", "the [[dem.body]] whose grains, spheres or clumps, it rains in"},
    {"min", "length vector", "", "the lower corner of the box grains appear in"},
    {"max", "length vector", "", "the upper corner"},
    {"rate", "frequency", "", "grains per second"},
    {"count", "integer >= 1", "none: until end", "grains in all"},
    {"start", "time or `phase:NAME`", "0 s", "when it begins (phase:NAME: when that phase begins)"},
    {"end", "time or `phase:NAME`", "never", "when it stops (phase:NAME: when that phase begins)"},
    {"velocity", "velocity vector", "0 m/s", "each grain's velocity as it appears"},
    {"seed", "integer >= 0", "1", "the draws' seed: equal seeds, equal arrivals", 1.0},
}};

/// One [[dem.source]] as read: grains of `body` appear at `rate` per second in the box
/// [min, max] from `start` to `end`, `count` in all.
struct SourceSettings {
    std::string name;
    int body = -1;
    Vec3 min = Vec3::Zero();
    Vec3 max = Vec3::Zero();
    double rate = 0.0;
    std::optional<Index> count;
    double start = 0.0;
    double end = std::numeric_limits<double>::infinity();
    /// The [[phase]] whose start is `start` (`end`), -1: a time.
    int start_phase = -1;
    int end_phase = -1;
    Vec3 velocity = Vec3::Zero();
    std::uint64_t seed = 1;
};

/// How DemModel integrates the grains' motion ([dem] integrator).
enum class Integrator { velocity_verlet, predictor_corrector };

/// The [dem] tables as read: what DemModel is built from.
struct DemSettings {
    std::optional<double> time_step;
    Integrator integrator = Integrator::velocity_verlet;
    int corrector_passes = 0;
    double corrector_tolerance = 0.0; ///< a fraction of |g|
    double steps_per_contact = 0.0;
    double impact_velocity = 0.0;
    std::optional<double> skin;
    bool contact_forces = false;
    ContactLaw law;
    std::vector<BodySettings> bodies;
    std::vector<PlaneWall> walls;
    /// [dem.triaxial]: a triaxial cell, its six walls the last of `walls`.
    std::optional<TriaxialSettings> triaxial;
    std::vector<SourceSettings> sources;
    /// [[dem.wall_map]]: maps of the walls' pressure and friction (walls by index of `walls`).
    std::vector<particles::WallMapSet::Map> wall_maps;
    /// [[dem.sink]]: the regions grains leave the scene through.
    std::shared_ptr<particles::SinkSet> sinks;
    /// [[phase]]: the run's phases, read before the walls and sources that may name them.
    particles::PhaseSequence phases;
    /// Where the case gives time_step: a step too long for the contacts is refused there.
    std::string time_step_where;
    /// Where the case gives the contact's damping ([dem.contact] gamma_n, else its law): an
    /// over-damped pair is refused there.
    std::string damping_where;
};

/// Reads [dem], [dem.contact], [[dem.body]], [[dem.wall]], [dem.triaxial], [[dem.source]],
/// [[dem.sink]] and
/// the [[phase]] tables of the case; the scene's up axis opens a box's top, its gravity gives
/// the sinks' Beverloo rates. Bad input throws io::CaseError naming the key.
DemSettings read_dem_settings(const io::CaseTable& root,
                              const materials::MaterialLibrary& materials,
                              const io::SceneSettings& scene);

} // namespace grainload::dem
