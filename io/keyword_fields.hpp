#pragma once
// The fields of one LS-DYNA card, fixed or free format, laid out by the keyword's card table.

#include "io/keyword_deck.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace grainload::io {

/// One field of a card layout: its name in the LS-DYNA manual's card table (for messages) and
/// its standard-format width in columns.
struct FieldSpec {
    std::string_view name;
    int width = 10;
};

/// The fields of one card, laid out by the keyword's card table. A card holding a comma is in
/// free format: its fields are the comma-separated words, blanks trimmed, an empty word being a
/// blank field (LS-DYNA Keyword User's Manual, Vol. I, "General card format"). Otherwise the
/// card is fixed format and field i occupies the columns of the widths before it, each
/// widened as the keyword's CardFormat says; columns beyond the end of the line are blank.
/// A blank field takes the caller's default. Integers are plain decimal; reals accept the
/// Fortran forms "1.", ".5", "1.5E3", "1.5D3", but not the exponent without its letter
/// ("1.5-3"), which is refused. A field starting with '&' (a *PARAMETER reference) is refused.
/// Every error is a KeywordError naming file, line, keyword, card, field and columns.
class CardFields {
  public:
    CardFields(const Keyword& keyword, const KeywordCard& card, std::span<const FieldSpec> layout);

    std::size_t size() const { return layout_.size(); }
    bool free_format() const { return free_format_; }
    bool blank(std::size_t i) const;
    std::int64_t integer(std::size_t i) const;
    std::int64_t integer_or(std::size_t i, std::int64_t fallback) const;
    double real(std::size_t i) const;
    double real_or(std::size_t i, double fallback) const;
    /// The field's text, blanks trimmed (empty when blank).
    std::string text(std::size_t i) const;

    [[noreturn]] void fail(std::size_t i, std::string_view why) const;
    [[noreturn]] void fail(std::string_view why) const;

  private:
    const Keyword& keyword_;
    const KeywordCard& card_;
    std::span<const FieldSpec> layout_;
    bool free_format_ = false;
    std::vector<std::string> fields_;
    std::vector<int> first_column_; ///< 1-based, fixed format only
    std::vector<int> widths_;
};

/// The width of a field of standard width `width` in the given format.
int field_width(int width, CardFormat format);

/// A title card (A70/A80 in the manual): the card's text, blanks trimmed, commas included.
std::string card_title(const KeywordCard& card);

} // namespace grainload::io
