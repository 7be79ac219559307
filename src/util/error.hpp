// The two kinds of failure a user sees (ARCHITECTURE.md "Errors"); both end a run with exit 1.
#pragma once

#include <stdexcept>
#include <string>

namespace crumple::util {

// Bad input: the message already names file:line, keyword, card and field.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Input that cannot be read at all (a field that is not a number): unlike an incomplete or
// invalid definition, never excused by the definition being unused.
class FormatError : public InputError {
 public:
  using InputError::InputError;
};

// The solution failed (negative volume, NaN, time-step collapse): names element, part,
// cycle and time. The solver writes the last state before this propagates.
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace crumple::util
