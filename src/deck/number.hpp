// Numbers as LS-DYNA reads them from keyword cards. The solver reads cards with Fortran
// formatted input, so besides the C forms it accepts a "D" exponent (1.0D-3) and an exponent
// written without its letter (2.00000-3 = 2.0e-3, 1.5+2 = 150), the form FORTRAN E-editing
// produces when the exponent has three digits and which older pre-processors still write.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace crumple::deck {

// Leading and trailing blanks removed.
std::string_view trim(std::string_view s);

// A finite real in any of the forms above; nullopt if `s` (trimmed) is not one.
std::optional<double> parseReal(std::string_view s);

// An integer; an integral real (1.0, 1e3, 2.+1) is accepted, as LS-DYNA does for I fields.
std::optional<int64_t> parseInteger(std::string_view s);

}  // namespace crumple::deck
