#include "io/keyword_deck.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

namespace grainload::io {

namespace {

namespace fs = std::filesystem;

std::string upper(std::string_view text) {
    std::string out(text);
    for (char& c : out) {
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    return out;
}

bool is_blank(std::string_view text) {
    return std::all_of(text.begin(), text.end(),
                       [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; });
}

std::string trimmed(std::string_view text) {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string_view::npos) {
        return {};
    }
    return std::string(text.substr(first, text.find_last_not_of(" \t") - first + 1));
}

/// A keyword line split into its name, format suffix and further words.
struct KeywordLine {
    std::string name;
    std::optional<CardFormat> suffix;
    std::vector<std::string> words;
};

std::optional<CardFormat> suffix_format(char c) {
    switch (c) {
    case '+':
        return CardFormat::long_format;
    case '%':
        return CardFormat::i10;
    case '-':
        return CardFormat::standard;
    default:
        return std::nullopt;
    }
}

KeywordLine split_keyword_line(const std::string& line) {
    std::istringstream words(line.substr(1));
    KeywordLine out;
    words >> out.name;
    out.name = upper(out.name);
    // The suffix may be glued to the name ("*NODE+") or stand as a word of its own.
    if (!out.name.empty()) {
        if (const auto format = suffix_format(out.name.back())) {
            out.suffix = format;
            out.name.pop_back();
        }
    }
    std::string word;
    while (words >> word) {
        const auto format = word.size() == 1 ? suffix_format(word[0]) : std::nullopt;
        if (format && !out.suffix) {
            out.suffix = format;
        } else {
            out.words.push_back(upper(word));
        }
    }
    return out;
}

/// What the cards after the current keyword line are.
enum class Mode { outside, keyword, comment, title, include };

class DeckReader {
  public:
    KeywordDeck deck;

    void read(std::istream& in, const std::string& name, const std::string& directory,
              CardFormat format) {
        open_files_.push_back(name);
        FileState state;
        state.name = name;
        state.directory = directory;
        state.format = format;
        std::string line;
        while (std::getline(in, line)) {
            ++state.line;
            if (!line.empty() && line.back() == '\r') {
                line.pop_back();
            }
            if (line.starts_with('$')) {
                continue;
            }
            if (!line.starts_with('*')) {
                add_card(state, line);
                continue;
            }
            finish(state);
            if (!start_keyword(state, split_keyword_line(line))) {
                break; // *END
            }
        }
        finish(state);
        open_files_.pop_back();
    }

  private:
    struct FileState {
        std::string name;
        std::string directory;
        CardFormat format = CardFormat::standard;
        int line = 0;
        Mode mode = Mode::outside;
        std::string keyword; ///< name of the keyword whose cards follow (for messages)
        int keyword_line = 0;
        std::vector<KeywordCard> cards; ///< cards of *TITLE or *INCLUDE
    };

    [[noreturn]] static void fail(const FileState& state, int line, const std::string& why) {
        throw KeywordError(state.name + ":" + std::to_string(line) + ": " + why);
    }

    /// Returns false at *END.
    bool start_keyword(FileState& state, const KeywordLine& keyword) {
        state.keyword = keyword.name;
        state.keyword_line = state.line;
        state.cards.clear();
        if (keyword.name.empty()) {
            fail(state, state.line, "a keyword line needs a name after '*'");
        }
        if (keyword.name == "KEYWORD") {
            apply_keyword_options(state, keyword.words);
            state.mode = Mode::outside;
            return true;
        }
        if (!keyword.words.empty()) {
            fail(state, state.line,
                 "unexpected \"" + keyword.words.front() + "\" after *" + keyword.name +
                     " (only a format suffix +, % or - may follow a keyword name)");
        }
        if (keyword.name == "END") {
            state.mode = Mode::outside;
            return false;
        }
        if (keyword.name.starts_with("INCLUDE_")) {
            fail(state, state.line,
                 "*" + keyword.name +
                     " is not supported: use *INCLUDE with file names relative "
                     "to the including file");
        }
        state.mode = keyword.name == "COMMENT"   ? Mode::comment
                     : keyword.name == "TITLE"   ? Mode::title
                     : keyword.name == "INCLUDE" ? Mode::include
                                                 : Mode::keyword;
        if (state.mode == Mode::keyword) {
            deck.keywords.push_back(Keyword{
                keyword.name, state.name, state.line, keyword.suffix.value_or(state.format), {}});
        }
        return true;
    }

    void apply_keyword_options(FileState& state, const std::vector<std::string>& words) {
        for (const std::string& word : words) {
            if (word == "LONG=Y") {
                state.format = CardFormat::long_format;
            } else if (word == "LONG=S" || word == "LONG=N" || word == "I10=N") {
                // LONG=S reads standard format (it only widens LS-DYNA's own structured file).
                state.format = CardFormat::standard;
            } else if (word == "I10=Y") {
                state.format = CardFormat::i10;
            } else if (word.starts_with("LONG=") || word.starts_with("I10=")) {
                fail(state, state.line,
                     "*KEYWORD option " + word +
                         ": expected LONG=Y, LONG=S, LONG=N, I10=Y or I10=N");
            }
            // Anything else (a memory size, MEMORY=, NCPU=) concerns the LS-DYNA run only.
        }
    }

