#pragma once
// An LS-DYNA keyword deck read into its keywords and their data cards, includes followed.

#include <istream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace grainload::io {

/// A malformed LS-DYNA keyword deck. The message names the file, the line and the card:
/// "wagon.k:12: *NODE card \"...\": field X (columns 9-24): expected a real number".
class KeywordError : public std::invalid_argument {
  public:
    using std::invalid_argument::invalid_argument;
};

/// Field widths of the fixed-format cards of one keyword (LS-DYNA Keyword User's Manual,
/// Vol. I, "General card format"): standard format has the widths each keyword's card table
/// gives (8, 10 or 16 columns; 80 in all); "I10" format widens every field narrower than 10
/// columns to 10 (`*KEYWORD I10=Y`, or a `%` after the keyword name); long format widens every
/// field narrower than 20 columns to 20 (`*KEYWORD LONG=Y`, or a `+` after the keyword name).
/// A `-` after the keyword name returns that keyword to standard format.
enum class CardFormat { standard, i10, long_format };

/// One data card: the text of a line that is neither a keyword nor a comment, with the file
/// and line it came from.
struct KeywordCard {
    std::string text;
    std::string file;
    int line = 0;
};

/// One keyword and its cards, in file order. `name` is upper case, without the `*` and without
/// a format suffix ("SECTION_SHELL_TITLE").
struct Keyword {
    std::string name;
    std::string file;
    int line = 0;
    CardFormat format = CardFormat::standard;
    std::vector<KeywordCard> cards;

    /// True for the _TITLE variant ("SET_NODE_LIST_TITLE"), whose first card is a title.
    bool has_title() const;
    /// "file:line: *NAME": the start of every message about this keyword.
    std::string where() const;
    /// "file:line: *NAME card \"text\"": the start of every message about one of its cards.
    std::string where(const KeywordCard& card) const;
};

/// The keywords of a deck and of every file it includes, in reading order (an included file's
/// keywords stand where its *INCLUDE stood).
struct KeywordDeck {
    std::vector<Keyword> keywords;
    std::string title; ///< the *TITLE card, if any

    /// Keywords named exactly `name` ("NODE"), in reading order.
    std::vector<const Keyword*> find(std::string_view name) const;
};

/// Reads an LS-DYNA keyword deck (`.k`): lines starting with `*` are keywords, lines
/// starting with `$` comments, every other line a card of the keyword before it. Cards are kept
/// as text; io/keyword_fields.hpp splits them into fields, fixed or free (comma-separated)
/// format. Handled here: *KEYWORD (its LONG=Y / LONG=S / I10=Y options set the format of the
/// rest of that file and of the files it includes; a memory size is ignored), *END (ends the
/// file it stands in), *TITLE, *COMMENT (its cards are skipped), *INCLUDE (each card a file
/// name, relative to the including file's directory unless absolute; a name that does not fit
/// one card continues on the next when the card ends in " +"; a file that includes itself,
/// directly or through others, is refused). *INCLUDE_PATH, *INCLUDE_TRANSFORM and the other
/// *INCLUDE_ variants, and *PARAMETER substitutions ("&name" fields, see keyword_fields.hpp),
/// are refused with a KeywordError.
///
/// Blank cards count (LS-DYNA reads a blank card as all defaults) except at the end of a
/// keyword, where a blank line only separates keywords. Non-blank text before the first
/// keyword is refused. Throws KeywordError naming the file and line.
KeywordDeck read_keyword_deck(const std::string& path);
/// Same, from a stream: `name` is used in messages and `directory` resolves *INCLUDE names.
KeywordDeck read_keyword_deck(std::istream& in, const std::string& name,
                              const std::string& directory);

} // namespace grainload::io
