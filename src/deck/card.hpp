// Typed reading of one card against its CardSpec, in fixed (standard, I10, long) or free
// (comma separated) format, with *PARAMETER references (&name, -&name) resolved and
// expressions over them (&a*0.5+&b) evaluated in numeric fields. Every error
// names file:line, keyword, card, field number and field name, e.g.
//   deck.k:123: *MAT_ELASTIC card 1 field 3 (E): 'abc' is not a number
#pragma once

#include <cmath>
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
#include "deck/number.hpp"
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
  // How a line is read. Columns: a line of plainly written values in the card's columns is
  // read in one pass over the compiled columns (readColumns), anything else as General; General
  // only: for tests that compare the two readings value for value.
  enum class Reading : uint8_t { Columns, General };

  // Parses `line` (nullptr: a card absent from the deck, all fields default). Throws
  // util::InputError for a value that is not of the field's type.
  Card(const CardSpec& spec, const DataLine* line, const Keyword& keyword, const Deck& deck,
       Reading reading = Reading::Columns);
  // The values view the deck's text and the card's own strings: a copy would view the
  // original's.
  Card(const Card&) = delete;
  Card& operator=(const Card&) = delete;
  // Reads another line into this card, keeping its storage (a list keyword reads one card per
  // record: no allocation per line).
  void assign(const CardSpec& spec, const DataLine* line, const Keyword& keyword, const Deck& deck,
              Reading reading = Reading::Columns);

  // Values after defaulting: a blank field, or 0 in a kZeroIsDefault field, gives the default.
  // A field by name, or by its slot of this card's layout (found once: no look-up per line).
  int64_t integer(std::string_view field) const;
  int64_t integer(const FieldSlot& field) const;
  double real(std::string_view field) const;
  double real(const FieldSlot& field) const;
  std::string text(std::string_view field) const;  // trimmed
  // True when the field was left blank (or the card is absent).
  bool blank(std::string_view field) const;
  bool blank(const FieldSlot& field) const;
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
  friend class PlainRecord;  // reads its lines as readColumns does, field by readPlainField
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
  // A field's columns in the keyword's format: [begin, end), end kRestOfLine for a wide text
  // field that ends the card. Worked out once per card layout and format (compile), not per
  // field of every line.
  struct Column {
    std::size_t begin = 0, end = 0;
    FieldType type = FieldType::Real;
  };
  static constexpr std::size_t kRestOfLine = std::string_view::npos;
  static std::optional<Reference> plainReference(std::string_view s);
  static std::vector<Column> columnsOf(const CardSpec& spec, Format format);
  void compile(const CardSpec& spec, Format format);
  // The index of a slot of this card's layout (a slot of another layout is a coding error).
  std::size_t slotIndex(const FieldSlot& field) const {
    if (field.card != spec_) [[unlikely]]
      wrongCard(field);
    return field.index;
  }
  [[noreturn]] void wrongCard(const FieldSlot& field) const;
  [[noreturn]] void notInteger(std::size_t i, std::string_view field) const;
  void readGeneral(std::string_view text);
  bool splittable() const;
  bool freeFormat(std::string_view text) const;
  void readFree(std::string_view text);
  // The usual card: fixed columns, every value a plain number or text, no comma, tab or '&'
  // anywhere in the line. False (the card unread) when anything needs the general reading.
  bool readColumns(std::string_view text);
  // One field of such a line into `v` (left blank when it is); false when it needs the general
  // reading. Defined (inline) in card.cpp, where its users are.
  static inline bool readPlainField(FieldType type, std::string_view raw, Value& v);
  // The text of each field in the card's columns into `out` (room for every field); how many.
  std::size_t fixedFields(std::string_view text, std::span<std::string_view> out) const;
  bool outOfColumns(std::string_view text, std::span<const std::string_view> fields) const;
  bool readSpaced(std::string_view text);
  std::size_t index(std::string_view field) const;
  int64_t integerAt(std::size_t i, std::string_view field) const;
  double realAt(std::size_t i) const;
  // Keeps `text` (a parameter's value) for as long as the card: the value views it.
  std::string_view own(std::string text);
  void parseField(std::size_t i, std::string_view raw);
  void resolveReference(std::size_t i, const Reference& ref);
  double evaluateInline(std::size_t i, std::string_view s) const;
  // Sets a numeric field; `what` names the value if an integer field gets a fraction.
  void setNumber(std::size_t i, double x, const std::string& what);

  const CardSpec* spec_ = nullptr;  // a table entry: it outlives the card
  // The layout columns_ was compiled for (a reused card mostly reads the same layout again).
  const CardSpec* compiled_ = nullptr;
  Format compiled_format_ = Format::Standard;
  std::vector<Column> columns_;
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

