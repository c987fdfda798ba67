#include "io/keyword_fields.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace grainload::io {

namespace {

std::string trimmed(std::string_view text) {
    const auto first = text.find_first_not_of(' ');
    if (first == std::string_view::npos) {
        return {};
    }
    return std::string(text.substr(first, text.find_last_not_of(' ') - first + 1));
}

} // namespace

int field_width(int width, CardFormat format) {
    switch (format) {
    case CardFormat::i10:
        return std::max(width, 10);
    case CardFormat::long_format:
        return std::max(width, 20);
    case CardFormat::standard:
        break;
    }
    return width;
}

std::string card_title(const KeywordCard& card) {
    return trimmed(card.text);
}

CardFields::CardFields(const Keyword& keyword, const KeywordCard& card,
                       std::span<const FieldSpec> layout)
    : keyword_(keyword), card_(card), layout_(layout),
      free_format_(card.text.find(',') != std::string::npos) {
    if (free_format_) {
        std::size_t start = 0;
        while (start <= card.text.size()) {
            const std::size_t end = std::min(card.text.find(',', start), card.text.size());
            fields_.push_back(trimmed(std::string_view(card.text).substr(start, end - start)));
            start = end + 1;
        }
        return;
    }
    int column = 0;
    for (const FieldSpec& field : layout_) {
        const int width = field_width(field.width, keyword.format);
        first_column_.push_back(column + 1);
        widths_.push_back(width);
        const auto from = static_cast<std::size_t>(column);
        fields_.push_back(from < card.text.size() ? trimmed(std::string_view(card.text).substr(
                                                        from, static_cast<std::size_t>(width)))
                                                  : std::string());
        column += width;
    }
}

bool CardFields::blank(std::size_t i) const {
    return i >= fields_.size() || fields_[i].empty();
}

std::string CardFields::text(std::size_t i) const {
    return blank(i) ? std::string() : fields_[i];
}

std::int64_t CardFields::integer(std::size_t i) const {
    if (blank(i)) {
        fail(i, "expected an integer, the field is blank");
    }
    return integer_or(i, 0);
}

std::int64_t CardFields::integer_or(std::size_t i, std::int64_t fallback) const {
    if (blank(i)) {
        return fallback;
    }
    const std::string& text = fields_[i];
    if (text.starts_with('&')) {
        fail(i, "*PARAMETER references (\"" + text + "\") are not supported");
    }
    const char* first = text.data() + (text.starts_with('+') ? 1 : 0);
    const char* last = text.data() + text.size();
    std::int64_t value = 0;
    const auto [end, error] = std::from_chars(first, last, value);
    if (error != std::errc() || end != last) {
        fail(i, "expected an integer, got \"" + text + "\"");
    }
    return value;
}

double CardFields::real(std::size_t i) const {
    if (blank(i)) {
        fail(i, "expected a real number, the field is blank");
    }
    return real_or(i, 0.0);
}

double CardFields::real_or(std::size_t i, double fallback) const {
    if (blank(i)) {
        return fallback;
    }
    std::string text = fields_[i];
    if (text.starts_with('&')) {
        fail(i, "*PARAMETER references (\"" + text + "\") are not supported");
    }
    // Fortran writes double-precision exponents with D.
    std::replace_if(
        text.begin(), text.end(), [](char c) { return c == 'd' || c == 'D'; }, 'e');
    const char* first = text.data() + (text.starts_with('+') ? 1 : 0);
    const char* last = text.data() + text.size();
    double value = 0.0;
    const auto [end, error] = std::from_chars(first, last, value);
    if (error != std::errc() || end != last || !std::isfinite(value)) {
        const bool bare_exponent =
            error == std::errc() && end != last && (*end == '+' || *end == '-');
        fail(i, "expected a real number, got \"" + fields_[i] + "\"" +
                    (bare_exponent ? " (write the exponent with E: 1.5E-3, not 1.5-3)" : ""));
    }
    return value;
}

void CardFields::fail(std::size_t i, std::string_view why) const {
    std::string field =
        i < layout_.size() ? std::string(layout_[i].name) : "#" + std::to_string(i + 1);
    if (free_format_) {
        field += " (free-format field " + std::to_string(i + 1) + ")";
    } else if (i < first_column_.size()) {
        field += " (columns " + std::to_string(first_column_[i]) + "-" +
                 std::to_string(first_column_[i] + widths_[i] - 1) + ")";
    }
    throw KeywordError(keyword_.where(card_) + ": field " + field + ": " + std::string(why));
}

void CardFields::fail(std::string_view why) const {
    throw KeywordError(keyword_.where(card_) + ": " + std::string(why));
}

} // namespace grainload::io
