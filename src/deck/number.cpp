#include "deck/number.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

namespace crumple::deck {

namespace {
bool isDigit(char c) {
  return c >= '0' && c <= '9';
}

std::optional<double> fromChars(const std::string& t) {
  double v = 0;
  const char* begin = t.data();
  const char* end = t.data() + t.size();
  auto [ptr, ec] = std::from_chars(begin, end, v);
  if (ec != std::errc() || ptr != end || !std::isfinite(v)) return std::nullopt;
  return v;
}
}  // namespace

std::optional<double> parseReal(std::string_view s) {
  s = trim(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return std::nullopt;
  // The usual number is C's: read in place. from_chars stops at a 'd' exponent or a Fortran
  // exponent without its letter ("1.5-3"), and "inf"/"nan" are not finite: those go on below.
  double fast = 0;
  if (parseSimpleReal(s, fast)) return fast;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), fast);
  if (ec == std::errc() && ptr == s.data() + s.size() && std::isfinite(fast)) return fast;
  std::string t(s);
  bool has_digit = false;
  for (char& c : t) {
    if (c == 'd' || c == 'D') c = 'e';
    has_digit = has_digit || isDigit(c);
  }
  // from_chars would accept "inf" and "nan"; a deck value must contain a digit.
  if (!has_digit) return std::nullopt;
  // Fortran exponent without its letter: a sign that follows a digit or the decimal point.
  for (std::size_t i = 1; i < t.size(); ++i) {
    if ((t[i] == '+' || t[i] == '-') && (isDigit(t[i - 1]) || t[i - 1] == '.')) {
      t.insert(i, 1, 'e');
      break;
    }
  }
  return fromChars(t);
}

std::optional<int64_t> parseInteger(std::string_view s) {
  s = trim(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return std::nullopt;
  // The usual id or flag: up to 18 digits cannot overflow, so no check per digit.
  if (s.size() <= 18 && std::all_of(s.begin(), s.end(), isDigit)) {
    int64_t v = 0;
    for (const char c : s) v = v * 10 + (c - '0');
    return v;
  }
  int64_t v = 0;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec == std::errc() && ptr == s.data() + s.size()) return v;
  const auto r = parseReal(s);
  // 2^63 is exactly representable; anything at or beyond it does not fit an int64_t.
  if (!r || std::trunc(*r) != *r || std::fabs(*r) >= 9223372036854775808.0) return std::nullopt;
  return static_cast<int64_t>(*r);
}

}  // namespace crumple::deck
