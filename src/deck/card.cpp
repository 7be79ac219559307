#include "deck/card.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <span>
#include <stdexcept>
#include <utility>

#include "deck/number.hpp"
#include "util/error.hpp"

namespace crumple::deck {

namespace {

// Width of a field in the keyword's format (see Format in layout.hpp).
int effectiveWidth(const FieldSpec& f, Format format) {
  switch (format) {
    case Format::Long:
      return std::max(f.width, 20);
    case Format::I10:
      return std::max(f.width, 10);
    case Format::Standard:
      break;
  }
  return f.width;
}

// A wide text field at the end of a card (a title, a file name, an expression) takes the
// rest of the line, however long, as LS-DYNA's long format allows.
bool takesRestOfLine(const CardSpec& spec, std::size_t i) {
  return i + 1 == spec.fields.size() && spec.fields[i].type == FieldType::Text &&
         spec.fields[i].width >= 70;
}

// The shortest text that reads back as exactly `v`: a parameter put into a text field (an
// expression) keeps its value.
std::string fmtNumber(double v) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, ec == std::errc() ? end : buf);
}

// Which of the characters that change how a line is read it holds: a comma (free format), a
// tab (columns not kept) and '&' (a parameter). One pass over the line, eight bytes at a time
// (a word holds the byte c when w ^ c has a zero byte; the test is exact for the whole word).
struct LineMarks {
  bool comma = false, tab = false, ampersand = false;
  bool any() const { return comma || tab || ampersand; }
};
LineMarks lineMarks(std::string_view s) {
  constexpr uint64_t kOnes = 0x0101010101010101ULL, kHighs = 0x8080808080808080ULL;
  const auto has = [](uint64_t w, char c) {
    const uint64_t x = w ^ (static_cast<uint64_t>(static_cast<unsigned char>(c)) * kOnes);
    return (x - kOnes) & ~x & kHighs;
  };
  uint64_t comma = 0, tab = 0, amp = 0;
  std::size_t i = 0;
  for (; i + 8 <= s.size(); i += 8) {
    uint64_t w;
    std::memcpy(&w, s.data() + i, 8);
    comma |= has(w, ',');
    tab |= has(w, '\t');
    amp |= has(w, '&');
  }
  LineMarks m{comma != 0, tab != 0, amp != 0};
  for (; i < s.size(); ++i) {
    m.comma = m.comma || s[i] == ',';
    m.tab = m.tab || s[i] == '\t';
    m.ampersand = m.ampersand || s[i] == '&';
  }
  return m;
}

// An id or flag as most decks write it: an optional '-' and at most 18 digits (no overflow).
bool parsePlainInteger(std::string_view s, int64_t& out) {
  const bool negative = s[0] == '-';
  s.remove_prefix(negative ? 1 : 0);
  if (s.empty() || s.size() > 18) return false;
  int64_t v = 0;
  for (const char c : s) {
    if (c < '0' || c > '9') return false;
    v = v * 10 + (c - '0');
  }
  out = negative ? -v : v;
  return true;
}

// An integer field as pre-processors write ids and flags: blanks, then at most eight digits
// that end the field (a field of eight columns or more, whole in the line). Read is the value
// and the digits' text, Blank a field of blanks only, Other anything else (a sign, a blank
// after the digits, more digits), left to the scalar reading. The last eight columns are read
// at once (eightDigitsValue), the leading blanks among them as zeros.
enum class Digits : uint8_t { Blank, Read, Other };
[[gnu::always_inline]] inline Digits rightAlignedDigits(std::string_view s, int64_t& value,
                                                        std::size_t& count) {
  if (s.size() < 8 || firstNonSpace(s, 0, s.size() - 8) != s.size() - 8) return Digits::Other;
  uint64_t w;
  std::memcpy(&w, s.data() + s.size() - 8, 8);
  const uint64_t nonblank = w ^ 0x2020202020202020ULL;
  if (nonblank == 0) return Digits::Blank;
  const int blanks = std::countr_zero(nonblank) / 8;  // the first bytes in memory order
  const uint64_t keep = ~uint64_t{0} << (8 * blanks);
  const uint64_t d = w ^ 0x3030303030303030ULL;
  if ((nonDigitBytes(d) & keep) != 0) return Digits::Other;
  value = static_cast<int64_t>(eightDigitsValue(d & keep));
  count = 8 - static_cast<std::size_t>(blanks);
  return Digits::Read;
}

}  // namespace

