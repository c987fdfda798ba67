#pragma once
// The particle floor's scene parts as a case states them: sinks, the settle watch and phases.

#include "io/key_spec.hpp"
#include "particles/phase_sequence.hpp"
#include "particles/settle_watch.hpp"
#include "particles/sink.hpp"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::particles {

/// The keys of each [[sph.sink]] and [[dem.sink]] table (docs/user-guide/sph.md, "Sinks").
inline constexpr std::array<io::KeySpec, 10> kSinkKeys{{
    {"name", "string", "", "names the sink in discharge.csv and summary.json"},
    {"type", "`plane` or `box`", "",
     "plane: the particles beyond a plane leave; box: the particles inside a box leave"},
    {"point", "length vector", "required for a plane", "a point of the plane"},
    {"normal", "vector", "required for a plane",
     "points out of the scene: particles on the side it points to leave"},
    {"min", "length vector", "required for a box", "the box's lower corner"},
    {"max", "length vector", "required for a box",
     "the box's upper corner, above min on every axis"},
    {"body", "string", "every body",
     "only the particles of the body of this name leave through the sink"},
    {"outlet_width", "length", "none",
     "the effective width of the outlet the sink drains (a slot's width, a circle's diameter): "
     "gives the steady rate Beverloo's figure as its reference and `grainload check` a "
     "discharge law"},
    {"outlet_length", "length", "3D: a circle",
     "3D: the length of a rectangular slot outlet; without it the outlet is circular"},
    {"bulk_density", "density", "required with outlet_width",
     "the flowing material's bulk density in Beverloo's law"},
}};

/// The keys of [sph.settle] (docs/user-guide/sph.md, "Settling: `[sph.settle]`").
inline constexpr std::array<io::KeySpec, 2> kSettleKeys{{
    {"kinetic_energy_fraction", "number", "",
     "settled: the material's kinetic energy below this fraction of its peak so far"},
    {"after", "time", "0 s", "the watch starts (e.g. when the sources stop)", 0.0},
}};

/// The keys of each [[phase]] table (docs/user-guide/sph.md, "Phases: `[[phase]]`").
inline constexpr std::array<io::KeySpec, 4> kPhaseKeys{{
    {"name", "string", "",
     "names the phase in log.txt and summary.json; `phase:NAME` in a time key is its start"},
    {"end", "time, `settled` or `discharged`", "the run's end (last phase only)",
     "the phase ends with the first step that reaches this time, that settles the scene, or "
     "after which the sinks have taken `discharged_mass` since the phase began"},
    {"kinetic_energy_fraction", "number", "required with `settled`",
     "settled: the material's kinetic energy below this fraction of its peak since t = 0"},
    {"discharged_mass", "mass", "required with `discharged`",
     "the mass the sinks take during the phase (plane strain: per metre of depth, kg/m)"},
}};

/// The bodies of a particle method's scene, indexed by body id, and the case table that
/// declares them ("[[sph.body]]"), which an unknown name's message cites.
struct BodyNames {
    std::string declared_in;
    std::vector<std::string> names;
};

/// The sink tables of `scene` (its [[sink]] array: [[sph.sink]] in `[sph]`, [[dem.sink]] in
/// `[dem]`); `body` keys name `bodies`; `gravity` is the magnitude Beverloo's rate takes,
/// `share` the part of each outlet the model holds (1/2 per symmetry plane through it), `grains`
/// each body's grain size (empty: none). A bad key fails at its line.
SinkSet read_sinks(const io::CaseTable& scene, const BodyNames& bodies, int dimension,
                   double gravity, double share = 1.0,
                   const std::vector<SinkSet::BodyGrain>& grains = {});

/// The watch of a [sph.settle] table.
SettleWatch read_settle_watch(const io::CaseTable& settle);

/// The [[phase]] tables of the case's root (none: an empty sequence).
PhaseSequence read_phases(const io::CaseTable& root);

/// The phase that key `key` of `table` names ("phase:NAME" of `phases`; null: none defined),
/// std::nullopt when the key is absent or holds anything else (a time, read as before). A name
/// no phase has fails at the key, listing the phases.
std::optional<int> read_phase_reference(const io::CaseTable& table, std::string_view key,
                                        const PhaseSequence* phases);

/// Whether a window's end (a source's) follows its start where the case fixes both: two times,
/// or two phases (which begin in the order of the table); a time against a phase (index -1:
/// none) is known only in the run.
bool window_in_order(double start, double end, int start_phase, int end_phase);

} // namespace grainload::particles
