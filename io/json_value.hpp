#pragma once
// A parsed JSON value, for the files grainload writes and reads back (summary.json and others).

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace grainload::io {

/// A malformed JSON text; the message names the source and the line.
class JsonError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// A parsed JSON value (RFC 8259), enough for the files grainload itself writes and reads back:
/// summary.json, a trade sweep's records, the cost calibration. Objects keep their key order.
struct JsonValue {
    enum class Type { null, boolean, number, string, array, object };
    Type type = Type::null;
    bool boolean = false;
    double number = 0.0;
    std::string string;
    std::vector<JsonValue> array;
    std::vector<std::pair<std::string, JsonValue>> object;

    // Defined in the .cpp, where JsonValue is complete: an implicit destructor here would
    // instantiate std::pair<std::string, JsonValue> of an incomplete type, which clang with
    // libstdc++ refuses (the fuzz build).
    JsonValue();
    JsonValue(const JsonValue&);
    JsonValue(JsonValue&&) noexcept;
    JsonValue& operator=(const JsonValue&);
    JsonValue& operator=(JsonValue&&) noexcept;
    ~JsonValue();

    /// The member `key` of an object; nullptr when absent or when this is not an object.
    const JsonValue* find(std::string_view key) const;
    /// The number at `key`, std::nullopt when absent, null or not a number.
    std::optional<double> number_at(std::string_view key) const;
    /// The string at `key`, std::nullopt when absent or not a string.
    std::optional<std::string> string_at(std::string_view key) const;
};

/// Parses `text`; `source` names it in messages. Throws JsonError.
JsonValue parse_json(std::string_view text, const std::string& source);
/// Reads and parses a file; throws JsonError when it cannot be read or parsed.
JsonValue read_json_file(const std::string& path);

/// `text` as a JSON string literal, quotes included.
std::string json_quoted(std::string_view text);
/// A number as JSON writes it (`digits` significant digits); null for NaN and infinities.
std::string json_number(double value, int digits = 12);

} // namespace grainload::io
