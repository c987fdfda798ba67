#include "io/case_table.hpp"

#include "io/units.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <toml++/toml.h>

namespace grainload::io {

CaseTable::CaseTable(CaseDocument* document, const toml::table* table, std::string path)
    : document_(document), table_(table), path_(std::move(path)) {}

bool CaseTable::has(std::string_view key) const {
    return (overlay_ != nullptr && overlay_->contains(key)) || table_->contains(key);
}

CaseTable CaseTable::with_sub_table(std::string_view key) const {
    const toml::node* node = table_->get(key);
    if (node == nullptr) {
        return *this;
    }
    if (!node->is_table()) {
        fail_at(node, key, "expected a table [" + key_path(key) + "] of the model's own keys");
    }
    document_->mark_used(node);
    CaseTable view = *this;
    view.overlay_ = node->as_table();
    for (const auto& [name, value] : *view.overlay_) {
        if (table_->contains(name.str())) {
            fail_at(&value, std::string(key) + "." + std::string(name.str()),
                    "given both here and in the table above: expected it once");
        }
    }
    return view;
}

std::string CaseTable::key_path(std::string_view key) const {
    if (path_.empty()) {
        return std::string(key);
    }
    return key.empty() ? path_ : path_ + "." + std::string(key);
}

int CaseTable::spatial_dimension() const {
    return document_->spatial_dimension;
}

DeckLedger& CaseTable::deck_ledger() const {
    return document_->deck_ledger();
}

const toml::node* CaseTable::lookup(std::string_view key) const {
    const toml::node* node = overlay_ != nullptr ? overlay_->get(key) : nullptr;
    node = node != nullptr ? node : table_->get(key);
    if (node != nullptr) {
        document_->mark_used(node);
    }
    return node;
}

const toml::node& CaseTable::require(std::string_view key) const {
    const toml::node* node = lookup(key);
    if (node == nullptr) {
        fail_at(table_, key, "missing required key");
    }
    return *node;
}

void CaseTable::fail(std::string_view key, std::string_view message) const {
    throw CaseError(where(key) + ": " + std::string(message));
}

void CaseTable::warn(std::string_view text) const {
    notify("grainload: warning: " + std::string(text));
}

void CaseTable::notify(std::string line) const {
    document_->notify(std::move(line));
}

std::string CaseTable::where(std::string_view key) const {
    const toml::node* node =
        key.empty() ? nullptr : (overlay_ != nullptr ? overlay_->get(key) : nullptr);
    node = node != nullptr || key.empty() ? node : table_->get(key);
    return located(node != nullptr ? node : table_, key);
}

void CaseTable::fail_at(const toml::node* node, std::string_view key,
                        std::string_view message) const {
    throw CaseError(located(node, key) + ": " + std::string(message));
}

std::string CaseTable::located(const toml::node* node, std::string_view key) const {
    const auto& region = node->source();
    std::ostringstream out;
    out << (region.path && !region.path->empty() ? *region.path : document_->file()) << ':'
        << region.begin.line << ':' << region.begin.column << ": ";
    const std::string full = key_path(key);
    out << (full.empty() ? std::string("case file") : "key '" + full + "'");
    return out.str();
}

namespace {

std::string shown(const toml::node& node) {
    std::ostringstream out;
    node.visit([&out](const auto& value) { out << value; });
    return out.str();
}

} // namespace

double CaseTable::quantity(std::string_view key, Dimension expected) const {
    const toml::node& node = require(key);
    const std::string wanted = "expected " + describe(expected);
    if (node.is_number()) {
        if (expected != dimension::kNone) {
            fail_at(&node, key, wanted + "; a bare number has no unit, got " + shown(node));
        }
        return node.value<double>().value();
    }
    if (!node.is_string()) {
        fail_at(&node, key, wanted + ", got " + shown(node));
    }
    const std::string text = node.value<std::string>().value();
    std::string error;
    const auto parsed = parse_quantity(text, &error);
    if (!parsed) {
        fail_at(&node, key, wanted + ": " + error);
    }
    if (parsed->dimension != expected) {
        fail_at(&node, key,
                wanted + ", got \"" + text + "\" which is " + describe(parsed->dimension));
    }
    return parsed->value;
}

double CaseTable::quantity_or(std::string_view key, Dimension expected, double fallback) const {
    return has(key) ? quantity(key, expected) : fallback;
}

double CaseTable::positive_quantity(std::string_view key, Dimension expected,
                                    bool allow_zero) const {
    const double value = quantity(key, expected);
    if (value < 0.0 || (value == 0.0 && !allow_zero)) {
        fail(key, std::string("expected a ") + (allow_zero ? "non-negative " : "positive ") +
                      "value, " + describe(expected));
    }
    return value;
}

double CaseTable::positive_quantity_or(std::string_view key, Dimension expected, double fallback,
                                       bool allow_zero) const {
    return has(key) ? positive_quantity(key, expected, allow_zero) : fallback;
}

std::vector<double> CaseTable::quantity_list(std::string_view key, Dimension expected) const {
    const toml::node& node = require(key);
    const std::string wanted = "expected a list of " + describe(expected);
    std::vector<double> values;
    auto check = [&](const Quantity& q, const std::string& text) {
        if (q.dimension != expected) {
            fail_at(&node, key,
                    wanted + ", got \"" + text + "\" which is " + describe(q.dimension));
        }
        values.push_back(q.value);
    };
    std::string error;
    if (const auto* text = node.as_string()) {
        const auto list = parse_quantity_list(text->get(), &error);
        if (!list) {
            fail_at(&node, key, wanted + ": " + error);
        }
        for (const auto& q : *list) {
            check(q, text->get());
        }
        return values;
    }
    const auto* array = node.as_array();
    if (array == nullptr) {
        fail_at(&node, key, wanted + ", got " + shown(node));
    }
    for (const auto& element : *array) {
        if (element.is_number() && expected == dimension::kNone) {
            values.push_back(element.value<double>().value());
            continue;
        }
        const auto text = element.value<std::string>();
        const auto q = text ? parse_quantity(*text, &error) : std::nullopt;
        if (!q) {
            fail_at(&element, key, wanted + (text ? ": " + error : ", got " + shown(element)));
        }
        check(*q, *text);
    }
    return values;
}

std::vector<std::pair<double, double>>
CaseTable::quantity_pairs(std::string_view key, Dimension first, Dimension second) const {
    const toml::node& node = require(key);
    const std::string wanted =
        "expected a list of pairs [" + describe(first) + ", " + describe(second) + "]";
    const auto value = [&](const toml::node& element, Dimension expected) {
        if (element.is_number() && expected == dimension::kNone) {
            return element.value<double>().value();
        }
        const auto text = element.value<std::string>();
        std::string error;
        const auto q = text ? parse_quantity(*text, &error) : std::nullopt;
        if (!q || q->dimension != expected) {
            fail_at(&element, key, wanted + ", got " + shown(element));
        }
        return q->value;
    };
    const auto* array = node.as_array();
    if (array == nullptr || array->empty()) {
        fail_at(&node, key, wanted + ", got " + shown(node));
    }
    std::vector<std::pair<double, double>> pairs;
    for (const auto& entry : *array) {
        const auto* pair = entry.as_array();
        if (pair == nullptr || pair->size() != 2) {
            fail_at(&entry, key, wanted + ", got " + shown(entry));
        }
        pairs.emplace_back(value(*pair->get(0), first), value(*pair->get(1), second));
    }
    return pairs;
}

std::vector<std::pair<double, Vec3>> CaseTable::vector_pairs(std::string_view key, Dimension first,
                                                             Dimension second) const {
    const toml::node& node = require(key);
    const int dim = spatial_dimension();
    const std::string wanted = "expected a list of pairs [" + describe(first) + ", " +
                               (dim == 2 ? "2 or 3" : "3") + " components of " + describe(second) +
                               "]";
    const auto* array = node.as_array();
    if (array == nullptr || array->empty()) {
        fail_at(&node, key, wanted + ", got " + shown(node));
    }
    std::vector<std::pair<double, Vec3>> pairs;
    for (const auto& entry : *array) {
        const auto* pair = entry.as_array();
        const auto* time =
            pair != nullptr && pair->size() == 2 ? pair->get(0)->as_string() : nullptr;
        const auto* text =
            pair != nullptr && pair->size() == 2 ? pair->get(1)->as_string() : nullptr;
        std::string error;
        std::optional<Quantity> t;
        std::optional<std::vector<Quantity>> list;
        if (time != nullptr && text != nullptr) {
            t = parse_quantity(time->get(), &error);
            list = parse_quantity_list(text->get(), &error);
        }
        const bool size_ok = list && (list->size() == 3 || (dim == 2 && list->size() == 2));
        if (!t || t->dimension != first || !size_ok) {
            fail_at(&entry, key, wanted + ", got " + shown(entry));
        }
        Vec3 v = Vec3::Zero();
        for (std::size_t i = 0; i < list->size(); ++i) {
            if ((*list)[i].dimension != second) {
                fail_at(&entry, key, wanted + ", got " + shown(entry));
            }
            v[static_cast<Eigen::Index>(i)] = (*list)[i].value;
        }
        pairs.emplace_back(t->value, v);
    }
    return pairs;
}

Vec3 CaseTable::vector(std::string_view key, Dimension expected) const {
    const auto values = quantity_list(key, expected);
    const int dim = spatial_dimension();
    const bool size_ok = values.size() == 3 || (dim == 2 && values.size() == 2);
    if (!size_ok) {
        fail(key, "expected " + std::string(dim == 2 ? "2 or 3" : "3") + " components of " +
                      describe(expected) + ", got " + std::to_string(values.size()));
    }
    Vec3 v = Vec3::Zero();
    for (std::size_t i = 0; i < values.size(); ++i) {
        v[static_cast<Eigen::Index>(i)] = values[i];
    }
    return v;
}

Vec3 CaseTable::vector_or(std::string_view key, Dimension expected, const Vec3& fallback) const {
    return has(key) ? vector(key, expected) : fallback;
}

double CaseTable::number(std::string_view key) const {
    return quantity(key, dimension::kNone);
}

double CaseTable::number_or(std::string_view key, double fallback) const {
    return has(key) ? number(key) : fallback;
}

std::int64_t CaseTable::integer(std::string_view key) const {
    const toml::node& node = require(key);
    if (!node.is_integer()) {
        fail_at(&node, key, "expected an integer, got " + shown(node));
    }
    return node.value<std::int64_t>().value();
}

std::int64_t CaseTable::integer_or(std::string_view key, std::int64_t fallback) const {
    return has(key) ? integer(key) : fallback;
}

bool CaseTable::boolean_or(std::string_view key, bool fallback) const {
    if (!has(key)) {
        return fallback;
    }
    const toml::node& node = require(key);
    if (!node.is_boolean()) {
        fail_at(&node, key, "expected true or false, got " + shown(node));
    }
    return node.value<bool>().value();
}

std::string CaseTable::string(std::string_view key) const {
    const toml::node& node = require(key);
    if (!node.is_string()) {
        fail_at(&node, key, "expected a string in quotes, got " + shown(node));
    }
    return node.value<std::string>().value();
}

std::string CaseTable::string_or(std::string_view key, std::string fallback) const {
    return has(key) ? string(key) : fallback;
}

std::optional<std::string> CaseTable::string_if(std::string_view key) const {
    const toml::node* node = lookup(key);
    if (node == nullptr || !node->is_string()) {
        return std::nullopt;
    }
    return node->value<std::string>().value();
}

std::vector<std::string> CaseTable::name_list(std::string_view key) const {
    const toml::node& node = require(key);
    const std::string wanted = "expected a name, an id or a list of them ([\"door\", 3])";
    auto name_of = [&](const toml::node& entry) {
        if (const auto text = entry.value_exact<std::string>()) {
            return *text;
        }
        if (const auto id = entry.value_exact<std::int64_t>()) {
            return std::to_string(*id);
        }
        fail_at(&entry, key, wanted + ", got " + shown(entry));
    };
    const auto* array = node.as_array();
    if (array == nullptr) {
        return {name_of(node)};
    }
    std::vector<std::string> names;
    for (const auto& entry : *array) {
        names.push_back(name_of(entry));
    }
    if (names.empty()) {
        fail_at(&node, key, wanted + ", got an empty list");
    }
    return names;
}

std::string CaseTable::resolved_path(std::string_view key) const {
    const std::filesystem::path name = string(key);
    return (name.is_absolute() ? name : std::filesystem::path(document_->directory()) / name)
        .string();
}

std::string CaseTable::file_path(std::string_view key) const {
    const std::filesystem::path name = string(key);
    const auto path =
        name.is_absolute() ? name : std::filesystem::path(document_->directory()) / name;
    if (!std::filesystem::is_regular_file(path)) {
        fail(key, "expected an existing file (relative to the case file), got \"" + path.string() +
                      "\"");
    }
    return path.string();
}

std::string CaseTable::choice(std::string_view key,
                              std::initializer_list<std::string_view> allowed) const {
    const std::string value = string(key);
    std::string options;
    for (auto option : allowed) {
        if (option == value) {
            return value;
        }
        options += (options.empty() ? "\"" : ", \"") + std::string(option) + "\"";
    }
    fail(key, "expected one of " + options + ", got \"" + value + "\"");
}

std::string CaseTable::choice_or(std::string_view key,
                                 std::initializer_list<std::string_view> allowed,
                                 std::string fallback) const {
    return has(key) ? choice(key, allowed) : fallback;
}

std::vector<std::string> CaseTable::keys() const {
    std::vector<std::pair<toml::source_position, std::string>> found;
    for (const auto& [key, node] : *table_) {
        found.emplace_back(node.source().begin, std::string(key.str()));
    }
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) {
        return a.first.line != b.first.line ? a.first.line < b.first.line
                                            : a.first.column < b.first.column;
    });
    std::vector<std::string> names;
    for (auto& entry : found) {
        names.push_back(std::move(entry.second));
    }
    return names;
}

CaseTable CaseTable::table(std::string_view key) const {
    const toml::node& node = require(key);
    if (!node.is_table()) {
        fail_at(&node, key, "expected a table [" + key_path(key) + "], got " + shown(node));
    }
    return CaseTable(document_, node.as_table(), key_path(key));
}

std::optional<CaseTable> CaseTable::optional_table(std::string_view key) const {
    if (!has(key)) {
        return std::nullopt;
    }
    return table(key);
}

std::vector<CaseTable> CaseTable::array_of_tables(std::string_view key) const {
    std::vector<CaseTable> tables;
    if (!has(key)) {
        return tables;
    }
    const toml::node& node = require(key);
    const auto* array = node.as_array();
    if (array == nullptr || !array->is_array_of_tables()) {
        fail_at(&node, key, "expected an array of tables [[" + key_path(key) + "]]");
    }
    for (std::size_t i = 0; i < array->size(); ++i) {
        const toml::node* element = array->get(i);
        document_->mark_used(element);
        tables.emplace_back(document_, element->as_table(),
                            key_path(key) + "[" + std::to_string(i) + "]");
    }
    return tables;
}

} // namespace grainload::io