// Inline: a list keyword reads every field of every line through these.
inline int64_t Card::integerAt(std::size_t i, std::string_view field) const {
  used_[i] = 1;
  const FieldSpec& f = spec_->fields[i];
  const Value& v = values_[i];
  if (v.blank || (f.zeroIsDefault() && v.inum == 0)) return static_cast<int64_t>(f.def);
  if (f.type == FieldType::Real) {
    if (std::trunc(v.num) != v.num) notInteger(i, field);
    return static_cast<int64_t>(v.num);
  }
  return v.inum;
}

inline int64_t Card::integer(const FieldSlot& field) const {
  return integerAt(slotIndex(field), field.name);
}

inline double Card::realAt(std::size_t i) const {
  used_[i] = 1;
  const FieldSpec& f = spec_->fields[i];
  const Value& v = values_[i];
  if (v.blank || (f.zeroIsDefault() && v.num == 0.0)) return f.def;
  return v.num;
}

inline double Card::real(const FieldSlot& field) const {
  return realAt(slotIndex(field));
}

inline bool Card::blank(const FieldSlot& field) const {
  return values_[slotIndex(field)].blank;
}

// A line of a list keyword (*NODE, *ELEMENT_SOLID: a card per line, a line per record) read
// without a Card: its numbers into an array, with no per-line card state, unused-value
// bookkeeping (the builder reads every field) or texts. Only a line the Card would read in one
// pass (Card::readColumns: plain numbers in their columns, no comma, tab or '&' in the line) is
// read, by the same pieces (the right-aligned digit word, Card::readPlainField); any other line
// is the Card's, whose values and messages are the reference
// (DeckCard.PlainRecordsReadAsTheCardReads).
class PlainRecord {
 public:
  // A layout with a text field reads no line (a text keeps the Card).
  PlainRecord(const CardSpec& spec, Format format);

  // True and the values set when `text` is such a line; false (the values unspecified) else.
  bool read(std::string_view text);
  // The values Card::integer of an Int field and Card::real of a numeric field give (blank, or
  // 0 in a kZeroIsDefault field, the default). A slot of another layout, or integer of a Real
  // field (whose fraction is a message), is a std::logic_error.
  int64_t integer(const FieldSlot& field) const {
    if (field.card != spec_ || columns_[field.index].type != FieldType::Int) [[unlikely]]
      wrongField(field);
    return integers_[field.index];
  }
  double real(const FieldSlot& field) const {
    if (field.card != spec_) [[unlikely]]
      wrongField(field);
    return reals_[field.index];
  }

 private:
  [[noreturn]] void wrongField(const FieldSlot& field) const;

  // A field's columns and kind, and what a blank field (or 0 in a kZeroIsDefault one) gives.
  struct Column {
    std::size_t begin = 0, end = 0;
    FieldType type = FieldType::Real;
    bool zero_is_default = false;
    double def = 0.0;
  };
  const CardSpec* spec_;
  std::vector<Column> columns_;
  bool numeric_ = true;  // no text field: a line can be read here
  std::vector<int64_t> integers_;
  std::vector<double> reals_;
};

// Walks the data lines of one keyword, card by card.
class CardCursor {
 public:
  CardCursor(const Keyword& keyword, const Deck& deck) : keyword_(&keyword), deck_(&deck) {}

  bool atEnd() const { return next_ >= keyword_->lines.size(); }
  std::size_t remaining() const { return keyword_->lines.size() - next_; }
  // The next line (precondition: !atEnd()).
  const DataLine& peek() const { return keyword_->lines[next_]; }
  bool nextIsBlank() const {
    if (atEnd()) return false;
    // A data line mostly ends in a value: it needs no trimming to be known not blank (inline:
    // a list keyword asks once per record).
    const std::string_view t = peek().text;
    const char last = t.empty() ? ' ' : t.back();
    return (last == ' ' || last == '\t' || last == '\r' || last == '\n') && trim(t).empty();
  }
  // Skips blank lines: list-type keywords (*NODE, *SET_..._LIST) have no meaning for them.
  void skipBlankLines() {
    while (nextIsBlank()) ++next_;
  }

  // Passes over the next line (precondition: !atEnd()), read without a card (PlainRecord).
  void skipLine() { ++next_; }

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
