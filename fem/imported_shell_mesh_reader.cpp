#include "fem/imported_shell_mesh_reader.hpp"

#include "fem/gmsh_reader.hpp"
#include "fem/keyword_shell_reader.hpp"
#include "io/case_table.hpp"
#include "io/deck_ledger.hpp"
#include "io/gmsh_runner.hpp"
#include "io/keyword_deck.hpp"
#include "io/keyword_mesh.hpp"

namespace grainload::fem {

namespace {

namespace dim = io::dimension;

ShellMesh read_gmsh_shell(const io::CaseTable& shell) {
    GroupThickness groups;
    for (const io::CaseTable& group : shell.array_of_tables("group")) {
        const std::string name = group.string("name");
        if (!groups.emplace(name, group.positive_quantity("thickness", dim::kLength)).second) {
            group.fail("name", "group \"" + name + "\" already has a thickness");
        }
    }
    // With groups, elements outside them need the shell's thickness only if there are any.
    const double thickness = groups.empty() ? shell.positive_quantity("thickness", dim::kLength)
                             : shell.has("thickness")
                                 ? shell.positive_quantity("thickness", dim::kLength)
                                 : 0.0;
    const std::string msh =
        shell.has("geo") ? shell.resolved_path("file") : shell.file_path("file");
    if (shell.has("geo")) {
        const std::string geo = shell.file_path("geo");
        std::vector<std::pair<std::string, double>> numbers;
        if (const auto table = shell.optional_table("geo_numbers")) {
            for (const std::string& name : table->keys()) {
                numbers.emplace_back(name, table->number(name));
            }
        }
        try {
            if (io::ensure_gmsh_mesh(geo, msh, numbers)) {
                shell.notify("grainload: meshed " + geo + " with gmsh into " + msh);
            }
        } catch (const std::invalid_argument& e) {
            shell.fail("geo", e.what());
        }
    }
    try {
        return read_gmsh_file(msh, thickness, groups);
    } catch (const std::invalid_argument& e) {
        shell.fail("file", e.what());
    }
}

ShellMesh read_lsdyna_shell(const io::CaseTable& shell) {
    std::string error;
    const auto units = io::parse_keyword_units(shell.string("units"), &error);
    if (!units) {
        shell.fail("units", error);
    }
    const std::vector<std::string> parts =
        shell.has("parts") ? shell.name_list("parts") : std::vector<std::string>{};
    const std::string path = shell.file_path("file");
    io::open_keyword_deck(shell, path, *units);
    io::KeywordMesh deck;
    try {
        deck = io::read_keyword_mesh(io::read_keyword_deck(path), *units);
    } catch (const std::invalid_argument& e) {
        shell.fail("file", e.what());
    }
    shell.deck_ledger().leave(path, deck.ignored);
    try {
        return make_keyword_shell_mesh(deck, parts);
    } catch (const std::invalid_argument& e) {
        shell.fail(shell.has("parts") ? "parts" : "file", e.what());
    }
}

} // namespace

ShellMesh read_imported_shell_mesh(const io::CaseTable& shell, const std::string& generator) {
    return generator == "lsdyna" ? read_lsdyna_shell(shell) : read_gmsh_shell(shell);
}

} // namespace grainload::fem
