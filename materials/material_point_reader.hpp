#pragma once
// A material-point driver file (one [[material]] and a [path]): read, driven and written.

#include "io/key_spec.hpp"
#include "materials/material_point_driver.hpp"

#include <array>
#include <string>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::materials {

/// The keys of a driver file's [path] table.
inline constexpr std::array<io::KeySpec, 3> kPathKeys{{
    {"initial_stress", "pressure list (xx yy zz xy yz zx)", "0 Pa",
     "the stress before the first segment", 0.0},
    {"tolerance", "number in (0, 1e-2)", "1e-10",
     "the Newton tolerance on the stress of the controlled components, relative to the stress "
     "level",
     1e-10},
    {"max_iterations", "integer >= 1", "25", "Newton iterations per step", 25.0},
}};

/// The keys of each [[path.segment]]: `strain_increment` and `stress` are tables of Voigt
/// components (xx yy zz xy yz zx), each component in one of them at most.
inline constexpr std::array<io::KeySpec, 3> kSegmentKeys{{
    {"steps", "integer >= 1", "", "equal sub-steps of the segment"},
    {"strain_increment", "table of numbers by component", "none",
     "the total strain increment of each component it names, over the segment"},
    {"stress", "table of pressures by component", "none",
     "the stress of each component it names at the end of the segment"},
}};

/// Read the [path] table of a driver file (format: docs/user-guide/matpoint.md).
MaterialPointPath read_material_point_path(const io::CaseTable& path_table);

/// `grainload matpoint DRIVER.toml --out FILE.csv`: read the driver (one [[material]] and a
/// [path]), run it and write the CSV. Returns 0 on success and 1 when the path cannot be
/// followed (the rows computed so far are still written); io::CaseError propagates.
/// `notices`: the lines for the user on stderr, in order (the reading's warnings, then the
/// path's failure), filled also when it throws.
int run_material_point(const std::string& driver_file, const std::string& csv_out,
                       std::vector<std::string>& notices);

} // namespace grainload::materials
