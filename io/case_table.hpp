#pragma once
// A case file and read access to its TOML tables: quantities with units, keys marked used.

#include "io/case_error.hpp"
#include "io/dimension.hpp"
#include "io/types.hpp"

#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace toml {
inline namespace v3 {
class table;
class node;
} // namespace v3
} // namespace toml

namespace grainload::io {

class CaseDocument;
class DeckLedger;

/// Read access to one TOML table of a case file. Every read marks the key as used, so that
/// CaseDocument::reject_unknown_keys() can report typos. Every failure throws CaseError naming
/// file:line:column, the full key ("sph.body[0].spacing") and what was expected.
class CaseTable {
  public:
    CaseTable(CaseDocument* document, const toml::table* table, std::string path);

    bool has(std::string_view key) const;
    /// Full dotted path of this table ("sph.body[1]"), empty for the root.
    const std::string& path() const { return path_; }
    std::string key_path(std::string_view key) const;

    /// A quantity with units, converted to SI. `expected` is checked; bare numbers are accepted
    /// only for dimensionless quantities.
    double quantity(std::string_view key, Dimension expected) const;
    double quantity_or(std::string_view key, Dimension expected, double fallback) const;
    /// Same, and the value must be > 0 (or >= 0 when `allow_zero`).
    double positive_quantity(std::string_view key, Dimension expected,
                             bool allow_zero = false) const;
    double positive_quantity_or(std::string_view key, Dimension expected, double fallback,
                                bool allow_zero = false) const;
    /// A 3-vector: "0 0 -9.81 m/s^2" or ["0 m/s^2", "0 m/s^2", "-9.81 m/s^2"]. In a 2D case a
    /// two-component vector is accepted and its z is 0.
    Vec3 vector(std::string_view key, Dimension expected) const;
    Vec3 vector_or(std::string_view key, Dimension expected, const Vec3& fallback) const;
    /// A list of quantities of one dimension: "1 2 3 mm" or ["1 mm", "2 mm"].
    std::vector<double> quantity_list(std::string_view key, Dimension expected) const;
    /// A list of pairs, e.g. a time function's points [["0 s", 0.0], ["0.5 s", 1.0]]; each
    /// entry a quantity string of its dimension or, for a dimensionless one, a bare number.
    std::vector<std::pair<double, double>> quantity_pairs(std::string_view key, Dimension first,
                                                          Dimension second) const;
    /// A list of (quantity, vector) pairs, e.g. a wall's velocity history
    /// [["0 s", "0 0 0 m/s"], ["0.5 s", "0 0 0.1 m/s"]]; vectors as in vector().
    std::vector<std::pair<double, Vec3>> vector_pairs(std::string_view key, Dimension first,
                                                      Dimension second) const;

    /// A plain number (no unit allowed), e.g. a Poisson ratio or a safety factor.
    double number(std::string_view key) const;
    double number_or(std::string_view key, double fallback) const;
    std::int64_t integer(std::string_view key) const;
    std::int64_t integer_or(std::string_view key, std::int64_t fallback) const;
    bool boolean_or(std::string_view key, bool fallback) const;
    std::string string(std::string_view key) const;
    std::string string_or(std::string_view key, std::string fallback) const;
    /// The key's text when its value is a string; std::nullopt when absent or of another type
    /// (for keys whose strings take more than one form: a time or "phase:NAME").
    std::optional<std::string> string_if(std::string_view key) const;
    /// A file name, resolved relative to the case file's directory unless absolute; the file
    /// must exist.
    std::string file_path(std::string_view key) const;
    /// A file name resolved like file_path(), which need not exist yet (a file to be made).
    std::string resolved_path(std::string_view key) const;
    /// Names or integer ids, alone or in a list: "door", 3 or ["door", 3] (ids as decimal text).
    std::vector<std::string> name_list(std::string_view key) const;
    /// A string that must be one of `allowed`.
    std::string choice(std::string_view key, std::initializer_list<std::string_view> allowed) const;
    std::string choice_or(std::string_view key, std::initializer_list<std::string_view> allowed,
                          std::string fallback) const;

