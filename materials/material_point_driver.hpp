#pragma once
// One material point driven along a path of strain- and stress-controlled segments.

#include "materials/material.hpp"

#include <array>
#include <iosfwd>
#include <string>
#include <vector>

namespace grainload::materials {

/// The Voigt components in their order, as a driver file and the CSV name them.
inline constexpr std::array<const char*, 6> kVoigtComponents = {"xx", "yy", "zz", "xy", "yz", "zx"};

/// One segment of a material-point path. Each Voigt component (xx, yy, zz, xy, yz, zx) is either
/// strain controlled (its total engineering strain increment over the segment is prescribed and
/// applied in equal parts) or stress controlled (its value at the end of the segment is
/// prescribed and reached linearly from its value at the start).
struct PathSegment {
    int steps = 1;
    std::array<bool, 6> stress_controlled{};
    Voigt6 strain_increment = Voigt6::Zero();
    Voigt6 stress_target = Voigt6::Zero();
};

struct MaterialPointPath {
    Voigt6 initial_stress = Voigt6::Zero();
    std::vector<PathSegment> segments;
    double tolerance = 0.0; ///< stress residual relative to the current stress level
    int max_iterations = 0;
};

/// One output row: the state at the end of a step (step 0 is the initial state).
struct MaterialPointRecord {
    int step = 0;
    Voigt6 strain = Voigt6::Zero();
    Voigt6 stress = Voigt6::Zero();
    std::vector<double> state;
    PlasticRegion region = PlasticRegion::elastic;
};

/// Run one material point along `path`. The unknown strain components of stress-controlled
/// steps are found by Newton's method with the material's consistent tangent. Throws
/// std::runtime_error naming the step when Newton does not converge; `records` then holds every
/// step completed before it.
void drive_material_point(const Material& material, const MaterialPointPath& path,
                          std::vector<MaterialPointRecord>& records);

/// CSV: step, strain (6), stress (6, Pa), equivalent plastic strain, plastic volumetric strain,
/// cap position (Pa; empty unless the material has a "cap_position" state), region.
void write_material_point_csv(const Material& material,
                              const std::vector<MaterialPointRecord>& records, std::ostream& out);

} // namespace grainload::materials
