#include "io/case_table.hpp"
#include "io/deck_ledger.hpp"

#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <toml++/toml.h>
#include <unordered_set>
#include <utility>

namespace grainload::io {

struct CaseDocument::Impl {
    toml::table root;
    std::unordered_set<const toml::node*> used;
    DeckLedger decks;
    std::vector<std::string> notices;
};

CaseDocument::CaseDocument() : impl_(std::make_unique<Impl>()) {}
CaseDocument::~CaseDocument() = default;

DeckLedger& CaseDocument::deck_ledger() {
    return impl_->decks;
}

void CaseDocument::notify(std::string line) {
    impl_->notices.push_back(std::move(line));
}

std::vector<std::string> CaseDocument::take_notices() {
    return std::exchange(impl_->notices, {});
}

namespace {

std::string location(const toml::source_region& region, const std::string& fallback_file) {
    std::ostringstream out;
    out << (region.path && !region.path->empty() ? *region.path : fallback_file) << ':'
        << region.begin.line << ':' << region.begin.column;
    return out.str();
}

toml::table parse_or_throw(std::string_view text, const std::string& source_name) {
    try {
        return toml::parse(text, source_name);
    } catch (const toml::parse_error& error) {
        throw CaseError(location(error.source(), source_name) +
                        ": TOML syntax error: " + std::string(error.description()));
    }
}

// "sph.body[0].spacing" -> {"sph", "body", "[0]", "spacing"}.
std::vector<std::string> split_key_path(std::string_view key) {
    std::vector<std::string> parts;
    std::string current;
    for (char c : key) {
        if (c == '.' || c == '[') {
            if (!current.empty()) {
                parts.push_back(current);
            }
            current.clear();
            if (c == '[') {
                current.push_back('[');
            }
        } else if (c == ']') {
            parts.push_back(current + "]");
            current.clear();
        } else {
            current += c;
        }
    }
    if (!current.empty()) {
        parts.push_back(current);
    }
    return parts;
}

} // namespace

std::unique_ptr<CaseDocument> CaseDocument::from_string(std::string_view text,
                                                        const std::string& source_name) {
    std::unique_ptr<CaseDocument> document(new CaseDocument());
    document->file_ = source_name;
    document->impl_->root = parse_or_throw(text, source_name);
    return document;
}

std::unique_ptr<CaseDocument> CaseDocument::from_file(const std::string& file) {
    std::error_code error;
    if (std::filesystem::is_directory(file, error)) {
        throw CaseError(file + ": is a directory; expected a case file (CASE.toml)");
    }
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        // errno from the failed open says why: no such file, permission denied, ...
        throw CaseError(file + ": cannot open the case file (" + std::strerror(errno) + ")");
    }
    std::ostringstream text;
    text << in.rdbuf();
    return from_string(text.str(), file);
}

std::string CaseDocument::directory() const {
    const auto parent = std::filesystem::path(file_).parent_path();
    return parent.empty() ? std::string(".") : parent.string();
}

CaseTable CaseDocument::root() {
    return CaseTable(this, &impl_->root, "");
}

void CaseDocument::mark_used(const toml::node* node) {
    impl_->used.insert(node);
}

void CaseDocument::set(std::string_view assignment, std::string_view option) {
    const std::string origin = std::string(option) + " " + std::string(assignment);
    const auto equals = assignment.find('=');
    if (equals == std::string_view::npos || equals == 0) {
        throw CaseError(origin + ": expected key=value, e.g. --set case.end_time=\"0.5 s\"");
    }
    const auto parts = split_key_path(assignment.substr(0, equals));
    const std::string value(assignment.substr(equals + 1));
    toml::table parsed;
    try {
        parsed = toml::parse("value = " + value, origin);
    } catch (const toml::parse_error&) {
        // Not TOML: a plain string, so that --set case.end_time="0.5 s" needs no inner quotes.
        std::string escaped;
        for (char c : value) {
            if (c == '"' || c == '\\') {
                escaped += '\\';
            }
            escaped += c;
        }
        parsed = parse_or_throw("value = \"" + escaped + "\"", origin);
    }
    toml::node* cursor = &impl_->root;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
        const auto& part = parts[i];
        if (part.front() == '[') {
            auto* array = cursor->as_array();
            // Digits only: "[x]", "[]" or an index beyond any array is the user's typo (exit
            // code 2), not std::stoul's exception (found by tests/fuzz/fuzz_case).
            std::size_t index = 0;
            const std::string digits = part.substr(1, part.size() - 2);
            const auto [end, error] =
                std::from_chars(digits.data(), digits.data() + digits.size(), index);
            if (digits.empty() || error != std::errc() || end != digits.data() + digits.size()) {
                throw CaseError(origin + ": '" + part + "' is not an index [0], [1], ...");
            }
            if (array == nullptr || index >= array->size()) {
                throw CaseError(origin + ": '" + part + "' does not name an existing element");
            }
            cursor = array->get(index);
            continue;
        }
        auto* table = cursor->as_table();
        if (table == nullptr) {
            throw CaseError(origin + ": '" + part + "' is not inside a table");
        }
        if (!table->contains(part)) {
            table->insert(part, toml::table{});
        }
        cursor = table->get(part);
    }
    auto* table = cursor->as_table();
    if (table == nullptr || parts.empty() || parts.back().front() == '[') {
        throw CaseError(origin + ": the key must end in a table entry");
    }
    table->insert_or_assign(parts.back(), std::move(*parsed.get("value")));
}

namespace {

void reject_unused(const toml::table& table, const std::string& path,
                   const std::unordered_set<const toml::node*>& used, const std::string& file) {
    for (const auto& [key, node] : table) {
        const std::string full =
            path.empty() ? std::string(key.str()) : path + "." + std::string(key.str());
        if (!used.contains(&node)) {
            throw CaseError(location(node.source(), file) + ": unknown key '" + full +
                            "' (check its spelling and its table; see docs/user-guide.md)");
        }
        if (const auto* child = node.as_table()) {
            reject_unused(*child, full, used, file);
        } else if (const auto* array = node.as_array(); array && array->is_array_of_tables()) {
            for (std::size_t i = 0; i < array->size(); ++i) {
                reject_unused(*array->get(i)->as_table(), full + "[" + std::to_string(i) + "]",
                              used, file);
            }
        }
    }
}

void collect_used(const toml::table& table, const std::string& path,
                  const std::unordered_set<const toml::node*>& used,
                  std::vector<std::string>& keys) {
    for (const auto& [key, node] : table) {
        const std::string full =
            path.empty() ? std::string(key.str()) : path + "." + std::string(key.str());
        if (const auto* child = node.as_table()) {
            collect_used(*child, full, used, keys);
        } else if (const auto* array = node.as_array(); array && array->is_array_of_tables()) {
            for (std::size_t i = 0; i < array->size(); ++i) {
                collect_used(*array->get(i)->as_table(), full + "[" + std::to_string(i) + "]", used,
                             keys);
            }
        } else if (used.contains(&node)) {
            keys.push_back(full);
        }
    }
}

} // namespace

void CaseDocument::reject_unknown_keys() const {
    reject_unused(impl_->root, "", impl_->used, file_);
}

std::vector<std::string> CaseDocument::used_keys() const {
    std::vector<std::string> keys;
    collect_used(impl_->root, "", impl_->used, keys);
    return keys;
}

} // namespace grainload::io
