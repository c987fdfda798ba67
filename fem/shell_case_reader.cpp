#include "fem/shell_case_reader.hpp"

#include "fem/imported_shell_mesh_reader.hpp"
#include "fem/shell_mesh_generators.hpp"
#include "io/case_table.hpp"
#include "io/named_index.hpp"
#include "materials/material_case_reader.hpp"

#include <algorithm>
#include <array>
#include <numbers>
#include <stdexcept>
#include <string>

namespace grainload::fem {

namespace dim = io::dimension;

namespace {

constexpr std::array<std::string_view, 6> kDofNames = {"ux", "uy", "uz", "rx", "ry", "rz"};

int element_count(const io::CaseTable& shell, std::string_view key) {
    const std::int64_t n = shell.integer(key);
    if (n < 1 || n > 100000) {
        shell.fail(key, "expected a number of elements between 1 and 100000");
    }
    return static_cast<int>(n);
}

ShellMesh generate(const io::CaseTable& shell, const std::string& generator, double thickness) {
    if (generator == "plate") {
        return make_plate(shell.positive_quantity("length_x", dim::kLength),
                          shell.positive_quantity("length_y", dim::kLength),
                          element_count(shell, "elements_x"), element_count(shell, "elements_y"),
                          thickness);
    }
    if (generator == "cylinder") {
        return make_cylinder(shell.positive_quantity("radius", dim::kLength),
                             shell.positive_quantity("length", dim::kLength),
                             shell.quantity("angle_start", dim::kAngle),
                             shell.quantity("angle_end", dim::kAngle),
                             element_count(shell, "elements_around"),
                             element_count(shell, "elements_along"), thickness);
    }
    if (generator == "sphere_zone") {
        return make_sphere_zone(shell.positive_quantity("radius", dim::kLength),
                                shell.quantity("polar_start", dim::kAngle),
                                shell.quantity("polar_end", dim::kAngle),
                                shell.positive_quantity("azimuth_end", dim::kAngle),
                                element_count(shell, "elements_polar"),
                                element_count(shell, "elements_around"), thickness);
    }
    if (generator == "box") {
        return make_box(shell.positive_quantity("length_x", dim::kLength),
                        shell.positive_quantity("length_y", dim::kLength),
                        shell.positive_quantity("height", dim::kLength),
                        element_count(shell, "elements_x"), element_count(shell, "elements_y"),
                        element_count(shell, "elements_z"),
                        shell.choice_or("top", {"open", "closed"},
                                        io::default_text(kShellGeneratorKeys, "top")) == "closed",
                        thickness);
    }
    return make_cone(shell.positive_quantity("radius_bottom", dim::kLength),
                     shell.positive_quantity("radius_top", dim::kLength, true),
                     shell.positive_quantity("height", dim::kLength),
                     shell.positive_quantity("azimuth_end", dim::kAngle),
                     element_count(shell, "elements_around"),
                     element_count(shell, "elements_along"), thickness);
}

const std::vector<Index>& node_set(const io::CaseTable& table, const ShellMesh& mesh,
                                   const PartScope& part) {
    const std::string name = table.string("node_set");
    const std::string scoped = part.name + "." + name;
    try {
        return mesh.has_node_set(scoped) ? mesh.node_set(scoped) : mesh.node_set(name);
    } catch (const std::invalid_argument& e) {
        table.fail("node_set", e.what());
    }
}

/// Largest extent of the nodes' bounding box.
double mesh_size(const ShellMesh& mesh) {
    if (mesh.node_count() == 0) {
        return 0.0;
    }
    Vec3 lower = mesh.node(0), upper = mesh.node(0);
    for (const Vec3& x : mesh.nodes()) {
        lower = lower.cwiseMin(x);
        upper = upper.cwiseMax(x);
    }
    return (upper - lower).maxCoeff();
}

/// Selects the history of the table's optional `time_function` (else history 0).
void use_time_function(const io::CaseTable& table, const HistoryNames& histories,
                       ShellAnalysis& analysis) {
    if (!table.has("time_function")) {
        analysis.use_history(0);
        return;
    }
    const std::string name = table.string("time_function");
    const auto found = histories.find(name);
    if (found == histories.end()) {
        table.fail("time_function", "no [[fem.time_function]] named '" + name + "'");
    }
    analysis.use_history(found->second);
}

} // namespace

int read_dof(const io::CaseTable& table, std::string_view key, const std::string& name) {
    for (std::size_t d = 0; d < kDofNames.size(); ++d) {
        if (name == kDofNames[d]) {
            return static_cast<int>(d);
        }
    }
    table.fail(key, "unknown DOF '" + name + "'; expected ux, uy, uz, rx, ry or rz");
}

ShellMesh read_shell_mesh(const io::CaseTable& shell) {
    const std::string generator = shell.choice(
        "generator", {"plate", "cylinder", "sphere_zone", "cone", "box", "gmsh", "lsdyna"});
    const bool imported = generator == "gmsh" || generator == "lsdyna";
    ShellMesh mesh = imported ? read_imported_shell_mesh(shell, generator) : ShellMesh();
    try {
        if (!imported) {
            mesh = generate(shell, generator, shell.positive_quantity("thickness", dim::kLength));
        }
        mesh.validate();
    } catch (const std::invalid_argument& e) {
        shell.fail("generator", e.what());
    }
    // A part placed elsewhere than its generator puts it (a wagon's sheets, a hopper below
    // its silo): every node moves by `offset`, normals and sets stay.
    if (shell.has("offset")) {
        mesh.translate(shell.vector("offset", dim::kLength));
    }
    // Fold lines (box edges, kinks of an imported mesh): see fem/shell_directors.hpp.
    const double fold_angle =
        shell.quantity_or("fold_angle", dim::kAngle, io::default_value(kShellKeys, "fold_angle"));
    if (!(fold_angle > 0.0 && fold_angle <= std::numbers::pi * (1.0 + 1e-12))) {
        shell.fail("fold_angle", "expected an angle in (0 deg, 180 deg]");
    }
    mesh.set_fold_angle(fold_angle);
    return mesh;
}

std::pair<ShellMesh, std::vector<ShellPart>>
read_shell_parts(const io::CaseTable& fem, const std::vector<io::CaseTable>& shells,
                 const materials::MaterialLibrary& materials) {
    std::vector<ShellMesh> meshes;
    std::vector<ShellPart> parts;
    double size = 0.0;
    for (const io::CaseTable& shell : shells) {
        ShellPart part;
        part.name = shell.string_or("name", shells.size() == 1 ? "shell" : "");
        if (part.name.empty()) {
            shell.fail("name", "a structure of several [[fem.shell]] parts names each of them");
        }
        io::refuse_repeated_name(shell, parts, part.name, "shell part", &ShellPart::name);
        part.material = &materials[materials::read_material_index(materials, shell, "material")];
        const bool elastic = part.material->model() == "linear_elastic";
        part.thickness_points =
            static_cast<int>(shell.integer_or("thickness_points", elastic ? 2 : 5));
        if (part.thickness_points < 2 || part.thickness_points > kMaxThicknessPoints) {
            shell.fail("thickness_points", "expected 2 to " + std::to_string(kMaxThicknessPoints) +
                                               " Gauss points through the thickness");
        }
        meshes.push_back(read_shell_mesh(shell));
        size = std::max(size, mesh_size(meshes.back()));
        parts.push_back(std::move(part));
    }
    const double tolerance = fem.positive_quantity_or(
        "seam_tolerance", dim::kLength, io::default_value(kFemKeys, "seam_tolerance") * size);
    ShellMesh structure;
    structure.set_fold_angle(meshes.front().fold_angle());
    for (std::size_t k = 0; k < meshes.size(); ++k) {
        const std::vector<Index> map = structure.append(meshes[k], static_cast<int>(k), tolerance);
        for (const auto& [name, members] : meshes[k].node_sets()) {
            std::vector<Index> nodes;
            for (const Index n : members) {
                nodes.push_back(map[static_cast<std::size_t>(n)]);
            }
            if (!structure.has_node_set(name)) {
                structure.add_node_set(name, nodes);
            }
            structure.add_node_set(parts[k].name + "." + name, std::move(nodes));
        }
        const std::vector<Index> elements = structure.part_elements(static_cast<int>(k));
        for (const auto& [name, members] : meshes[k].element_sets()) {
            std::vector<Index> selected;
            for (const Index e : members) {
                selected.push_back(elements[static_cast<std::size_t>(e)]);
            }
            if (!structure.has_element_set(name)) {
                structure.add_element_set(name, selected);
            }
            structure.add_element_set(parts[k].name + "." + name, std::move(selected));
        }
        structure.add_element_set(parts[k].name, elements);
    }
    return {std::move(structure), std::move(parts)};
}

void read_shell_boundaries(const io::CaseTable& shell, const HistoryNames& histories,
                           const PartScope& part, ShellAnalysis& analysis) {
    for (const io::CaseTable& bc : shell.array_of_tables("boundary")) {
        use_time_function(bc, histories, analysis);
        const std::vector<Index> nodes =
            bc.has("point")
                ? std::vector<Index>{analysis.mesh().nearest_node(bc.vector("point", dim::kLength))}
                : node_set(bc, analysis.mesh(), part);
        if (bc.has("symmetry")) {
            // Symmetry plane with normal along the axis: normal translation and the two
            // in-plane rotation components vanish (a rotation vector is an axial vector).
            const std::string axis = bc.choice("symmetry", {"x", "y", "z"});
            const int a = axis[0] - 'x';
            analysis.prescribe(nodes, {a, 3 + (a + 1) % 3, 3 + (a + 2) % 3});
            continue;
        }
        if (bc.has("angle")) {
            // Rigid rotation of the nodes about an axis (a lifted or tipped edge).
            analysis.prescribe_rigid_rotation(
                nodes, bc.vector("axis", dim::kNone),
                bc.vector_or("axis_point", dim::kLength,
                             io::default_vector(kBoundaryKeys, "axis_point")),
                bc.quantity("angle", dim::kAngle));
            continue;
        }
        // Prescribed values follow the table's history (the load factor by default); zero by
        // default.
        const double displacement = bc.quantity_or(
            "displacement", dim::kLength, io::default_value(kBoundaryKeys, "displacement"));
        const double rotation =
            bc.quantity_or("rotation", dim::kAngle, io::default_value(kBoundaryKeys, "rotation"));
        const std::string dofs = bc.string("dofs");
        std::vector<int> selected;
        std::size_t start = 0;
        while (start < dofs.size()) {
            const std::size_t end = std::min(dofs.find(' ', start), dofs.size());
            const std::string name = dofs.substr(start, end - start);
            if (name == "all") {
                selected = {0, 1, 2, 3, 4, 5};
            } else if (!name.empty()) {
                selected.push_back(read_dof(bc, "dofs", name));
            }
            start = end + 1;
        }
        if (selected.empty()) {
            bc.fail("dofs", "expected DOF names (ux uy uz rx ry rz) or \"all\"");
        }
        for (const int d : selected) {
            for (const Index n : nodes) {
                analysis.prescribe(n, d, d < 3 ? displacement : rotation);
            }
        }
    }
    analysis.use_history(0);
}

void read_shell_loads(const io::CaseTable& shell, const Vec3& case_gravity,
                      const HistoryNames& histories, const PartScope& part,
                      ShellAnalysis& analysis) {
    analysis.use_part(part.index);
    for (const io::CaseTable& load : shell.array_of_tables("load")) {
        use_time_function(load, histories, analysis);
        const std::string type = load.choice(
            "type", {"area_force", "pressure", "gravity", "nodal_force", "nodal_moment"});
        if (type == "area_force") {
            analysis.add_area_load(load.vector("value", dim::kPressure));
        } else if (type == "pressure") {
            const double pressure = load.quantity("value", dim::kPressure);
            if (load.boolean_or("follower", io::default_value(kLoadKeys, "follower") != 0.0)) {
                analysis.add_follower_pressure(pressure);
            } else {
                analysis.add_pressure(pressure);
            }
        } else if (type == "gravity") {
            analysis.add_gravity(load.vector_or("acceleration", dim::kAcceleration, case_gravity));
        } else {
            const bool force = type == "nodal_force";
            const Vec3 value = load.vector("value", force ? dim::kForce : dim::kMoment);
            std::vector<Index> nodes;
            if (load.has("point")) {
                nodes.push_back(analysis.mesh().nearest_node(load.vector("point", dim::kLength)));
            } else {
                nodes = node_set(load, analysis.mesh(), part);
            }
            for (const Index n : nodes) {
                for (int d = 0; d < 3; ++d) {
                    analysis.add_nodal_load(n, (force ? 0 : 3) + d, value(d));
                }
            }
        }
    }
    analysis.use_history(0);
    analysis.use_part(-1);
}

std::vector<ShellReaction> read_shell_reactions(const io::CaseTable& shell, const ShellMesh& mesh,
                                                const PartScope& part) {
    std::vector<ShellReaction> reactions;
    for (const io::CaseTable& table : shell.array_of_tables("reaction")) {
        reactions.push_back({table.string("name"), node_set(table, mesh, part)});
    }
    return reactions;
}

std::vector<ShellMonitor> read_shell_monitors(const io::CaseTable& shell, const ShellMesh& mesh) {
    std::vector<ShellMonitor> monitors;
    for (const io::CaseTable& table : shell.array_of_tables("monitor")) {
        ShellMonitor m;
        m.name = table.string("name");
        m.node = mesh.nearest_node(table.vector("point", dim::kLength));
        m.dof = read_dof(table, "dof", table.string("dof"));
        m.magnitude =
            table.boolean_or("magnitude", io::default_value(kMonitorKeys, "magnitude") != 0.0);
        if (table.has("reference")) {
            m.reference = table.quantity("reference", m.dof < 3 ? dim::kLength : dim::kAngle);
        }
        m.source = table.string_or("source", "");
        monitors.push_back(std::move(m));
    }
    return monitors;
}

std::map<std::string, TimeFunction> read_time_functions(const io::CaseTable& fem) {
    std::map<std::string, TimeFunction> functions;
    for (const io::CaseTable& table : fem.array_of_tables("time_function")) {
        const std::string name = table.string("name");
        if (functions.count(name) != 0) {
            table.fail("name", "time function '" + name + "' is defined twice");
        }
        const std::string type = table.choice_or("type", {"points", "ramp"},
                                                 io::default_text(kTimeFunctionKeys, "type"));
        try {
            functions.emplace(
                name, type == "ramp"
                          ? TimeFunction::ramp(table.positive_quantity("ramp_time", dim::kTime))
                          : TimeFunction(table.quantity_pairs("points", dim::kTime, dim::kNone)));
        } catch (const std::invalid_argument& e) {
            table.fail("points", e.what());
        }
    }
    return functions;
}

} // namespace grainload::fem
