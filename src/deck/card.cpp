#include "deck/card.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <stdexcept>

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

}  // namespace

ParameterLookup numericParameters(const Deck& deck) {
  return [&deck](std::string_view name) -> std::optional<double> {
    const Parameter* p = deck.parameter(name);
    if (!p || p->type == 'C') return std::nullopt;
    return p->value;
  };
}

Card::Card(const CardSpec& spec, const DataLine* line, const Keyword& keyword, const Deck& deck)
    : spec_(&spec),
      keyword_(&keyword),
      deck_(&deck),
      file_(line ? line->file : keyword.file),
      line_(line ? line->line : keyword.line),
      values_(spec.fields.size()),
      used_(spec.fields.size(), false) {
  if (!line) return;
  const std::string_view text = line->text;
  const std::size_t n = spec.fields.size();
  // Free format (Keyword Manual, "Free format input"): fields separated by commas. A card
  // whose last field is a wide text field is free format only if a comma comes before that
  // field's column, so that an expression such as max(a,b) in fixed columns stays whole.
  // A card of one text field (a title, a file name) is never split.
  const bool splittable = n > 1 || spec.fields[0].type != FieldType::Text;
  std::size_t comma = splittable ? text.find(',') : std::string_view::npos;
  if (n > 1 && comma != std::string_view::npos && takesRestOfLine(spec, n - 1)) {
    int start = 0;
    for (std::size_t i = 0; i + 1 < n; ++i) start += effectiveWidth(spec.fields[i], keyword.format);
    if (comma >= static_cast<std::size_t>(start)) comma = std::string_view::npos;
  }
  if (comma != std::string_view::npos) {
    std::size_t pos = 0;
    for (std::size_t i = 0; i < n && pos <= text.size(); ++i) {
      std::size_t end = takesRestOfLine(spec, i) ? std::string_view::npos : text.find(',', pos);
      if (end == std::string_view::npos) end = text.size();
      parseField(i, text.substr(pos, end - pos));
      pos = end + 1;
    }
    return;
  }
  std::size_t col = 0;
  for (std::size_t i = 0; i < n && col < text.size(); ++i) {
    const std::size_t w =
        takesRestOfLine(spec, i)
            ? std::string_view::npos
            : static_cast<std::size_t>(effectiveWidth(spec.fields[i], keyword.format));
    parseField(i, text.substr(col, w));
    col = w == std::string_view::npos ? text.size() : col + w;
  }
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
  v.text = std::string(s);
  if (const auto ref = plainReference(s)) return resolveReference(i, *ref);
  if (f.type != FieldType::Text && s.find('&') != std::string_view::npos) {
    const double x = evaluateInline(i, s);
    return setNumber(i, x, "'" + v.text + "' = " + fmtNumber(x));
  }
  switch (f.type) {
    case FieldType::Text:
      return;  // an expression in a text field (*PARAMETER_EXPRESSION) stays text
    case FieldType::Real: {
      const auto r = parseReal(s);
      if (!r) fail(f.name, "'" + v.text + "' is not a number");
      v.num = *r;
      return;
    }
    case FieldType::Int: {
      const auto k = parseInteger(s);
      if (!k) fail(f.name, "'" + v.text + "' is not an integer");
      v.inum = *k;
      v.num = static_cast<double>(*k);
      return;
    }
  }
}

void Card::resolveReference(std::size_t i, const Reference& ref) {
  const FieldSpec& f = spec_->fields[i];
  const Parameter* p = deck_->parameter(ref.name);
  if (!p) fail(f.name, "parameter '" + ref.name + "' is not defined");
  if (f.type == FieldType::Text) {
    values_[i].text = p->type == 'C' ? p->text : fmtNumber(p->value);
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
    fail(spec_->fields[i].name, e.what());
  }
}

void Card::setNumber(std::size_t i, double x, const std::string& what) {
  Value& v = values_[i];
  v.num = x;
  if (spec_->fields[i].type != FieldType::Int) return;
  if (std::trunc(x) != x) fail(spec_->fields[i].name, what + " is not an integer");
  v.inum = static_cast<int64_t>(x);
}

std::size_t Card::index(std::string_view field) const {
  for (std::size_t i = 0; i < spec_->fields.size(); ++i)
    if (spec_->fields[i].name == field) return i;
  throw std::logic_error("field " + std::string(field) + " is not in " + std::string(spec_->label) +
                         " of " + keyword_->name);
}

int64_t Card::integer(std::string_view field) const {
  const std::size_t i = index(field);
  used_[i] = true;
  const FieldSpec& f = spec_->fields[i];
  const Value& v = values_[i];
  if (v.blank || (f.zeroIsDefault() && v.inum == 0)) return static_cast<int64_t>(f.def);
  if (f.type == FieldType::Real) {
    if (std::trunc(v.num) != v.num) fail(field, "'" + v.text + "' is not an integer");
    return static_cast<int64_t>(v.num);
  }
  return v.inum;
}

double Card::real(std::string_view field) const {
  const std::size_t i = index(field);
  used_[i] = true;
  const FieldSpec& f = spec_->fields[i];
  const Value& v = values_[i];
  if (v.blank || (f.zeroIsDefault() && v.num == 0.0)) return f.def;
  return v.num;
}

std::string Card::text(std::string_view field) const {
  const std::size_t i = index(field);
  used_[i] = true;
  const Value& v = values_[i];
  return v.blank ? std::string(spec_->fields[i].text_def) : v.text;
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
  std::vector<UnusedValue> out;
  for (std::size_t i = 0; i < values_.size(); ++i) {
    const FieldSpec& f = spec_->fields[i];
    const Value& v = values_[i];
    if (used_[i] || v.blank || f.quiet()) continue;
    if (f.type == FieldType::Text) {
      std::string a = v.text, b(f.text_def);
      for (auto* s : {&a, &b})
        std::transform(s->begin(), s->end(), s->begin(),
                       [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
      if (a == b) continue;
    } else if (v.num == f.def || (f.zeroIsDefault() && v.num == 0.0)) {
      continue;
    }
    out.push_back({keyword_->name, std::string(f.name), v.text, where()});
  }
  return out;
}

bool CardCursor::nextIsBlank() const {
  return !atEnd() && trim(peek().text).empty();
}

void CardCursor::skipBlankLines() {
  while (nextIsBlank()) ++next_;
}

const Card& CardCursor::read(const CardSpec& spec) {
  if (atEnd())
    throw util::InputError(deck_->loc(*keyword_).str() + ": " + keyword_->name + " " +
                           std::string(spec.label) + " is missing");
  return cards_.emplace_back(spec, &keyword_->lines[next_++], *keyword_, *deck_);
}

const Card& CardCursor::readOptional(const CardSpec& spec) {
  if (atEnd()) return cards_.emplace_back(spec, nullptr, *keyword_, *deck_);
  return read(spec);
}

std::vector<UnusedValue> CardCursor::flush() {
  std::vector<UnusedValue> out;
  for (const Card& c : cards_) {
    auto u = c.unusedValues();
    out.insert(out.end(), u.begin(), u.end());
  }
  cards_.clear();
  return out;
}

}  // namespace crumple::deck
