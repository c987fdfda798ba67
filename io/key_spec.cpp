#include "io/key_spec.hpp"

#include "io/units.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string>

namespace grainload::io {

const KeySpec* find_key_spec(std::span<const KeySpec> specs, std::string_view name) {
    for (const KeySpec& spec : specs) {
        if (spec.name == name) {
            return &spec;
        }
    }
    return nullptr;
}

namespace {

/// The spec of a key the calling reader declared itself: a missing one is a programming error.
const KeySpec& declared_spec(std::span<const KeySpec> specs, std::string_view name) {
    const KeySpec* spec = find_key_spec(specs, name);
    if (spec == nullptr) {
        throw std::logic_error("no declared key '" + std::string(name) + "'");
    }
    return *spec;
}

} // namespace

double default_value(std::span<const KeySpec> specs, std::string_view name) {
    return declared_spec(specs, name).value;
}

std::string default_text(std::span<const KeySpec> specs, std::string_view name) {
    return std::string(declared_spec(specs, name).default_text);
}

Vec3 default_vector(std::span<const KeySpec> specs, std::string_view name) {
    std::string text(declared_spec(specs, name).default_text);
    std::erase_if(text, [](char c) { return c == '`' || c == '"'; });
    std::string error;
    const auto values = parse_quantity_list(text, &error);
    if (values && values->size() == 3) {
        return {(*values)[0].value, (*values)[1].value, (*values)[2].value};
    }
    if (values && values->size() == 1 && values->front().value == 0.0) {
        return Vec3::Zero();
    }
    throw std::logic_error("the default of '" + std::string(name) + "', \"" + text +
                           "\", is not a vector");
}

std::vector<const KeyTable*> key_table_parts(std::span<const KeyTable> tables,
                                             std::string_view name) {
    std::vector<const KeyTable*> parts;
    for (const KeyTable& table : tables) {
        if (table.name == name) {
            parts.push_back(&table);
        }
    }
    return parts;
}

std::string table_of_key(std::string_view key_path) {
    std::string table;
    bool in_index = false;
    for (char c : key_path) {
        if (c == '[' || c == ']') {
            in_index = c == '[';
        } else if (!in_index) {
            table.push_back(c);
        }
    }
    const std::size_t dot = table.rfind('.');
    return dot == std::string::npos ? std::string() : table.substr(0, dot);
}

std::string table_header(const KeyTable& table) {
    const std::string name(table.name);
    return table.array ? "[[" + name + "]]" : "[" + name + "]";
}

std::string describe_key_table(const KeyTable& table) {
    std::ostringstream out;
    out << table_header(table) << "  " << table.doc << "\n  (" << table.guide_page << ")\n";
    if (table.user_keys) {
        out << "  its keys are names of your own choice\n";
    }
    for (const KeySpec& key : table.keys) {
        out << "\n  " << key.name << "  (" << key.type
            << "; default: " << (key.default_text.empty() ? "required" : key.default_text)
            << ")\n    " << key.doc << '\n';
    }
    return out.str();
}

} // namespace grainload::io
