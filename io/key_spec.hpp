#pragma once
// Case-file keys as the modules that read them declare them: name, type, default, meaning.

#include "io/types.hpp"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace grainload::io {

/// One case-file key as declared by the module that reads it (MOOSE's validParams): name,
/// type as the user guide states it, default as the user would write it (empty: required),
/// and a one-line meaning. The reader takes its default from here, so a default lives in one
/// place, and the key tests (tests/support/guide_table.hpp) check the user guide's tables against
/// it.
struct KeySpec {
    std::string_view name;
    std::string_view type;
    std::string_view default_text;
    std::string_view doc;
    double value = 0.0; ///< the default as a number (SI), for keys whose default is one
};

/// One table of the case file (or one part of it) with the keys declared for it: its dotted name
/// without indices
/// ("sph.body.shape" for every [sph.body.shape] of every [[sph.body]]), whether it is an array of
/// tables, a one-line meaning, and the user-guide table that documents it (tested against
/// `keys`, tests/unit/app/test_case_schema.cpp).
struct KeyTable {
    std::string_view name;
    bool array = false;
    std::string_view doc;
    std::span<const KeySpec> keys;
    std::string_view guide_page;    ///< relative to the source tree: "docs/user-guide/sph.md"
    std::string_view guide_heading; ///< the heading line the table follows
    /// The table's keys are the user's own names (the numbers a Gmsh geometry is given): `keys`
    /// is empty and any key is accepted.
    bool user_keys = false;
};

/// The spec of `name` in `specs`; nullptr when there is none.
const KeySpec* find_key_spec(std::span<const KeySpec> specs, std::string_view name);
/// The numeric default of `name` (KeySpec::value); throws std::logic_error for an undeclared key.
double default_value(std::span<const KeySpec> specs, std::string_view name);
/// The default of `name` as the user writes it (KeySpec::default_text), for a key whose value
/// is a word ("m", "regular"); throws std::logic_error for an undeclared key.
std::string default_text(std::span<const KeySpec> specs, std::string_view name);
/// The default of a vector key, in SI, parsed from its default text: three components with one
/// unit ("1 0 0", "0 0 0 m"), or "0" with a unit for the zero vector ("0 m/s"); throws
/// std::logic_error for an undeclared key or a default that is no such vector.
Vec3 default_vector(std::span<const KeySpec> specs, std::string_view name);

/// The parts of `tables` named `name`: a table whose keys the user guide documents under more
/// than one heading ([[sph.wall]]: its geometry, its outlet keys) is declared in as many parts.
std::vector<const KeyTable*> key_table_parts(std::span<const KeyTable> tables,
                                             std::string_view name);
/// The declared table a key's full path lies in: "sph.body[0].shape.cut[1].normal" ->
/// "sph.body.shape.cut" (indices dropped, the key's own name removed).
std::string table_of_key(std::string_view key_path);
/// The table as a case file opens it: "[[sph.wall]]" for an array of tables, "[sph]" else.
std::string table_header(const KeyTable& table);
/// The table as `grainload help keys TABLE` prints it: its header line, its meaning, and one
/// block per key (name, type, default, meaning).
std::string describe_key_table(const KeyTable& table);

} // namespace grainload::io
