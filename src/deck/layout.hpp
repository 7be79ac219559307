// Card layouts as data: a keyword is a list of cards, a card a list of typed fields with
// their standard-format width and default (LS-DYNA Keyword Manual Vol. I, "General card
// format"). The physics that gives the fields their meaning lives in src/model/build*.cpp;
// adding a keyword is a table entry in keywords.cpp plus its meaning there.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace crumple::deck {

enum class FieldType : uint8_t { Int, Real, Text };

// Field-width family of a keyword. Standard: the widths of the tables (mostly 10); I10:
// fields narrower than 10 become 10 ("*KEYWORD I10=Y", or a "%" after the keyword); Long:
// every field becomes 20 wide ("*KEYWORD LONG=Y", or a "+" after the keyword); a "-" after
// the keyword forces the standard widths. Free format (a card containing a comma) needs none.
enum class Format : uint8_t { Standard, I10, Long };

enum FieldFlag : uint8_t {
  kZeroIsDefault = 1,  // LS-DYNA reads 0 as "use the default" (e.g. TSSFAC 0 -> 0.9)
  kQuiet = 2,          // no influence on the solution (output format flags, unused columns):
                       // never reported as ignored
};

struct FieldSpec {
  std::string_view name;
  FieldType type = FieldType::Real;
  int width = 10;  // standard-format width in characters
  double def = 0.0;
  std::string_view text_def = {};
  uint8_t flags = 0;

  bool zeroIsDefault() const { return (flags & kZeroIsDefault) != 0; }
  bool quiet() const { return (flags & kQuiet) != 0; }
};

struct CardSpec;

// A field of one card layout found once by name (CardSpec::slot), so that a builder reading a
// card per line of a large list (*NODE, *ELEMENT_SOLID) asks for it without a look-up by name.
struct FieldSlot {
  const CardSpec* card = nullptr;  // the layout it belongs to (a card of another is a bug)
  std::size_t index = 0;
  std::string_view name;
};

struct CardSpec {
  std::string_view label;  // as the manual numbers it: "card 1", "title card", ...
  std::vector<FieldSpec> fields;

  // The field of that name; throws std::logic_error if the card has none, or two (a coding
  // error: a slot must name one field).
  FieldSlot slot(std::string_view name) const;
};

struct KeywordSpec {
  std::string_view name;  // base keyword, e.g. "*MAT_ELASTIC"
  std::vector<CardSpec> cards;

  // The card with this label; throws std::logic_error if the table has none (a coding error).
  const CardSpec& card(std::string_view label) const;
};

// Field constructors that keep the tables short and readable.
constexpr FieldSpec I(std::string_view name, double def = 0, uint8_t flags = 0, int width = 10) {
  return {name, FieldType::Int, width, def, {}, flags};
}
constexpr FieldSpec R(std::string_view name, double def = 0, uint8_t flags = 0, int width = 10) {
  return {name, FieldType::Real, width, def, {}, flags};
}
constexpr FieldSpec A(std::string_view name, int width = 10, std::string_view def = {},
                      uint8_t flags = 0) {
  return {name, FieldType::Text, width, 0.0, def, flags};
}

// Title line of the _TITLE option and of *TITLE / *PART (the whole line, A80).
inline CardSpec titleCard(std::string_view label = "title card") {
  return {label, {A("TITLE", 80, {}, kQuiet)}};
}

// The table of a keyword; throws std::logic_error for a keyword without one (a coding error:
// the builder asks only for keywords it gives meaning to).
const KeywordSpec& keywordSpec(std::string_view name);

}  // namespace crumple::deck