    void add_card(FileState& state, const std::string& text) {
        switch (state.mode) {
        case Mode::outside:
            if (!is_blank(text)) {
                fail(state, state.line,
                     "card \"" + trimmed(text) +
                         "\" outside any keyword (a keyword line starts "
                         "with '*', a comment with '$')");
            }
            return;
        case Mode::comment:
            return;
        case Mode::title:
        case Mode::include:
            state.cards.push_back({text, state.name, state.line});
            return;
        case Mode::keyword:
            if (text.find('\t') != std::string::npos) {
                fail(state, state.line,
                     "*" + state.keyword + " card \"" + trimmed(text) +
                         "\": tab characters make fixed-format columns ambiguous; use spaces "
                         "or commas");
            }
            deck.keywords.back().cards.push_back({text, state.name, state.line});
            return;
        }
    }

    void finish(FileState& state) {
        if (state.mode == Mode::keyword) {
            // A blank line at the end of a keyword separates it from the next one.
            auto& cards = deck.keywords.back().cards;
            while (!cards.empty() && is_blank(cards.back().text)) {
                cards.pop_back();
            }
        } else if (state.mode == Mode::title) {
            for (const auto& card : state.cards) {
                if (!is_blank(card.text)) {
                    deck.title = trimmed(card.text);
                    break;
                }
            }
        } else if (state.mode == Mode::include) {
            include_files(state);
        }
        state.mode = Mode::outside;
    }

    /// Each file name of an *INCLUDE; " +" at the end of a card continues the name on the next.
    void include_files(FileState& state) {
        std::string name;
        int first_line = 0;
        for (const KeywordCard& card : state.cards) {
            std::string text = trimmed(card.text);
            if (text.empty() && name.empty()) {
                continue;
            }
            first_line = name.empty() ? card.line : first_line;
            if (text.ends_with(" +")) {
                name += trimmed(text.substr(0, text.size() - 2));
                continue;
            }
            name += text;
            include_file(state, name, first_line);
            name.clear();
        }
        if (!name.empty()) {
            fail(state, first_line,
                 "*INCLUDE file name \"" + name +
                     "\" ends in \" +\" but no "
                     "card continues it");
        }
        if (first_line == 0) {
            fail(state, state.keyword_line, "*INCLUDE without a file name");
        }
    }

    void include_file(const FileState& state, const std::string& name, int line) {
        const fs::path given(name);
        const fs::path path = given.is_absolute() ? given : fs::path(state.directory) / given;
        const std::string key = fs::weakly_canonical(path).string();
        for (const std::string& open : open_files_) {
            if (fs::weakly_canonical(open).string() == key) {
                std::string chain;
                for (const std::string& file : open_files_) {
                    chain += file + " -> ";
                }
                fail(state, line,
                     "*INCLUDE \"" + name + "\" would include itself: " + chain + path.string());
            }
        }
        std::ifstream in(path);
        if (!in) {
            fail(state, line, "*INCLUDE: cannot open \"" + path.string() + "\"");
        }
        const std::string directory =
            path.parent_path().empty() ? std::string(".") : path.parent_path().string();
        read(in, path.string(), directory, state.format);
    }

    std::vector<std::string> open_files_;
};

} // namespace

bool Keyword::has_title() const {
    return name.ends_with("_TITLE");
}

std::string Keyword::where() const {
    return file + ":" + std::to_string(line) + ": *" + name;
}

std::string Keyword::where(const KeywordCard& card) const {
    return card.file + ":" + std::to_string(card.line) + ": *" + name + " card \"" +
           trimmed(card.text) + "\"";
}

std::vector<const Keyword*> KeywordDeck::find(std::string_view name) const {
    std::vector<const Keyword*> found;
    for (const Keyword& keyword : keywords) {
        if (keyword.name == name) {
            found.push_back(&keyword);
        }
    }
    return found;
}

KeywordDeck read_keyword_deck(std::istream& in, const std::string& name,
                              const std::string& directory) {
    DeckReader reader;
    reader.read(in, name, directory, CardFormat::standard);
    return std::move(reader.deck);
}

KeywordDeck read_keyword_deck(const std::string& path) {
    std::ifstream in(path);
    if (!in) {
        throw KeywordError("cannot open LS-DYNA keyword file \"" + path + "\"");
    }
    const auto parent = fs::path(path).parent_path();
    return read_keyword_deck(in, path, parent.empty() ? std::string(".") : parent.string());
}

} // namespace grainload::io