ParameterLookup numericParameters(const Deck& deck) {
  return [&deck](std::string_view name) -> std::optional<double> {
    const Parameter* p = deck.parameter(name);
    if (!p || p->type == 'C') return std::nullopt;
    return p->value;
  };
}

Card::Card(const CardSpec& spec, const DataLine* line, const Keyword& keyword, const Deck& deck,
           Reading reading) {
  assign(spec, line, keyword, deck, reading);
}

void Card::assign(const CardSpec& spec, const DataLine* line, const Keyword& keyword,
                  const Deck& deck, Reading reading) {
  if (&spec != compiled_ || keyword.format != compiled_format_) compile(spec, keyword.format);
  spec_ = &spec;
  keyword_ = &keyword;
  deck_ = &deck;
  file_ = line ? line->file : keyword.file;
  line_ = line ? line->line : keyword.line;
  used_.assign(spec.fields.size(), 0);
  if (!owned_.empty()) owned_.clear();
  next_field_ = 0;
  spaced_ = false;
  if (line && reading == Reading::Columns && readColumns(line->text)) return;
  values_.assign(spec.fields.size(), Value{});
  if (line) readGeneral(line->text);
}

std::vector<Card::Column> Card::columnsOf(const CardSpec& spec, Format format) {
  std::vector<Column> columns;
  std::size_t col = 0;
  for (std::size_t i = 0; i < spec.fields.size(); ++i) {
    const std::size_t end =
        takesRestOfLine(spec, i)
            ? kRestOfLine
            : col + static_cast<std::size_t>(effectiveWidth(spec.fields[i], format));
    columns.push_back({col, end, spec.fields[i].type});
    col = end;
  }
  return columns;
}

void Card::compile(const CardSpec& spec, Format format) {
  columns_ = columnsOf(spec, format);
  compiled_ = &spec;
  compiled_format_ = format;
}

// Free format when the line has a comma in the right place, else the card's columns, read as
// blank-separated values when they are not kept (a tab, blanks inside a number).
void Card::readGeneral(std::string_view text) {
  const LineMarks marks = lineMarks(text);
  references_ = marks.ampersand;
  if (marks.comma && freeFormat(text)) {
    readFree(text);
    return;
  }
  // The fields on the stack for the usual card (a heap list per card line was one allocation
  // per line of the deck).
  constexpr std::size_t kOnStack = 32;
  std::array<std::string_view, kOnStack> small;
  std::vector<std::string_view> large(spec_->fields.size() > kOnStack ? spec_->fields.size() : 0);
  const std::span<std::string_view> all =
      large.empty() ? std::span<std::string_view>(small.data(), spec_->fields.size())
                    : std::span<std::string_view>(large);
  const auto fields = all.first(fixedFields(text, all));
  for (auto& f : fields) f = trim(f);  // once: the checks and the parse below take them so
  if (outOfColumns(text, fields) && readSpaced(text)) return;
  for (std::size_t i = 0; i < fields.size(); ++i) parseField(i, fields[i]);
}

