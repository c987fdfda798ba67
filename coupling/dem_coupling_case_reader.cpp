// The reader of a DEM-shell scene: [dem], [fem] and [coupling] joined in one DemCoupledModel.
#include "coupling/coupling_case_reader.hpp"
#include "fem/shell_model_reader.hpp"
#include "io/case_table.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace grainload::coupling {

namespace {

/// The [coupling] settings a DEM scene runs: no added mass.
CouplingSettings read_dem_settings(const io::CaseTable& coupling, const fem::ShellModel& fem) {
    const CouplingSettings settings = read_settings(coupling, fem);
    if (settings.added_mass > 0.0) {
        coupling.fail("added_mass", "the added mass is estimated from an SPH scene's sand: "
                                    "expected 0 with [dem]");
    }
    return settings;
}

/// The keys of [[coupling.interface]] and [[coupling.friction]] that lay or rub SPH wall
/// particles, which a DEM scene has none of.
void refuse_sph_keys(const io::CaseTable& coupling, const io::CaseTable& table) {
    for (const char* key : {"spacing", "layers", "bodies"}) {
        if (table.has(key)) {
            table.fail(key, "grains meet a shell's mid-surface as a plate of its thickness, "
                            "with no wall particles: expected no `" +
                                std::string(key) + "` with [dem]");
        }
    }
    if (coupling.has("friction")) {
        coupling.fail("friction", "grains slide on a coupled shell with [dem.contact] "
                                  "wall_friction: expected no [[coupling.friction]] with [dem]");
    }
}

/// One [[coupling.interface]] as a DEM wall added to `walls`: coupled (following the shell and
/// loading it) into `parts`, or rigid (where the shell was built) into `rigid`.
void read_dem_interface(const io::CaseTable& coupling, const io::CaseTable& table,
                        const fem::ShellModel& fem, std::vector<char>& coupled,
                        std::vector<dem::PlaneWall>& walls, std::vector<DemCoupledPart>& parts,
                        std::vector<std::string>& rigid) {
    refuse_sph_keys(coupling, table);
    const auto& names = fem.part_names();
    const int index = part_index(table, "part", names);
    const std::string name = table.string_or("name", names[static_cast<std::size_t>(index)]);
    if (std::any_of(walls.begin(), walls.end(),
                    [&](const dem::PlaneWall& w) { return w.name == name; })) {
        table.fail(table.has("name") ? "name" : "part",
                   "a wall called \"" + name +
                       "\" already exists ([[dem.wall]] or an interface): expected one name "
                       "per wall");
    }
    const fem::ShellMesh& mesh = fem.analysis().mesh();
    std::vector<Index> elements = interface_elements(table, mesh, index, coupled);
    const auto [thinnest, thickest] =
        std::minmax_element(elements.begin(), elements.end(), [&](Index a, Index b) {
            return mesh.element(a).thickness < mesh.element(b).thickness;
        });
    if (mesh.element(*thickest).thickness > mesh.element(*thinnest).thickness * (1.0 + 1e-9)) {
        table.fail(table.has("element_sets") ? "element_sets" : "part",
                   "grains touch an interface as a plate of one thickness: expected elements of "
                   "one thickness (an interface per thickness, by element_sets)");
    }
    const std::string side = table.choice("side", {"positive", "negative", "both"});
    const bool is_rigid =
        table.boolean_or("rigid", io::default_value(kInterfaceKeys, "rigid") != 0.0);
    DemShellWall wall(fem.analysis(), elements);
    walls.push_back(wall.make_wall(fem.analysis(), name, !is_rigid));
    if (is_rigid) {
        rigid.push_back(name);
        return;
    }
    DemCoupledPart part{name, walls.size() - 1, std::move(wall), std::move(elements)};
    part.side = side == "positive"   ? ContactSide::positive
                : side == "negative" ? ContactSide::negative
                                     : ContactSide::both;
    parts.push_back(std::move(part));
}

} // namespace

std::unique_ptr<DemCoupledModel>
read_dem_coupled_model(const io::CaseTable& root, const io::SceneSettings& scene,
                       const materials::MaterialLibrary& materials) {
    const io::CaseTable coupling = root.table("coupling");
    if (!root.has("fem")) {
        coupling.fail("", "a coupling joins the grains and shells: expected [fem] with "
                          "[[fem.shell]] tables");
    }
    auto fem = fem::read_shell_model(root, scene, materials);
    const CouplingSettings settings = read_dem_settings(coupling, *fem);
    dem::DemSettings grains = dem::read_dem_settings(root, materials, scene);
    const auto interfaces = coupling.array_of_tables("interface");
    if (interfaces.empty()) {
        coupling.fail("interface", "expected at least one [[coupling.interface]] table");
    }
    std::vector<char> coupled(static_cast<std::size_t>(fem->analysis().mesh().element_count()), 0);
    std::vector<DemCoupledPart> parts;
    std::vector<std::string> rigid;
    for (const io::CaseTable& table : interfaces) {
        read_dem_interface(coupling, table, *fem, coupled, grains.walls, parts, rigid);
    }
    auto dem = std::make_unique<dem::DemModel>(std::move(grains), scene, materials);
    if (settings.window < dem->stable_time_step() * (1.0 - 1e-9)) {
        std::ostringstream message;
        message << "the coupling window " << settings.window << " s is shorter than the DEM step "
                << dem->stable_time_step() << " s: expected a window of at least one DEM step";
        coupling.fail("window", message.str());
    }
    warn_about_ramp(coupling, *fem, settings, scene.end_time);
    return std::make_unique<DemCoupledModel>(std::move(dem), std::move(fem), std::move(parts),
                                             std::move(rigid), settings);
}

} // namespace grainload::coupling
