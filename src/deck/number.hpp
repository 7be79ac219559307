// Numbers as LS-DYNA reads them from keyword cards. The solver reads cards with Fortran
// formatted input, so besides the C forms it accepts a "D" exponent (1.0D-3) and an exponent
// written without its letter (2.00000-3 = 2.0e-3, 1.5+2 = 150), the form FORTRAN E-editing
// produces when the exponent has three digits and which older pre-processors still write.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string_view>

namespace crumple::deck {

// The first byte of s[first, last) that is not a space (last if none). Fixed-format fields
// are mostly leading blanks ("               0"): eight at a time, the blanks of the first word
// that is not all blank counted at once (bytes in memory order).
inline std::size_t firstNonSpace(std::string_view s, std::size_t first, std::size_t last) {
  static_assert(std::endian::native == std::endian::little);
  constexpr uint64_t kEightBlanks = 0x2020202020202020ULL;
  for (uint64_t w; last - first >= 8; first += 8) {
    std::memcpy(&w, s.data() + first, 8);
    if (const uint64_t other = w ^ kEightBlanks; other != 0)
      return first + static_cast<std::size_t>(std::countr_zero(other) / 8);
  }
  while (first < last && s[first] == ' ') ++first;
  return first;
}

// Leading and trailing blanks removed. Inline: a deck's fields are trimmed several times each
// (a call was a tenth of the instructions of reading one), and a plain loop, because
// find_first_not_of with a set of characters calls memchr once per character.
inline std::string_view trim(std::string_view s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  std::size_t first = firstNonSpace(s, 0, s.size()), last = s.size();
  while (first < last && blank(s[first])) ++first;
  while (last > first && blank(s[last - 1])) --last;
  return s.substr(first, last - first);
}

// Leading and trailing spaces removed, nothing else: a field read in place (Card::readColumns)
// holds no other blank, since a tab sends its line to the general reading.
inline std::string_view trimSpaces(std::string_view s) {
  std::size_t last = s.size();
  while (last > 0 && s[last - 1] == ' ') --last;
  const std::size_t first = firstNonSpace(s, 0, last);
  return s.substr(first, last - first);
}

// Eight digits read at once from a 64-bit word (Lemire, "Number parsing at a gigabyte per
// second", 2021). `d` is the word XOR eight '0's: a digit byte is then 0..9.
// Non-zero when a byte of `d` is not a digit: 0x76 added keeps a digit's high bit clear (a
// carry between bytes only comes out of a byte already failed).
inline uint64_t nonDigitBytes(uint64_t d) {
  return (d | (d + 0x7676767676767676ULL)) & 0x8080808080808080ULL;
}
// The value of eight digit bytes, the first in memory order the most significant: pairs, quads,
// then all eight by three multiplications.
inline uint64_t eightDigitsValue(uint64_t d) {
  d = d * 10 + (d >> 8);
  return ((d & 0x000000FF000000FFULL) * 0x000F424000000064ULL +
          ((d >> 16) & 0x000000FF000000FFULL) * 0x0000271000000001ULL) >>
         32;
}

// The run of digits at p (advanced past it) appended to `m`, eight at a time while eight are
// left; how many. `m` wraps beyond 19 digits, which the caller refuses.
inline int appendDigits(const char*& p, const char* end, uint64_t& m) {
  const char* const start = p;
  for (uint64_t w; end - p >= 8; p += 8) {
    std::memcpy(&w, p, 8);
    const uint64_t d = w ^ 0x3030303030303030ULL;
    if (nonDigitBytes(d) != 0) break;
    m = m * 100000000 + eightDigitsValue(d);
  }
  for (; p != end && *p >= '0' && *p <= '9'; ++p) m = m * 10 + static_cast<uint64_t>(*p - '0');
  return static_cast<int>(p - start);
}

// The usual decimal number ("-12.5", "3", "1.e5", "2.5E-03", written by pre-processors in
// every field) read in place, exactly: true and `out` set when `s` (trimmed, no '+') is an
// optional '-', at most 19 digits with an optional '.', and an optional e/E exponent, and
// the value is a significand below 2^53 times a power of ten of at most 22. Then one IEEE
// multiplication or division of two exact doubles gives the correctly rounded value, the
// one std::from_chars gives (Clinger, "How to read floating point numbers accurately",
// PLDI 1990, the "fast path"). Anything else is false, and the caller reads it the long way.
inline bool parseSimpleReal(std::string_view s, double& out) {
  static constexpr double kPow10[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                        1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                        1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  const char* p = s.data();
  const char* const end = p + s.size();
  const bool negative = p != end && *p == '-';
  p += negative ? 1 : 0;
  uint64_t m = 0;
  int digits = appendDigits(p, end, m);
  int exponent = 0;
  if (p != end && *p == '.') {
    ++p;
    exponent = -appendDigits(p, end, m);
    digits -= exponent;
  }
  if (digits == 0 || digits > 19) return false;
  if (p != end) {
    if (*p != 'e' && *p != 'E') return false;
    ++p;
    const bool minus = p != end && *p == '-';
    p += p != end && (*p == '-' || *p == '+') ? 1 : 0;
    if (p == end || end - p > 3) return false;
    int e = 0;
    for (; p != end; ++p) {
      if (*p < '0' || *p > '9') return false;
      e = e * 10 + (*p - '0');
    }
    exponent += minus ? -e : e;
  }
  if (m > (uint64_t{1} << 53) || exponent < -22 || exponent > 22) return false;
  const auto x = static_cast<double>(m);
  const double v = exponent < 0 ? x / kPow10[-exponent] : x * kPow10[exponent];
  out = negative ? -v : v;
  return true;
}

// A finite real in any of the forms above; nullopt if `s` (trimmed) is not one.
std::optional<double> parseReal(std::string_view s);

// An integer; an integral real (1.0, 1e3, 2.+1) is accepted, as LS-DYNA does for I fields.
std::optional<int64_t> parseInteger(std::string_view s);

}  // namespace crumple::deck
