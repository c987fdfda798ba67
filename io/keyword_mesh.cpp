#include "io/keyword_mesh.hpp"

#include "io/keyword_fields.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <set>

namespace grainload::io {

namespace {

// Card layouts of LS-DYNA Keyword User's Manual Vol. I (R13): field names and standard widths.
constexpr std::array<FieldSpec, 6> kNodeCard{
    {{"NID", 8}, {"X", 16}, {"Y", 16}, {"Z", 16}, {"TC", 8}, {"RC", 8}}};
constexpr std::array<FieldSpec, 10> kShellCard{{{"EID", 8},
                                                {"PID", 8},
                                                {"N1", 8},
                                                {"N2", 8},
                                                {"N3", 8},
                                                {"N4", 8},
                                                {"N5", 8},
                                                {"N6", 8},
                                                {"N7", 8},
                                                {"N8", 8}}};
constexpr std::array<FieldSpec, 5> kShellThicknessCard{
    {{"THIC1", 16}, {"THIC2", 16}, {"THIC3", 16}, {"THIC4", 16}, {"BETA", 16}}};
constexpr std::array<FieldSpec, 8> kSectionCard1{{{"SECID", 10},
                                                  {"ELFORM", 10},
                                                  {"SHRF", 10},
                                                  {"NIP", 10},
                                                  {"PROPT", 10},
                                                  {"QR/IRID", 10},
                                                  {"ICOMP", 10},
                                                  {"SETYP", 10}}};
constexpr std::array<FieldSpec, 8> kSectionCard2{{{"T1", 10},
                                                  {"T2", 10},
                                                  {"T3", 10},
                                                  {"T4", 10},
                                                  {"NLOC", 10},
                                                  {"MAREA", 10},
                                                  {"IDOF", 10},
                                                  {"EDGSET", 10}}};
constexpr std::array<FieldSpec, 8> kPartCard{{{"PID", 10},
                                              {"SECID", 10},
                                              {"MID", 10},
                                              {"EOSID", 10},
                                              {"HGID", 10},
                                              {"GRAV", 10},
                                              {"ADPOPT", 10},
                                              {"TMID", 10}}};
constexpr std::array<FieldSpec, 6> kSetCard{
    {{"SID", 10}, {"DA1", 10}, {"DA2", 10}, {"DA3", 10}, {"DA4", 10}, {"SOLVER", 10}}};
constexpr std::array<FieldSpec, 8> kSetMembersCard{{{"ID1", 10},
                                                    {"ID2", 10},
                                                    {"ID3", 10},
                                                    {"ID4", 10},
                                                    {"ID5", 10},
                                                    {"ID6", 10},
                                                    {"ID7", 10},
                                                    {"ID8", 10}}};
constexpr std::array<FieldSpec, 4> kSphCard{{{"NID", 8}, {"PID", 8}, {"MASS", 16}, {"NEND", 8}}};

KeywordSource source_of(const KeywordCard& card) {
    return {card.file, card.line};
}

/// A card's fields that must be > 0 (ids, thicknesses).
KeywordId positive_id(const CardFields& fields, std::size_t i) {
    const KeywordId id = fields.integer(i);
    if (id <= 0) {
        fields.fail(i, "expected an id > 0, got " + std::to_string(id));
    }
    return id;
}

bool is_blank_card(const KeywordCard& card) {
    return card.text.find_first_not_of(' ') == std::string::npos;
}

class MeshReader {
  public:
    MeshReader(const KeywordUnits& units) : units_(units) {}

    KeywordMesh read(const KeywordDeck& deck) {
        for (const Keyword* node : deck.find("NODE")) {
            node_cards_ += static_cast<KeywordId>(node->cards.size());
        }
        for (const Keyword& keyword : deck.keywords) {
            read_keyword(keyword);
        }
        for (const KeywordShell& shell : mesh_.shells) {
            for (const KeywordId node : shell.nodes) {
                mesh_.node(node,
                           shell.source.text() + ": *ELEMENT_SHELL " + std::to_string(shell.id));
            }
        }
        return std::move(mesh_);
    }

