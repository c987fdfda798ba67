#pragma once
// What the readers of a case took from its LS-DYNA decks: one unit system, keywords left unread.

#include "io/keyword_units.hpp"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace grainload::io {

class CaseTable;

/// A keyword (or a field of its cards) a reader of an LS-DYNA deck left unread: its name as
/// the warning shows it ("*MAT_ELASTIC", "*NODE TC/RC constraints") and where it stands.
struct IgnoredKeyword {
    std::string name;
    std::string file;
    int line = 0;
};

/// What the readers of one case took from the LS-DYNA decks it names. One deck may serve
/// several readers (the *MAT_GEOLOGIC_CAP_MODEL of a material, the particles of two bodies, the
/// shells of three parts): it has one unit system, a keyword is ignored only when none of them
/// took it, and each deck is reported once.
class DeckLedger {
  public:
    /// The first reader of a deck: its units and the case key that gave them.
    struct Opening {
        std::string key;
        std::string units;
    };
    /// A reader opens `deck` with `units`, given at the case key `key`; returns the first
    /// reader's opening when it gave the deck other units (the reader refuses its own key then).
    std::optional<Opening> open(const std::string& deck, const KeywordUnits& units,
                                const std::string& key);
    /// A reader of `deck` took the keyword at `file`:`line` (the deck or a file it includes).
    void take(const std::string& deck, const std::string& file, int line);
    /// A reader of `deck` left these.
    void leave(const std::string& deck, const std::vector<IgnoredKeyword>& ignored);
    /// One line per deck with keywords no reader took, in the order the decks were opened:
    /// "DECK: ignored what grainload does not read from LS-DYNA decks: *MAT_ELASTIC (2), ...".
    std::vector<std::string> warnings() const;

  private:
    using Place = std::pair<std::string, int>; ///< canonical file, line
    struct Deck {
        std::string shown; ///< the name as first opened, for the warning
        KeywordUnits units;
        std::string units_key;
        std::set<Place> taken;
        std::map<Place, std::string> left; ///< where -> the name shown
    };
    Deck& deck(const std::string& name);

    std::vector<std::string> order_; ///< canonical names, as first opened
    std::map<std::string, Deck> decks_;
};

/// Records that the reader at `table` opens `deck` with `units` (its key `units`), refusing
/// units that differ from an earlier reader's of the same deck: a deck has one unit system.
void open_keyword_deck(const CaseTable& table, const std::string& deck, const KeywordUnits& units);

} // namespace grainload::io
