#include "materials/material_point_reader.hpp"

#include "io/atomic_file.hpp"
#include "io/case_table.hpp"
#include "materials/material_case_reader.hpp"

#include <stdexcept>

namespace grainload::materials {

namespace {

PathSegment read_segment(const io::CaseTable& table) {
    PathSegment segment;
    const std::int64_t steps = table.integer("steps");
    if (steps < 1) {
        table.fail("steps", "expected at least one step");
    }
    segment.steps = static_cast<int>(steps);
    const auto strains = table.optional_table("strain_increment");
    const auto stresses = table.optional_table("stress");
    for (int i = 0; i < 6; ++i) {
        const char* c = kVoigtComponents[static_cast<std::size_t>(i)];
        const bool by_strain = strains && strains->has(c);
        const bool by_stress = stresses && stresses->has(c);
        if (by_strain && by_stress) {
            stresses->fail(c, "this component is also given in strain_increment; each component "
                              "is either strain or stress controlled");
        }
        if (by_strain) {
            segment.strain_increment(i) = strains->number(c);
        }
        if (by_stress) {
            segment.stress_target(i) = stresses->quantity(c, io::dimension::kPressure);
            segment.stress_controlled[static_cast<std::size_t>(i)] = true;
        }
    }
    return segment;
}

/// run_material_point on the read `document`; the path's failure is its last notice.
int drive_from(io::CaseDocument& document, const std::string& driver_file,
               const std::string& csv_out) {
    const io::CaseTable root = document.root();
    const std::vector<io::CaseTable> materials = root.array_of_tables("material");
    if (materials.size() != 1) {
        root.fail("material", "a material-point driver needs exactly one [[material]] table");
    }
    materials.front().string_or("name", "");
    const auto material = read_material(materials.front());
    const MaterialPointPath path = read_material_point_path(root.table("path"));
    document.reject_unknown_keys();

    std::vector<MaterialPointRecord> records;
    int code = 0;
    try {
        drive_material_point(*material, path, records);
    } catch (const io::CaseError&) {
        throw;
    } catch (const std::runtime_error& error) {
        document.notify(driver_file + ": " + error.what());
        code = 1;
    }
    io::write_file_atomically(
        csv_out, [&](std::ostream& out) { write_material_point_csv(*material, records, out); });
    return code;
}

} // namespace

MaterialPointPath read_material_point_path(const io::CaseTable& table) {
    MaterialPointPath path;
    if (table.has("initial_stress")) {
        const std::vector<double> s =
            table.quantity_list("initial_stress", io::dimension::kPressure);
        if (s.size() != 6) {
            table.fail("initial_stress", "expected six components xx yy zz xy yz zx");
        }
        path.initial_stress = Eigen::Map<const Voigt6>(s.data());
    }
    path.tolerance = table.number_or("tolerance", io::default_value(kPathKeys, "tolerance"));
    if (!(path.tolerance > 0.0 && path.tolerance < 1e-2)) {
        table.fail("tolerance", "expected a relative tolerance in (0, 1e-2)");
    }
    path.max_iterations = static_cast<int>(table.integer_or(
        "max_iterations",
        static_cast<std::int64_t>(io::default_value(kPathKeys, "max_iterations"))));
    if (path.max_iterations < 1) {
        table.fail("max_iterations", "expected at least one iteration");
    }
    for (const io::CaseTable& segment : table.array_of_tables("segment")) {
        path.segments.push_back(read_segment(segment));
    }
    if (path.segments.empty()) {
        table.fail("", "expected at least one [[path.segment]]");
    }
    return path;
}

int run_material_point(const std::string& driver_file, const std::string& csv_out,
                       std::vector<std::string>& notices) {
    const auto document = io::CaseDocument::from_file(driver_file);
    int code = 0;
    try {
        code = drive_from(*document, driver_file, csv_out);
    } catch (...) {
        notices = document->take_notices();
        throw;
    }
    notices = document->take_notices();
    return code;
}

} // namespace grainload::materials