// Inlined into readColumns: a call per field was a fifth of reading it.
[[gnu::always_inline]] inline bool Card::readPlainField(FieldType type, std::string_view raw,
                                                        Value& v) {
  if (type == FieldType::Int) {
    std::size_t count = 0;
    switch (rightAlignedDigits(raw, v.inum, count)) {
      case Digits::Blank:
        return true;
      case Digits::Read:
        v.num = static_cast<double>(v.inum);
        v.blank = false;
        v.text = std::string_view(raw.data() + raw.size() - count, count);
        return true;
      case Digits::Other:
        break;
    }
  }
  if (type == FieldType::Text && lineMarks(raw).any()) return false;
  const std::string_view s = type == FieldType::Text ? trim(raw) : trimSpaces(raw);
  if (s.empty()) return true;
  if (type == FieldType::Int) {
    if (!parsePlainInteger(s, v.inum)) return false;
    v.num = static_cast<double>(v.inum);
  } else if (type == FieldType::Real) {
    if (!parseSimpleReal(s, v.num)) return false;
  }
  v.blank = false;
  v.text = s;
  return true;
}

// Fixed columns read field by field in one pass over the compiled columns: a blank field
// stays blank, a text field is kept trimmed, a number must be plainly written
// (parsePlainInteger, parseSimpleReal) between spaces. Anything else (a comma, tab or '&' in
// the line, a blank inside a number, another number form, a bad value) leaves the card to the
// general reading, which gives the same values, or the message, as before this path existed.
bool Card::readColumns(std::string_view text) {
  values_.resize(columns_.size());
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    const Column& c = columns_[i];
    Value& v = values_[i];
    v = Value{};
    if (c.begin >= text.size()) continue;
    const std::string_view raw(text.data() + c.begin, std::min(c.end, text.size()) - c.begin);
    if (!readPlainField(c.type, raw, v)) return false;
  }
  // Past the last field: a comma, tab or '&' there changes how the whole line reads.
  const std::size_t covered = columns_.back().end;
  if (covered < text.size() && lineMarks(text.substr(covered)).any()) return false;
  references_ = false;
  return true;
}

PlainRecord::PlainRecord(const CardSpec& spec, Format format)
    : spec_(&spec), integers_(spec.fields.size()), reals_(spec.fields.size()) {
  for (const Card::Column& c : Card::columnsOf(spec, format)) {
    const FieldSpec& f = spec.fields[columns_.size()];
    columns_.push_back({c.begin, c.end, c.type, f.zeroIsDefault(), f.def});
    numeric_ = numeric_ && c.type != FieldType::Text;
  }
}

// Card::readColumns without the card, each field defaulted as Card::integer and Card::real
// default it. A field of blanks and right-aligned digits (ids, and integral coordinates) is
// read here at once, the value readPlainField gives it (a real of at most eight digits is the
// integer's exact double, as parseSimpleReal reads it); any other through readPlainField.
bool PlainRecord::read(std::string_view text) {
  if (!numeric_) return false;
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    const Column& c = columns_[i];
    if (c.end <= text.size()) {
      int64_t value = 0;
      std::size_t count = 0;
      const Digits form = rightAlignedDigits(
          std::string_view(text.data() + c.begin, c.end - c.begin), value, count);
      if (form != Digits::Other) {
        const bool def = form == Digits::Blank || (c.zero_is_default && value == 0);
        integers_[i] = def ? static_cast<int64_t>(c.def) : value;
        reals_[i] = def ? c.def : static_cast<double>(value);
        continue;
      }
    }
    Card::Value v;
    if (c.begin < text.size()) {
      const std::string_view raw(text.data() + c.begin, std::min(c.end, text.size()) - c.begin);
      if (!Card::readPlainField(c.type, raw, v)) return false;
    }
    const bool def = v.blank || (c.zero_is_default && v.num == 0.0);
    integers_[i] = def ? static_cast<int64_t>(c.def) : v.inum;
    reals_[i] = def ? c.def : v.num;
  }
  const std::size_t covered = columns_.back().end;
  return covered >= text.size() || !lineMarks(text.substr(covered)).any();
}

void PlainRecord::wrongField(const FieldSlot& field) const {
  throw std::logic_error("field " + std::string(field.name) + " is of another card than " +
                         std::string(spec_->label) + ", or not an integer field");
}

