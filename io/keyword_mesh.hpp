#pragma once
// The mesh cards of an LS-DYNA deck (nodes, shells, sections, parts, sets, SPH particles) in SI.

#include "io/deck_ledger.hpp"
#include "io/keyword_deck.hpp"
#include "io/keyword_units.hpp"
#include "io/types.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace grainload::io {

using KeywordId = std::int64_t;

/// Where a mesh item was defined, for messages: "wagon.k:120".
struct KeywordSource {
    std::string file;
    int line = 0;
    std::string text() const { return file + ":" + std::to_string(line); }
};

/// *ELEMENT_SHELL (or _THICKNESS): a 3- or 4-node shell; a triangle repeats its third node.
struct KeywordShell {
    KeywordId id = 0;
    KeywordId part = 0;
    std::array<KeywordId, 4> nodes{};
    /// *ELEMENT_SHELL_THICKNESS: THIC1..THIC4 [m], a zero taking the section's value.
    std::optional<std::array<double, 4>> thickness;
    KeywordSource source;
};

/// *SECTION_SHELL: the thickness at the four nodes T1..T4 [m] (T2..T4 default to T1).
struct KeywordShellSection {
    KeywordId id = 0;
    std::string title;
    int element_form = 0; ///< ELFORM, kept for information: grainload always uses MITC4
    std::array<double, 4> thickness{};
    KeywordSource source;
};

/// *PART: its heading, section and material ids.
struct KeywordPart {
    KeywordId id = 0;
    std::string title;
    KeywordId section = 0;
    KeywordId material = 0;
    KeywordSource source;
};

/// *SET_NODE_LIST or *SET_SHELL_LIST (title from the _TITLE variant, else empty).
struct KeywordSet {
    KeywordId id = 0;
    std::string title;
    std::vector<KeywordId> members;
    KeywordSource source;
};

/// One particle of *ELEMENT_SPH: its node, part and mass [kg] (or, with _VOLUME or a negative
/// MASS, its volume [m^3]).
struct KeywordParticle {
    KeywordId node = 0;
    KeywordId part = 0;
    double mass = 0.0;
    bool is_volume = false;
    KeywordSource source;
};

/// The mesh cards of a deck, converted to SI. Keywords read: *NODE, *ELEMENT_SHELL,
/// *ELEMENT_SHELL_THICKNESS, *SECTION_SHELL(_TITLE), *PART, *SET_NODE_LIST(_TITLE),
/// *SET_SHELL_LIST(_TITLE), *ELEMENT_SPH(_VOLUME). Variants of these that would change what
/// the cards mean (*ELEMENT_SHELL_OFFSET, *PART_COMPOSITE, *SECTION_SHELL_ALE, ...) are refused
/// with a KeywordError; every other keyword is listed in `ignored`.
struct KeywordMesh {
    std::vector<KeywordId> node_ids; ///< in reading order
    std::vector<Vec3> nodes;         ///< positions [m], parallel to node_ids
    std::map<KeywordId, std::size_t> node_index;
    std::vector<KeywordShell> shells;
    std::map<KeywordId, KeywordShellSection> sections;
    std::map<KeywordId, KeywordPart> parts;
    std::vector<KeywordSet> node_sets;
    std::vector<KeywordSet> shell_sets;
    std::vector<KeywordParticle> particles;
    /// Keywords (and fields) grainload does not read from a mesh, each where it stands; the
    /// case's DeckLedger lists those no other reader took either.
    std::vector<IgnoredKeyword> ignored;

    /// Index of node `id` in `nodes`; throws KeywordError naming `where` if there is none.
    std::size_t node(KeywordId id, const std::string& where) const;
};

/// The part ids that `names` select, each a *PART title (every part of that title) or an id;
/// empty `names`: all of `candidates`, the parts that hold elements of the kind `what` names
/// ("shell", "SPH"). A selected part outside `candidates` is refused too. Throws KeywordError
/// naming `file` and listing the candidates.
std::vector<KeywordId> select_parts(const KeywordMesh& mesh, const std::vector<std::string>& names,
                                    const std::vector<KeywordId>& candidates,
                                    const std::string& what, const std::string& file);

/// Reads the mesh cards of `deck`; lengths, masses and volumes are converted with `units`.
/// Duplicate node, element, part, section or set ids, unknown node ids in elements, 8-node
/// shells and malformed cards throw KeywordError with file, line and card.
KeywordMesh read_keyword_mesh(const KeywordDeck& deck, const KeywordUnits& units);

} // namespace grainload::io
