// Typed reading of one card against its CardSpec, in fixed (standard, I10, long) or free
// (comma separated) format, with *PARAMETER references (&name, -&name) resolved and
// expressions over them (&a*0.5+&b) evaluated in numeric fields. Every error
// names file:line, keyword, card, field number and field name, e.g.
//   deck.k:123: *MAT_ELASTIC card 1 field 3 (E): 'abc' is not a number
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "deck/deck.hpp"
#include "deck/expression.hpp"
#include "deck/layout.hpp"
#include "util/source_loc.hpp"

namespace crumple::deck {

// The deck's numeric parameters by name, for evaluateExpression (a character parameter is no
// number).
ParameterLookup numericParameters(const Deck& deck);

// A field that was read with a value different from its default but that the code using
// the keyword did not look at: reported so the user learns it is not honoured.
struct UnusedValue {
  std::string keyword, field, value;
  util::SourceLoc where;
};

class Card {
 public:
  // Parses `line` (nullptr: a card absent from the deck, all fields default). Throws
  // util::InputError for a value that is not of the field's type.
  Card(const CardSpec& spec, const DataLine* line, const Keyword& keyword, const Deck& deck);
  // The values view the deck's text and the card's own strings: a copy would view the
  // original's.
  Card(const Card&) = delete;
  Card& operator=(const Card&) = delete;
  // Reads another line into this card, keeping its storage (a list keyword reads one card per
  // record: no allocation per line).
  void assign(const CardSpec& spec, const DataLine* line, const Keyword& keyword, const Deck& deck);

  // Values after defaulting: a blank field, or 0 in a kZeroIsDefault field, gives the default.
  int64_t integer(std::string_view field) const;
  double real(std::string_view field) const;
  std::string text(std::string_view field) const;  // trimmed
  // True when the field was left blank (or the card is absent).
  bool blank(std::string_view field) const;
  bool allBlank() const;

  // "deck.k:12: *PART card 2 field 3 (MID)"
  std::string context(std::string_view field) const;
  [[noreturn]] void fail(std::string_view field, std::string_view message) const;
  util::SourceLoc where() const;
  int32_t fileIndex() const { return file_; }
  int32_t lineNumber() const { return line_; }
  const Keyword& keyword() const { return *keyword_; }
  std::string_view label() const { return spec_->label; }

  // Fields not read through the accessors above whose value differs from the default.
  std::vector<UnusedValue> unusedValues() const;
  // True when the fixed-format line was not in the card's columns (a tab, or blanks inside a
  // numeric field) and was read as blank-separated values in field order instead.
  bool readAsSpaceSeparated() const { return spaced_; }

 private:
  struct Value {
    bool blank = true;
    double num = 0.0;
    int64_t inum = 0;
    std::string_view text;  // into the line, or into owned_
  };
  struct Reference {
    std::string name;
    bool negate = false;
  };
  static std::optional<Reference> plainReference(std::string_view s);
  bool splittable() const;
  bool freeFormat(std::string_view text) const;
  void readFree(std::string_view text);
  // The usual card: fixed columns, every value a plain number or text. False (the card
  // unread) when anything needs the general reading.
  bool readPlainFixed(std::string_view text);
  // The text of each field in the card's columns into `out` (room for every field); how many.
  std::size_t fixedFields(std::string_view text, std::span<std::string_view> out) const;
  bool outOfColumns(std::string_view text, std::span<const std::string_view> fields) const;
  bool readSpaced(std::string_view text);
  std::size_t index(std::string_view field) const;
  // Keeps `text` (a parameter's value) for as long as the card: the value views it.
  std::string_view own(std::string text);
  void parseField(std::size_t i, std::string_view raw);
  void resolveReference(std::size_t i, const Reference& ref);
  double evaluateInline(std::size_t i, std::string_view s) const;
  // Sets a numeric field; `what` names the value if an integer field gets a fraction.
  void setNumber(std::size_t i, double x, const std::string& what);

  const CardSpec* spec_;
  const Keyword* keyword_;
  const Deck* deck_;
  int32_t file_ = 0, line_ = 0;
  std::vector<Value> values_;
  mutable std::vector<uint8_t> used_;  // bytes: assigning them is one memset per line
  // False when the line holds no '&': no field then needs a look for a parameter reference.
  bool references_ = true;
  // Texts that are not in the line (a parameter's value); a deque never moves its elements.
  std::deque<std::string> owned_;
  // Fields are mostly asked for in card order: the search for a name starts after the last.
  mutable std::size_t next_field_ = 0;
  bool spaced_ = false;
};

// Walks the data lines of one keyword, card by card.
class CardCursor {
 public:
  CardCursor(const Keyword& keyword, const Deck& deck) : keyword_(&keyword), deck_(&deck) {}

  bool atEnd() const { return next_ >= keyword_->lines.size(); }
  std::size_t remaining() const { return keyword_->lines.size() - next_; }
  // The next line (precondition: !atEnd()).
  const DataLine& peek() const { return keyword_->lines[next_]; }
  bool nextIsBlank() const;
  // Skips blank lines: list-type keywords (*NODE, *SET_..._LIST) have no meaning for them.
  void skipBlankLines();

  // The next card; throws util::InputError when the keyword has no more lines.
  const Card& read(const CardSpec& spec);
  // The next card, or an all-default card when the keyword has no more lines (trailing
  // optional cards).
  const Card& readOptional(const CardSpec& spec);

  // Hands back the unused non-default values of the cards read since the last call and
  // forgets those cards (list keywords call it per record to keep memory flat).
  std::vector<UnusedValue> flush();
  // Hands back what the cards read so far want the user to know and forgets it: one note per
  // keyword when a card was read as space-separated fields (Card::readAsSpaceSeparated).
  std::vector<ReaderNote> takeNotes();

  const Keyword& keyword() const { return *keyword_; }
  const Deck& deck() const { return *deck_; }

 private:
  const Keyword* keyword_;
  const Deck* deck_;
  const Card& noteSpaced(const Card& card);
  // The next card of cards_ for `line`: a flushed one reused, or a new one.
  const Card& nextCard(const CardSpec& spec, const DataLine* line);

  std::size_t next_ = 0;
  std::deque<Card> cards_;
  std::size_t live_ = 0;  // cards_[0, live_) are read since the last flush; the rest are spare
  std::vector<ReaderNote> notes_;
  bool noted_spaced_ = false;
};

}  // namespace crumple::deck