// A card of one text field (a title, a file name) is never split.
bool Card::splittable() const {
  return spec_->fields.size() > 1 || spec_->fields[0].type != FieldType::Text;
}

// Free format (Keyword Manual, "Free format input"): fields separated by commas. A card
// whose last field is a wide text field is free format only if a comma comes before that
// field's column, so that an expression such as max(a,b) in fixed columns stays whole.
bool Card::freeFormat(std::string_view text) const {
  const std::size_t comma = splittable() ? text.find(',') : std::string_view::npos;
  const std::size_t n = spec_->fields.size();
  if (comma == std::string_view::npos || n == 1 || columns_[n - 1].end != kRestOfLine)
    return comma != std::string_view::npos;
  return comma < columns_[n - 1].begin;
}

void Card::readFree(std::string_view text) {
  std::size_t pos = 0;
  for (std::size_t i = 0; i < spec_->fields.size() && pos <= text.size(); ++i) {
    std::size_t end = columns_[i].end == kRestOfLine ? kRestOfLine : text.find(',', pos);
    if (end == std::string_view::npos) end = text.size();
    parseField(i, text.substr(pos, end - pos));
    pos = end + 1;
  }
}

// The text of each field in the keyword's column widths, up to the end of the line.
std::size_t Card::fixedFields(std::string_view text, std::span<std::string_view> out) const {
  std::size_t n = 0;
  for (; n < columns_.size() && columns_[n].begin < text.size(); ++n)
    out[n] = text.substr(columns_[n].begin, columns_[n].end - columns_[n].begin);
  return n;
}

// A tab inside the line, or a blank inside a numeric field ("0       1": a script wrote 8-wide
// columns into a 10-wide card), means the values are not in the card's columns.
bool Card::outOfColumns(std::string_view text, std::span<const std::string_view> fields) const {
  if (!splittable()) return false;
  // A tab before the trailing blanks (a leading one counts).
  std::size_t end = text.size();
  while (end > 0 && (text[end - 1] == ' ' || text[end - 1] == '\t')) --end;
  if (text.substr(0, end).find('\t') != std::string_view::npos) return true;
  // The fields are trimmed (the caller did it).
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (spec_->fields[i].type == FieldType::Text) continue;
    const std::string_view s = fields[i];
    const bool blank_inside =
        std::any_of(s.begin(), s.end(), [](char c) { return c == ' ' || c == '\t'; });
    if (blank_inside && s.find('&') == std::string_view::npos) return true;
  }
  return false;
}

// Reads the line as blank-separated values in field order, if there are no more values than
// fields and each reads as its field's type; otherwise leaves the card unread (false).
bool Card::readSpaced(std::string_view text) {
  std::vector<std::string_view> tokens;
  for (std::size_t pos = text.find_first_not_of(" \t"); pos != std::string_view::npos;) {
    const std::size_t end = text.find_first_of(" \t", pos);
    tokens.push_back(text.substr(pos, end - pos));
    pos = end == std::string_view::npos ? end : text.find_first_not_of(" \t", end);
  }
  if (tokens.size() > spec_->fields.size()) return false;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const FieldType t = spec_->fields[i].type;
    const bool ok = t == FieldType::Text || tokens[i].find('&') != std::string_view::npos ||
                    (t == FieldType::Real ? parseReal(tokens[i]).has_value()
                                          : parseInteger(tokens[i]).has_value());
    if (!ok) return false;
  }
  for (std::size_t i = 0; i < tokens.size(); ++i) parseField(i, tokens[i]);
  spaced_ = true;
  return true;
}

// "&name", "-&name" (negated) or "+&name": a field that is one *PARAMETER reference (Keyword
// Manual, *PARAMETER). Anything more after the & ("&a*0.5+&b") is an expression instead.
std::optional<Card::Reference> Card::plainReference(std::string_view s) {
  const bool sign = s.size() > 1 && (s[0] == '-' || s[0] == '+') && s[1] == '&';
  if (s[0] != '&' && !sign) return std::nullopt;
  const std::string_view name = trim(s.substr(sign ? 2 : 1));
  const auto nameChar = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  };
  if (name.empty() || !std::all_of(name.begin(), name.end(), nameChar)) return std::nullopt;
  return Reference{std::string(name), s[0] == '-'};
}

