#pragma once
// Where a table's keys stand in the case file, kept by its reader for checks made after it.

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace grainload::io {

class CaseTable;

/// The places of some keys of one case table ("case.toml:12:1: key 'sph.sink[0].min'"), taken
/// when the table is read, so that a check made once the scene is built (a body inside a wall, a
/// sink out of reach) can still name file, line and key without the table; MOOSE's parameters
/// keep their input locations alike. A key the table does not hold is placed at the table.
class KeyPlaces {
  public:
    KeyPlaces() = default;
    KeyPlaces(const CaseTable& table, std::initializer_list<std::string_view> keys);

    /// Whether the table holds `key` (one of those taken).
    bool has(std::string_view key) const;
    /// CaseTable::where of `key` (one of those taken).
    const std::string& where(std::string_view key) const;
    /// Throws io::CaseError at `key`, as CaseTable::fail does.
    [[noreturn]] void fail(std::string_view key, std::string_view message) const;

  private:
    struct Place {
        std::string key;
        std::string where;
        bool held = false;
    };
    const Place& place(std::string_view key) const;

    std::vector<Place> places_;
};

} // namespace grainload::io
