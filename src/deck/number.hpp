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

// Leading and trailing blanks removed. Inline: a deck's fields are trimmed several times each
// (a call was a tenth of the instructions of reading one), and a plain loop, because
// find_first_not_of with a set of characters calls memchr once per character.
inline std::string_view trim(std::string_view s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  std::size_t first = 0, last = s.size();
  // Fixed-format fields are mostly leading blanks ("               0"): eight at a time, the
  // blanks of the first word that is not all blank counted at once (bytes in memory order).
  static_assert(std::endian::native == std::endian::little);
  constexpr uint64_t kEightBlanks = 0x2020202020202020ULL;
  for (uint64_t w; last - first >= 8;) {
    std::memcpy(&w, s.data() + first, 8);
    const uint64_t other = w ^ kEightBlanks;
    first += other == 0 ? 8 : static_cast<std::size_t>(std::countr_zero(other) / 8);
    if (other != 0) break;
  }
  while (first < last && blank(s[first])) ++first;
  while (last > first && blank(s[last - 1])) --last;
  return s.substr(first, last - first);
}

// A finite real in any of the forms above; nullopt if `s` (trimmed) is not one.
std::optional<double> parseReal(std::string_view s);

// An integer; an integral real (1.0, 1e3, 2.+1) is accepted, as LS-DYNA does for I fields.
std::optional<int64_t> parseInteger(std::string_view s);

}  // namespace crumple::deck