void Card::parseField(std::size_t i, std::string_view raw) {
  const FieldSpec& f = spec_->fields[i];
  Value& v = values_[i];
  const std::string_view s = trim(raw);
  if (s.empty()) return;
  v.blank = false;
  v.text = s;
  if (references_) {
    if (const auto ref = plainReference(s)) return resolveReference(i, *ref);
  }
  if (references_ && f.type != FieldType::Text && s.find('&') != std::string_view::npos) {
    const double x = evaluateInline(i, s);
    return setNumber(i, x, "'" + std::string(v.text) + "' = " + fmtNumber(x));
  }
  switch (f.type) {
    case FieldType::Text:
      return;  // an expression in a text field (*PARAMETER_EXPRESSION) stays text
    case FieldType::Real: {
      const auto r = parseReal(s);
      if (!r)
        throw util::FormatError(context(f.name) + ": '" + std::string(s) + "' is not a number");
      v.num = *r;
      return;
    }
    case FieldType::Int: {
      const auto k = parseInteger(s);
      if (!k)
        throw util::FormatError(context(f.name) + ": '" + std::string(s) + "' is not an integer");
      v.inum = *k;
      v.num = static_cast<double>(*k);
      return;
    }
  }
}

void Card::resolveReference(std::size_t i, const Reference& ref) {
  const FieldSpec& f = spec_->fields[i];
  const Parameter* p = deck_->parameter(ref.name);
  if (!p)
    throw util::FormatError(context(f.name) + ": parameter '" + ref.name + "' is not defined");
  if (f.type == FieldType::Text) {
    values_[i].text = own(p->type == 'C' ? p->text : fmtNumber(p->value));
    return;
  }
  if (p->type == 'C')
    fail(f.name, "parameter '" + ref.name + "' is a character parameter, a number is needed");
  setNumber(i, ref.negate ? -p->value : p->value,
            "parameter '" + ref.name + "' = " + fmtNumber(p->value));
}

// A field such as "&tp*0.5+&b" in a numeric field is evaluated like a *PARAMETER_EXPRESSION.
double Card::evaluateInline(std::size_t i, std::string_view s) const {
  try {
    return evaluateExpression(s, numericParameters(*deck_));
  } catch (const ExpressionError& e) {
    throw util::FormatError(context(spec_->fields[i].name) + ": " + e.what());
  }
}

void Card::setNumber(std::size_t i, double x, const std::string& what) {
  Value& v = values_[i];
  v.num = x;
  if (spec_->fields[i].type != FieldType::Int) return;
  if (std::trunc(x) != x) fail(spec_->fields[i].name, what + " is not an integer");
  v.inum = static_cast<int64_t>(x);
}

std::string_view Card::own(std::string text) {
  return owned_.emplace_back(std::move(text));
}

std::size_t Card::index(std::string_view field) const {
  // Names are a few characters: a loop, not a call to memcmp per comparison.
  const auto same = [&](std::string_view name) {
    if (name.size() != field.size()) return false;
    for (std::size_t c = 0; c < name.size(); ++c)
      if (name[c] != field[c]) return false;
    return true;
  };
  const std::size_t n = spec_->fields.size();
  for (std::size_t k = 0, i = next_field_; k < n; ++k, i = i + 1 == n ? 0 : i + 1) {
    if (!same(spec_->fields[i].name)) continue;
    next_field_ = i + 1 == n ? 0 : i + 1;
    return i;
  }
  throw std::logic_error("field " + std::string(field) + " is not in " + std::string(spec_->label) +
                         " of " + keyword_->name);
}

void Card::wrongCard(const FieldSlot& field) const {
  throw std::logic_error("field " + std::string(field.name) + " is of another card than " +
                         std::string(spec_->label) + " of " + keyword_->name);
}