  private:
    void read_keyword(const Keyword& k) {
        const std::string& name = k.name;
        if (name == "NODE") {
            read_nodes(k);
        } else if (name == "ELEMENT_SHELL" || name == "ELEMENT_SHELL_THICKNESS") {
            read_shells(k, name == "ELEMENT_SHELL_THICKNESS");
        } else if (name == "SECTION_SHELL" || name == "SECTION_SHELL_TITLE") {
            read_sections(k);
        } else if (name == "PART") {
            read_parts(k);
        } else if (name == "SET_NODE_LIST" || name == "SET_NODE_LIST_TITLE") {
            mesh_.node_sets.push_back(read_set(k, node_set_ids_));
        } else if (name == "SET_SHELL_LIST" || name == "SET_SHELL_LIST_TITLE") {
            mesh_.shell_sets.push_back(read_set(k, shell_set_ids_));
        } else if (name == "ELEMENT_SPH" || name == "ELEMENT_SPH_VOLUME") {
            read_particles(k, name == "ELEMENT_SPH_VOLUME");
        } else if (name.starts_with("ELEMENT_SHELL_") || name.starts_with("SECTION_SHELL_") ||
                   name.starts_with("PART_") || name.starts_with("ELEMENT_SPH_")) {
            throw KeywordError(k.where() + ": this variant is not supported (its cards would "
                                           "change the mesh grainload reads): use *NODE, "
                                           "*ELEMENT_SHELL(_THICKNESS), *SECTION_SHELL(_TITLE), "
                                           "*PART, *ELEMENT_SPH(_VOLUME)");
        } else {
            mesh_.ignored.push_back({"*" + name, k.file, k.line});
        }
    }

    void read_nodes(const Keyword& k) {
        for (const KeywordCard& card : k.cards) {
            const CardFields f(k, card, kNodeCard);
            const KeywordId id = positive_id(f, 0);
            if (!mesh_.node_index.emplace(id, mesh_.nodes.size()).second) {
                f.fail(0, "node " + std::to_string(id) + " is defined twice");
            }
            mesh_.node_ids.push_back(id);
            mesh_.nodes.push_back(units_.length *
                                  Vec3(f.real_or(1, 0.0), f.real_or(2, 0.0), f.real_or(3, 0.0)));
            if (f.real_or(4, 0.0) != 0.0 || f.real_or(5, 0.0) != 0.0) {
                mesh_.ignored.push_back({"*NODE TC/RC constraints", card.file, card.line});
            }
        }
    }

    void read_shells(const Keyword& k, bool with_thickness) {
        const std::size_t per_element = with_thickness ? 2 : 1;
        if (k.cards.size() % per_element != 0) {
            throw KeywordError(k.where(k.cards.back()) +
                               ": expected a thickness card (THIC1..THIC4) after it");
        }
        for (std::size_t c = 0; c < k.cards.size(); c += per_element) {
            const CardFields f(k, k.cards[c], kShellCard);
            KeywordShell shell;
            shell.id = positive_id(f, 0);
            shell.part = positive_id(f, 1);
            shell.source = source_of(k.cards[c]);
            for (std::size_t n = 0; n < 3; ++n) {
                shell.nodes[n] = positive_id(f, 2 + n);
            }
            // LS-DYNA's triangle: N4 = N3 (a blank N4 reads as 0, the same triangle).
            shell.nodes[3] = f.integer_or(5, 0) == 0 ? shell.nodes[2] : positive_id(f, 5);
            for (std::size_t n = 6; n < 10; ++n) {
                if (f.integer_or(n, 0) != 0) {
                    f.fail(n, "8-node shells are not supported: expected 3 or 4 nodes");
                }
            }
            if (with_thickness) {
                const CardFields t(k, k.cards[c + 1], kShellThicknessCard);
                std::array<double, 4> thickness{};
                for (std::size_t n = 0; n < 4; ++n) {
                    thickness[n] = units_.length * t.real_or(n, 0.0);
                    if (thickness[n] < 0.0) {
                        t.fail(n, "expected a thickness >= 0 (0: the section's)");
                    }
                }
                shell.thickness = thickness;
            }
            if (!shell_ids_.insert(shell.id).second) {
                f.fail(0, "shell element " + std::to_string(shell.id) + " is defined twice");
            }
            mesh_.shells.push_back(shell);
        }
    }

