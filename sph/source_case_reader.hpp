#pragma once
// The [[sph.source]] tables of a case, read into the scene's sources.

#include "io/key_spec.hpp"
#include "particles/phase_sequence.hpp"
#include "sph/source.hpp"

#include <array>
#include <string>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::sph {

/// The keys of each [[sph.source]] table (docs/user-guide/sph.md, "Sources").
inline constexpr std::array<io::KeySpec, 9> kSourceKeys{{
    {"name", "string", "", "names the source in log.txt and summary.json"},
    {"body", "string", "", "the [[sph.body]] whose particles (material, spacing) it creates"},
    {"min", "length vector", "", "the lower corner of the box the particles are created in"},
    {"max", "length vector", "", "the box's upper corner, above min by a spacing on every axis"},
    {"shape", "table", "none: min and max",
     "instead of min and max: any [sph.body.shape] (cylinder, cone, mesh, cuts)"},
    {"mass_rate", "mass rate", "", "kg/s created (in plane strain per metre of depth, kg/(m s))"},
    {"start", "time or `phase:NAME`", "0 s", "creation starts (phase:NAME: when that phase begins)",
     0.0},
    {"end", "time or `phase:NAME`", "never", "creation ends (phase:NAME: when that phase begins)"},
    {"velocity", "velocity vector", "0 m/s", "the velocity the new particles start with"},
}};

/// The [[sph.source]] tables of `sph`. `body_material[b]` and `body_density[b]` describe
/// body b; every body has `spacing`. A source's region is its box (min, max) or any body
/// shape ([sph.source.shape]: a cylinder for a silo); its sites are taken lowest first
/// against `gravity`. `start` and `end` may name the start of one of `phases`.
SourceSet read_sources(const io::CaseTable& sph, const std::vector<std::string>& body_names,
                       const std::vector<int>& body_material,
                       const std::vector<double>& body_density, double spacing, int dimension,
                       const Vec3& gravity, const particles::PhaseSequence* phases = nullptr);

} // namespace grainload::sph
