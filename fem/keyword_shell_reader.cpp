#include "fem/keyword_shell_reader.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace grainload::fem {

namespace {

using io::KeywordError;
using io::KeywordId;

/// Mean thickness of a shell: its own nodal values where given and > 0, else the section's.
double element_thickness(const io::KeywordShell& shell, const io::KeywordShellSection& section) {
    const bool triangle = shell.nodes[3] == shell.nodes[2];
    const int corners = triangle ? 3 : 4;
    double sum = 0.0;
    for (int n = 0; n < corners; ++n) {
        const auto k = static_cast<std::size_t>(n);
        const double own = shell.thickness ? (*shell.thickness)[k] : 0.0;
        sum += own > 0.0 ? own : section.thickness[k];
    }
    return sum / corners;
}

const io::KeywordShellSection& section_of(const io::KeywordMesh& deck, KeywordId part_id) {
    const auto part = deck.parts.find(part_id);
    if (part == deck.parts.end()) {
        throw KeywordError("part " + std::to_string(part_id) +
                           " holds shell elements but has no *PART card (its section, and so "
                           "its thickness, is unknown)");
    }
    const auto section = deck.sections.find(part->second.section);
    if (section == deck.sections.end()) {
        throw KeywordError(part->second.source.text() + ": *PART " + std::to_string(part_id) +
                           ": SECID " + std::to_string(part->second.section) +
                           " is not a *SECTION_SHELL");
    }
    return section->second;
}

/// Adds sets by name; the same name twice is refused, as one would hide the other.
class SetNames {
  public:
    explicit SetNames(ShellMesh& mesh) : mesh_(mesh) {}

    void add_nodes(const std::string& name, std::vector<Index> nodes, const std::string& where) {
        claim(node_names_, name, where);
        mesh_.add_node_set(name, std::move(nodes));
    }
    void add_elements(const std::string& name, std::vector<Index> elements,
                      const std::string& where) {
        claim(element_names_, name, where);
        mesh_.add_element_set(name, std::move(elements));
    }

  private:
    static void claim(std::map<std::string, std::string>& names, const std::string& name,
                      const std::string& where) {
        const auto [it, fresh] = names.emplace(name, where);
        if (!fresh) {
            throw KeywordError(where + ": a set named \"" + name + "\" is already defined (" +
                               it->second + "); give the sets different titles");
        }
    }

    ShellMesh& mesh_;
    std::map<std::string, std::string> node_names_, element_names_;
};

std::string set_name(const io::KeywordSet& set) {
    return set.title.empty() ? "set" + std::to_string(set.id) : set.title;
}

void add_sets(const io::KeywordMesh& deck, const std::vector<KeywordId>& parts,
              const std::map<KeywordId, Index>& node_index,
              const std::map<KeywordId, Index>& element_index,
              const std::vector<KeywordId>& element_part, ShellMesh& mesh) {
    SetNames names(mesh);
    for (const KeywordId id : parts) {
        std::vector<Index> elements;
        std::set<Index> nodes;
        for (Index e = 0; e < mesh.element_count(); ++e) {
            if (element_part[static_cast<std::size_t>(e)] == id) {
                elements.push_back(e);
                const auto& n = mesh.element(e).nodes;
                nodes.insert(n.begin(), n.end());
            }
        }
        const io::KeywordPart& part = deck.parts.at(id);
        const std::string name = part.title.empty() ? "part" + std::to_string(id) : part.title;
        names.add_elements(name, std::move(elements), part.source.text());
        names.add_nodes(name, {nodes.begin(), nodes.end()}, part.source.text());
    }
    const auto members = [](const io::KeywordSet& set, const std::map<KeywordId, Index>& index) {
        std::vector<Index> found;
        for (const KeywordId id : set.members) {
            const auto it = index.find(id);
            if (it != index.end()) {
                found.push_back(it->second);
            }
        }
        return found;
    };
    for (const io::KeywordSet& set : deck.node_sets) {
        if (auto nodes = members(set, node_index); !nodes.empty()) {
            names.add_nodes(set_name(set), std::move(nodes), set.source.text());
        }
    }
    for (const io::KeywordSet& set : deck.shell_sets) {
        if (auto elements = members(set, element_index); !elements.empty()) {
            names.add_elements(set_name(set), std::move(elements), set.source.text());
        }
    }
}

} // namespace

ShellMesh make_keyword_shell_mesh(const io::KeywordMesh& deck,
                                  const std::vector<std::string>& part_names) {
    std::vector<KeywordId> with_shells;
    for (const io::KeywordShell& shell : deck.shells) {
        if (std::find(with_shells.begin(), with_shells.end(), shell.part) == with_shells.end()) {
            with_shells.push_back(shell.part);
        }
    }
    std::sort(with_shells.begin(), with_shells.end());
    const std::string file =
        deck.shells.empty() ? std::string("LS-DYNA deck") : deck.shells.front().source.file;
    const std::vector<KeywordId> parts =
        io::select_parts(deck, part_names, with_shells, "shell", file);
    const std::set<KeywordId> selected(parts.begin(), parts.end());
    std::set<KeywordId> used;
    for (const io::KeywordShell& shell : deck.shells) {
        if (selected.contains(shell.part)) {
            used.insert(shell.nodes.begin(), shell.nodes.end());
        }
    }
    ShellMesh mesh;
    std::map<KeywordId, Index> node_index, element_index;
    for (std::size_t k = 0; k < deck.node_ids.size(); ++k) {
        if (used.contains(deck.node_ids[k])) {
            node_index[deck.node_ids[k]] = mesh.add_node(deck.nodes[k]);
        }
    }
    std::vector<KeywordId> element_part;
    for (const io::KeywordShell& shell : deck.shells) {
        if (!selected.contains(shell.part)) {
            continue;
        }
        std::array<Index, 4> nodes{};
        for (std::size_t n = 0; n < 4; ++n) {
            nodes[n] = node_index.at(shell.nodes[n]);
        }
        element_index[shell.id] =
            mesh.add_element(nodes, element_thickness(shell, section_of(deck, shell.part)));
        element_part.push_back(shell.part);
    }
    add_sets(deck, parts, node_index, element_index, element_part, mesh);
    return mesh;
}

} // namespace grainload::fem