    /// Cards of one section: [title], card 1, card 2, ICOMP = 1 angle cards.
    void read_sections(const Keyword& k) {
        std::size_t c = 0;
        while (c < k.cards.size()) {
            KeywordShellSection section;
            if (k.has_title()) {
                section.title = card_title(k.cards[c++]);
            }
            if (c + 1 >= k.cards.size()) {
                throw KeywordError(k.where() + ": expected two cards per section (SECID ELFORM "
                                               "... and T1 T2 T3 T4 ...)");
            }
            const CardFields f1(k, k.cards[c], kSectionCard1);
            section.id = positive_id(f1, 0);
            section.element_form = static_cast<int>(f1.integer_or(1, 0));
            section.source = source_of(k.cards[c]);
            if (section.element_form >= 101 && section.element_form <= 105) {
                f1.fail(1, "user-defined shell elements (ELFORM 101-105) are not supported");
            }
            const CardFields f2(k, k.cards[c + 1], kSectionCard2);
            const double t1 = f2.real_or(0, 0.0);
            if (!(t1 > 0.0)) {
                f2.fail(0, "expected a shell thickness T1 > 0");
            }
            for (std::size_t n = 0; n < 4; ++n) {
                const double t = n == 0 ? t1 : f2.real_or(n, 0.0);
                if (t < 0.0) {
                    f2.fail(n, "expected a thickness >= 0 (0: T1)");
                }
                section.thickness[n] = units_.length * (t > 0.0 ? t : t1);
            }
            // ICOMP = 1: NIP material angles (NIP default 2), eight to a card.
            const auto nip = f1.integer_or(3, 0) > 0 ? f1.integer_or(3, 0) : 2;
            c += 2 + (f1.integer_or(6, 0) == 1 ? static_cast<std::size_t>((nip + 7) / 8) : 0);
            if (!mesh_.sections.emplace(section.id, section).second) {
                f1.fail(0, "section " + std::to_string(section.id) + " is defined twice");
            }
        }
    }

    void read_parts(const Keyword& k) {
        if (k.cards.size() % 2 != 0) {
            throw KeywordError(k.where() + ": expected two cards per part (HEADING, then PID "
                                           "SECID MID ...)");
        }
        for (std::size_t c = 0; c < k.cards.size(); c += 2) {
            const CardFields f(k, k.cards[c + 1], kPartCard);
            KeywordPart part;
            part.title = card_title(k.cards[c]);
            part.id = positive_id(f, 0);
            part.section = f.integer_or(1, 0);
            part.material = f.integer_or(2, 0);
            part.source = source_of(k.cards[c + 1]);
            if (!mesh_.parts.emplace(part.id, part).second) {
                f.fail(0, "part " + std::to_string(part.id) + " is defined twice");
            }
        }
    }

    KeywordSet read_set(const Keyword& k, std::set<KeywordId>& ids) {
        std::size_t c = 0;
        KeywordSet set;
        if (k.has_title() && !k.cards.empty()) {
            set.title = card_title(k.cards[c++]);
        }
        if (c >= k.cards.size()) {
            throw KeywordError(k.where() + ": expected a card with the set id SID");
        }
        const CardFields head(k, k.cards[c], kSetCard);
        set.id = positive_id(head, 0);
        set.source = source_of(k.cards[c]);
        if (!ids.insert(set.id).second) {
            head.fail(0, "set " + std::to_string(set.id) + " is defined twice");
        }
        for (++c; c < k.cards.size(); ++c) {
            const CardFields f(k, k.cards[c], kSetMembersCard);
            for (std::size_t i = 0; i < kSetMembersCard.size(); ++i) {
                if (f.integer_or(i, 0) != 0) {
                    set.members.push_back(positive_id(f, i));
                }
            }
        }
        return set;
    }

