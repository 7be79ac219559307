// Arithmetic expressions of *PARAMETER_EXPRESSION (LS-DYNA Keyword Manual Vol. I, *PARAMETER):
// + - * / and ** (power, right associative), unary signs, parentheses, numbers in the forms
// of number.hpp, other parameters by name (optionally written &name), and the functions
// sin cos tan asin acos atan atan2 sinh cosh tanh sqrt exp log log10 abs min max mod sign int
// nint.
#pragma once

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace crumple::deck {

// Thrown with a message that names what is wrong in the expression (no location: the caller
// adds file:line and keyword).
class ExpressionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Looks a parameter up by name; nullopt if it is not defined.
using ParameterLookup = std::function<std::optional<double>(std::string_view)>;

double evaluateExpression(std::string_view text, const ParameterLookup& lookup);

}  // namespace crumple::deck
