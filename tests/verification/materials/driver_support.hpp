#pragma once
// Material-point drivers run from text or a file for the verification tests.

// Runs a material-point driver given as TOML text or as a file, for the verification tests.

#include "io/case_table.hpp"
#include "materials/material_case_reader.hpp"
#include "materials/material_point_reader.hpp"

#include <memory>
#include <string>
#include <vector>

namespace grainload::materials::testing {

struct DriverRun {
    std::unique_ptr<Material> material;
    std::vector<MaterialPointRecord> records;
};

inline DriverRun run_driver(io::CaseDocument& document) {
    const io::CaseTable root = document.root();
    DriverRun run{read_material(root.array_of_tables("material").front()), {}};
    drive_material_point(*run.material, read_material_point_path(root.table("path")), run.records);
    return run;
}

inline DriverRun run_driver_text(const std::string& text) {
    return run_driver(*io::CaseDocument::from_string(text, "driver.toml"));
}

inline DriverRun run_driver_file(const std::string& file) {
    return run_driver(*io::CaseDocument::from_file(file));
}

} // namespace grainload::materials::testing