    void read_particles(const Keyword& k, bool volume_option) {
        for (const KeywordCard& card : k.cards) {
            if (is_blank_card(card)) {
                continue;
            }
            const CardFields f(k, card, kSphCard);
            KeywordParticle particle;
            particle.part = positive_id(f, 1);
            particle.source = source_of(card);
            const double value = f.real_or(2, 0.0);
            // "If the VOLUME option is used, the field for MASS is treated as particle volume;
            // a negative MASS has the same effect" (Keyword User's Manual, *ELEMENT_SPH).
            particle.is_volume = volume_option || value < 0.0;
            particle.mass = particle.is_volume ? std::abs(value) * std::pow(units_.length, 3)
                                               : value * units_.mass;
            const KeywordId first = positive_id(f, 0);
            const KeywordId last = f.integer_or(3, 0) == 0 ? first : f.integer(3);
            if (last < first) {
                f.fail(3,
                       "expected NEND >= NID (particles NID..NEND), got " + std::to_string(last));
            }
            // Every particle needs a node of its own: a range longer than the deck's *NODE
            // cards cannot be right, and would otherwise allocate without bound (found by
            // tests/fuzz/fuzz_keyword: NEND = 3.3e82 asked for gigabytes).
            if (last - first >= node_cards_) {
                f.fail(3, "particles NID..NEND = " + std::to_string(first) + ".." +
                              std::to_string(last) + " are more than the deck's " +
                              std::to_string(node_cards_) + " *NODE cards");
            }
            for (KeywordId node = first; node <= last; ++node) {
                particle.node = node;
                mesh_.particles.push_back(particle);
            }
        }
    }

    const KeywordUnits& units_;
    KeywordId node_cards_ = 0; ///< cards of every *NODE keyword: an upper bound on node count
    KeywordMesh mesh_;
    std::set<KeywordId> shell_ids_, node_set_ids_, shell_set_ids_;
};

} // namespace

std::size_t KeywordMesh::node(KeywordId id, const std::string& where) const {
    const auto found = node_index.find(id);
    if (found == node_index.end()) {
        throw KeywordError(where + ": node " + std::to_string(id) + " is not defined by *NODE");
    }
    return found->second;
}

std::vector<KeywordId> select_parts(const KeywordMesh& mesh, const std::vector<std::string>& names,
                                    const std::vector<KeywordId>& candidates,
                                    const std::string& what, const std::string& file) {
    std::string known;
    for (const KeywordId id : candidates) {
        const auto part = mesh.parts.find(id);
        known += (known.empty() ? "" : ", ") + std::to_string(id) +
                 (part != mesh.parts.end() && !part->second.title.empty()
                      ? " \"" + part->second.title + "\""
                      : "");
    }
    known = "parts with " + what + " elements: " + (known.empty() ? "none" : known);
    if (names.empty()) {
        if (candidates.empty()) {
            throw KeywordError(file + ": no " + what + " elements");
        }
        return candidates;
    }
    std::vector<KeywordId> selected;
    for (const std::string& name : names) {
        std::vector<KeywordId> ids;
        for (const auto& [id, part] : mesh.parts) {
            if (part.title == name) {
                ids.push_back(id);
            }
        }
        KeywordId number = 0;
        const auto [end, error] = std::from_chars(name.data(), name.data() + name.size(), number);
        if (ids.empty() && error == std::errc() && end == name.data() + name.size()) {
            ids.push_back(number);
        }
        if (ids.empty()) {
            throw KeywordError(file + ": no *PART titled \"" + name + "\" (" + known + ")");
        }
        for (const KeywordId id : ids) {
            if (std::find(candidates.begin(), candidates.end(), id) == candidates.end()) {
                throw KeywordError(file + ": part " + std::to_string(id) + " (\"" + name +
                                   "\") has no " + what + " elements (" + known + ")");
            }
            if (std::find(selected.begin(), selected.end(), id) == selected.end()) {
                selected.push_back(id);
            }
        }
    }
    return selected;
}

KeywordMesh read_keyword_mesh(const KeywordDeck& deck, const KeywordUnits& units) {
    return MeshReader(units).read(deck);
}

} // namespace grainload::io
