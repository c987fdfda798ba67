#pragma once
// One material point driven along a path of strain- and stress-controlled segments.

#include "materials/material.hpp"

#include <array>
#include <iosfwd>
#include <string>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::materials {

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
    double tolerance = 1e-10; ///< stress residual relative to the current stress level
    int max_iterations = 25;
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

/// Read the [path] table of a driver file (format: docs/user-guide/matpoint.md).
MaterialPointPath read_material_point_path(const io::CaseTable& path_table);

/// CSV: step, strain (6), stress (6, Pa), equivalent plastic strain, plastic volumetric strain,
/// cap position (Pa; empty unless the material has a "cap_position" state), region.
void write_material_point_csv(const Material& material,
                              const std::vector<MaterialPointRecord>& records, std::ostream& out);

/// `grainload matpoint DRIVER.toml --out FILE.csv`: read the driver (one [[material]] and a
/// [path]), run it and write the CSV. Returns 0 on success and 1 when the path cannot be
/// followed (the rows computed so far are still written); io::CaseError propagates.
/// `notices`: the lines for the user on stderr, in order (the reading's warnings, then the
/// path's failure), filled also when it throws.
int run_material_point(const std::string& driver_file, const std::string& csv_out,
                       std::vector<std::string>& notices);

} // namespace grainload::materials
