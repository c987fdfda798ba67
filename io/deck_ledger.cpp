#include "io/deck_ledger.hpp"

#include "io/case_table.hpp"

#include <cmath>
#include <filesystem>

namespace grainload::io {

namespace {

std::string canonical(const std::string& file) {
    return std::filesystem::weakly_canonical(file).string();
}

/// Two unit systems convert every quantity alike (e.g. "mm-t-s" and "mm-N-s").
bool same_units(const KeywordUnits& a, const KeywordUnits& b) {
    auto close = [](double x, double y) { return std::abs(x - y) <= 1e-12 * std::abs(x); };
    return close(a.length, b.length) && close(a.mass, b.mass) && close(a.time, b.time);
}

} // namespace

DeckLedger::Deck& DeckLedger::deck(const std::string& name) {
    const std::string key = canonical(name);
    auto found = decks_.find(key);
    if (found == decks_.end()) {
        order_.push_back(key);
        found = decks_.emplace(key, Deck{}).first;
        found->second.shown = name;
    }
    return found->second;
}

std::optional<DeckLedger::Opening>
DeckLedger::open(const std::string& name, const KeywordUnits& units, const std::string& key) {
    Deck& d = deck(name);
    if (d.units_key.empty()) {
        d.units = units;
        d.units_key = key;
        return std::nullopt;
    }
    if (!same_units(d.units, units)) {
        return Opening{d.units_key, d.units.name};
    }
    return std::nullopt;
}

void DeckLedger::take(const std::string& name, const std::string& file, int line) {
    deck(name).taken.insert({canonical(file), line});
}

void DeckLedger::leave(const std::string& name, const std::vector<IgnoredKeyword>& ignored) {
    Deck& d = deck(name);
    for (const IgnoredKeyword& k : ignored) {
        d.left.emplace(Place{canonical(k.file), k.line}, k.name);
    }
}

std::vector<std::string> DeckLedger::warnings() const {
    std::vector<std::string> lines;
    for (const std::string& key : order_) {
        const Deck& d = decks_.at(key);
        std::map<std::string, int> count; // by name: the order of the list
        for (const auto& [place, name] : d.left) {
            count[name] += d.taken.contains(place) ? 0 : 1;
        }
        std::string list;
        for (const auto& [name, n] : count) {
            if (n > 0) {
                list += (list.empty() ? "" : ", ") + name +
                        (n > 1 ? " (" + std::to_string(n) + ")" : "");
            }
        }
        if (!list.empty()) {
            lines.push_back(d.shown +
                            ": ignored what grainload does not read from LS-DYNA decks: " + list);
        }
    }
    return lines;
}

void open_keyword_deck(const CaseTable& table, const std::string& deck, const KeywordUnits& units) {
    if (const auto first = table.deck_ledger().open(deck, units, table.key_path("units"))) {
        table.fail("units", std::filesystem::path(deck).filename().string() + " is read in \"" +
                                first->units + "\" for " + first->key +
                                ": a deck has one unit system; expected \"" + first->units +
                                "\" here too");
    }
}

} // namespace grainload::io
