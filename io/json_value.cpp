#include "io/json_value.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace grainload::io {

JsonValue::JsonValue() = default;
JsonValue::JsonValue(const JsonValue&) = default;
JsonValue::JsonValue(JsonValue&&) noexcept = default;
JsonValue& JsonValue::operator=(const JsonValue&) = default;
JsonValue& JsonValue::operator=(JsonValue&&) noexcept = default;
JsonValue::~JsonValue() = default;

namespace {

class Parser {
  public:
    Parser(std::string_view text, const std::string& source) : text_(text), source_(source) {}

    JsonValue document() {
        JsonValue value = parse_value(0);
        skip_space();
        if (pos_ != text_.size()) {
            fail("unexpected text after the JSON value");
        }
        return value;
    }

  private:
    // Deep enough for any file grainload writes; guards the recursion against hostile input.
    static constexpr int kMaxDepth = 64;

    [[noreturn]] void fail(const std::string& why) const {
        int line = 1;
        for (std::size_t i = 0; i < pos_ && i < text_.size(); ++i) {
            line += text_[i] == '\n';
        }
        throw JsonError(source_ + ":" + std::to_string(line) + ": " + why);
    }

    void skip_space() {
        while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\n' ||
                                       text_[pos_] == '\t' || text_[pos_] == '\r')) {
            ++pos_;
        }
    }

    bool consume(std::string_view word) {
        if (text_.substr(pos_).starts_with(word)) {
            pos_ += word.size();
            return true;
        }
        return false;
    }

    JsonValue parse_value(int depth) {
        if (depth > kMaxDepth) {
            fail("nested too deeply");
        }
        skip_space();
        if (pos_ >= text_.size()) {
            fail("expected a value, got the end of the text");
        }
        JsonValue value;
        const char c = text_[pos_];
        if (c == '{') {
            value.type = JsonValue::Type::object;
            parse_members(value, depth);
        } else if (c == '[') {
            value.type = JsonValue::Type::array;
            parse_elements(value, depth);
        } else if (c == '"') {
            value.type = JsonValue::Type::string;
            value.string = parse_string();
        } else if (consume("true")) {
            value.type = JsonValue::Type::boolean;
            value.boolean = true;
        } else if (consume("false")) {
            value.type = JsonValue::Type::boolean;
        } else if (consume("null")) {
            value.type = JsonValue::Type::null;
        } else {
            value.type = JsonValue::Type::number;
            value.number = parse_number();
        }
        return value;
    }

    void parse_members(JsonValue& value, int depth) {
        ++pos_;
        skip_space();
        if (consume("}")) {
            return;
        }
        while (true) {
            skip_space();
            if (pos_ >= text_.size() || text_[pos_] != '"') {
                fail("expected a member name in quotes");
            }
            std::string key = parse_string();
            skip_space();
            if (!consume(":")) {
                fail("expected ':' after the member name \"" + key + "\"");
            }
            value.object.emplace_back(std::move(key), parse_value(depth + 1));
            skip_space();
            if (consume("}")) {
                return;
            }
            if (!consume(",")) {
                fail("expected ',' or '}' in an object");
            }
        }
    }

    void parse_elements(JsonValue& value, int depth) {
        ++pos_;
        skip_space();
        if (consume("]")) {
            return;
        }
        while (true) {
            value.array.push_back(parse_value(depth + 1));
            skip_space();
            if (consume("]")) {
                return;
            }
            if (!consume(",")) {
                fail("expected ',' or ']' in an array");
            }
        }
    }

    double parse_number() {
        const char* first = text_.data() + pos_;
        double number = 0.0;
        const auto [end, error] = std::from_chars(first, text_.data() + text_.size(), number);
        if (error != std::errc() || end == first) {
            fail("expected a value (object, array, string, number, true, false or null)");
        }
        pos_ += static_cast<std::size_t>(end - first);
        return number;
    }

    /// Appends code point `cp` as UTF-8.
    static void append_utf8(std::string& out, unsigned cp) {
        if (cp < 0x80) {
            out += static_cast<char>(cp);
        } else if (cp < 0x800) {
            out += static_cast<char>(0xC0 | (cp >> 6));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else {
            out += static_cast<char>(0xE0 | (cp >> 12));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        }
    }

    std::string parse_string() {
        ++pos_;
        std::string out;
        while (pos_ < text_.size() && text_[pos_] != '"') {
            char c = text_[pos_++];
            if (c != '\\') {
                out += c;
                continue;
            }
            if (pos_ >= text_.size()) {
                break;
            }
            c = text_[pos_++];
            switch (c) {
            case 'n':
                out += '\n';
                break;
            case 't':
                out += '\t';
                break;
            case 'r':
                out += '\r';
                break;
            case 'b':
                out += '\b';
                break;
            case 'f':
                out += '\f';
                break;
            case 'u': {
                unsigned cp = 0;
                const auto [end, error] =
                    std::from_chars(text_.data() + pos_, text_.data() + pos_ + 4, cp, 16);
                if (pos_ + 4 > text_.size() || error != std::errc() ||
                    end != text_.data() + pos_ + 4) {
                    fail("expected four hex digits after \\u");
                }
                pos_ += 4;
                append_utf8(out, cp);
                break;
            }
            default:
                out += c; // \" \\ \/
            }
        }
        if (!consume("\"")) {
            fail("unterminated string");
        }
        return out;
    }

    std::string_view text_;
    const std::string& source_;
    std::size_t pos_ = 0;
};

} // namespace

const JsonValue* JsonValue::find(std::string_view key) const {
    for (const auto& [name, value] : object) {
        if (name == key) {
            return &value;
        }
    }
    return nullptr;
}

std::optional<double> JsonValue::number_at(std::string_view key) const {
    const JsonValue* value = find(key);
    if (value == nullptr || value->type != Type::number) {
        return std::nullopt;
    }
    return value->number;
}

std::optional<std::string> JsonValue::string_at(std::string_view key) const {
    const JsonValue* value = find(key);
    if (value == nullptr || value->type != Type::string) {
        return std::nullopt;
    }
    return value->string;
}

JsonValue parse_json(std::string_view text, const std::string& source) {
    return Parser(text, source).document();
}

JsonValue read_json_file(const std::string& path) {
    std::ifstream in(path);
    if (!in) {
        throw JsonError(path + ": cannot be read");
    }
    std::ostringstream text;
    text << in.rdbuf();
    return parse_json(text.str(), path);
}

std::string json_quoted(std::string_view text) {
    std::ostringstream out;
    out << '"';
    for (const char c : text) {
        if (c == '"' || c == '\\') {
            out << '\\' << c;
        } else if (c == '\n') {
            out << "\\n";
        } else if (c == '\t') {
            out << "\\t";
        } else if (static_cast<unsigned char>(c) < 0x20) {
            out << "\\u" << std::hex << std::setw(4) << std::setfill('0') << int(c) << std::dec;
        } else {
            out << c;
        }
    }
    out << '"';
    return out.str();
}

std::string json_number(double value, int digits) {
    if (!std::isfinite(value)) {
        return "null";
    }
    std::ostringstream out;
    out << std::setprecision(digits) << value;
    return out.str();
}

} // namespace grainload::io