int64_t Card::integer(std::string_view field) const {
  return integerAt(index(field), field);
}

void Card::notInteger(std::size_t i, std::string_view field) const {
  fail(field, "'" + std::string(values_[i].text) + "' is not an integer");
}

double Card::real(std::string_view field) const {
  return realAt(index(field));
}

std::string Card::text(std::string_view field) const {
  const std::size_t i = index(field);
  used_[i] = true;
  const Value& v = values_[i];
  return std::string(v.blank ? spec_->fields[i].text_def : v.text);
}

bool Card::blank(std::string_view field) const {
  return values_[index(field)].blank;
}

bool Card::allBlank() const {
  return std::all_of(values_.begin(), values_.end(), [](const Value& v) { return v.blank; });
}

util::SourceLoc Card::where() const {
  return deck_->loc(file_, line_);
}

std::string Card::context(std::string_view field) const {
  const std::size_t i = index(field);
  return where().str() + ": " + keyword_->name + " " + std::string(spec_->label) + " field " +
         std::to_string(i + 1) + " (" + std::string(field) + ")";
}

void Card::fail(std::string_view field, std::string_view message) const {
  throw util::InputError(context(field) + ": " + std::string(message));
}

std::vector<UnusedValue> Card::unusedValues() const {
  // Mostly every field was asked for (a list keyword's builder reads them all): nothing to say.
  if (std::all_of(used_.begin(), used_.end(), [](uint8_t u) { return u != 0; })) return {};
  std::vector<UnusedValue> out;
  for (std::size_t i = 0; i < values_.size(); ++i) {
    const FieldSpec& f = spec_->fields[i];
    const Value& v = values_[i];
    if (used_[i] || v.blank || f.quiet()) continue;
    if (f.type == FieldType::Text) {
      std::string a(v.text), b(f.text_def);
      for (auto* s : {&a, &b})
        std::transform(s->begin(), s->end(), s->begin(),
                       [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
      if (a == b) continue;
    } else if (v.num == f.def || (f.zeroIsDefault() && v.num == 0.0)) {
      continue;
    }
    out.push_back({keyword_->name, std::string(f.name), std::string(v.text), where()});
  }
  return out;
}

const Card& CardCursor::read(const CardSpec& spec) {
  if (atEnd())
    throw util::InputError(deck_->loc(*keyword_).str() + ": " + keyword_->name + " " +
                           std::string(spec.label) + " is missing");
  return noteSpaced(nextCard(spec, &keyword_->lines[next_++]));
}

const Card& CardCursor::nextCard(const CardSpec& spec, const DataLine* line) {
  if (live_ == cards_.size()) {
    cards_.emplace_back(spec, line, *keyword_, *deck_);
  } else {
    cards_[live_].assign(spec, line, *keyword_, *deck_);
  }
  return cards_[live_++];
}

// Once per keyword: the cards after the first are most likely written by the same script.
const Card& CardCursor::noteSpaced(const Card& card) {
  if (!card.readAsSpaceSeparated() || noted_spaced_) return card;
  noted_spaced_ = true;
  notes_.push_back({keyword_->name, std::string(card.label()),
                    "values not in the card's columns (a tab, or blanks inside a number): read "
                    "as space-separated fields in order",
                    card.where()});
  return card;
}

std::vector<ReaderNote> CardCursor::takeNotes() {
  return std::exchange(notes_, {});
}

const Card& CardCursor::readOptional(const CardSpec& spec) {
  if (atEnd()) return nextCard(spec, nullptr);
  return read(spec);
}

std::vector<UnusedValue> CardCursor::flush() {
  std::vector<UnusedValue> out;
  for (std::size_t k = 0; k < live_; ++k) {
    auto u = cards_[k].unusedValues();
    out.insert(out.end(), u.begin(), u.end());
  }
  live_ = 0;  // kept for reuse
  return out;
}

}  // namespace crumple::deck
