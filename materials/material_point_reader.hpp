#pragma once
// A material-point driver file (one [[material]] and a [path]): read, driven and written.

#include "materials/material_point_driver.hpp"

#include <string>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::materials {

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