    /// The table's own keys, in file order (for tables whose keys are the user's names).
    std::vector<std::string> keys() const;
    /// This table seen through its sub-table `key` when it has one (keys are looked up in the
    /// sub-table first, then here): a material's keys of one model in [material.MODEL], so
    /// that `--set material[0].model=...` switches between models whose own keys differ. A key
    /// given both there and here is an error. Without the sub-table: this table.
    CaseTable with_sub_table(std::string_view key) const;
    CaseTable table(std::string_view key) const;
    std::optional<CaseTable> optional_table(std::string_view key) const;
    /// [[key]] arrays of tables; empty when absent.
    std::vector<CaseTable> array_of_tables(std::string_view key) const;

    /// Throw a CaseError located at `key` (or at the table itself when `key` is empty).
    [[noreturn]] void fail(std::string_view key, std::string_view message) const;
    /// Where fail() would locate `key`: "case.toml:12:1: key 'sph.sink[0].min'", for a warning
    /// that names its key as an error does.
    std::string where(std::string_view key) const;
    /// A warning for the user, "grainload: warning: TEXT", kept with the document's notices
    /// (CaseDocument::take_notices) for the reader's caller to print.
    void warn(std::string_view text) const;
    /// A line for the user (a note, what was done for the case), kept as warn() keeps warnings.
    void notify(std::string line) const;

    /// Dimension of the scene (2 or 3), needed to read vectors; set from [case].dimension.
    int spatial_dimension() const;
    /// The document's record of the LS-DYNA decks its readers open (io/deck_ledger.hpp).
    DeckLedger& deck_ledger() const;

  private:
    const toml::node* lookup(std::string_view key) const;
    const toml::node& require(std::string_view key) const;
    [[noreturn]] void fail_at(const toml::node* node, std::string_view key,
                              std::string_view message) const;
    std::string located(const toml::node* node, std::string_view key) const;
    Vec3 vector_from(const toml::node& node, std::string_view key, Dimension expected) const;

    CaseDocument* document_;
    const toml::table* table_;
    const toml::table* overlay_ = nullptr; ///< with_sub_table(): looked up before table_
    std::string path_;
};

/// A parsed case file plus the overrides given on the command line.
class CaseDocument {
  public:
    /// Parse `file`; syntax errors throw CaseError with the line and column.
    static std::unique_ptr<CaseDocument> from_file(const std::string& file);
    static std::unique_ptr<CaseDocument> from_string(std::string_view text,
                                                     const std::string& source_name);
    ~CaseDocument();

    /// Apply "--set key=value": key is dotted with optional [i] indices ("sph.body[0].spacing");
    /// value is TOML ("3", "true", "\"5 mm\"") or, when it is not valid TOML, a plain string.
    /// `option` is the command-line flag that gave it, which messages about it name.
    void set(std::string_view assignment, std::string_view option = "--set");

    CaseTable root();
    const std::string& file() const { return file_; }
    /// Directory of the case file, for paths relative to it (meshes, geometry).
    std::string directory() const;

    void mark_used(const toml::node* node);
    /// What the readers took from the LS-DYNA decks the case names (io/deck_ledger.hpp).
    DeckLedger& deck_ledger();
    /// The lines the readers had for the user (CaseTable::warn, notify), in the order they came,
    /// and forgets them: the library prints nothing, its caller prints these on stderr.
    void notify(std::string line);
    std::vector<std::string> take_notices();
    /// Throw CaseError for the first key that no reader asked for.
    void reject_unknown_keys() const;
    /// The full paths ("sph.body[0].spacing") of the values the readers took, in file order:
    /// what the declared schema must cover (tests/unit/app/test_case_schema.cpp).
    std::vector<std::string> used_keys() const;

    int spatial_dimension = 3;

  private:
    CaseDocument();
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::string file_;
};

} // namespace grainload::io
