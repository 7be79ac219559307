// Compiled by ctest (tests/CMakeLists.txt, compile.field_count_*): with FIELDS equal to the
// struct's member count it must compile, with one fewer (a member added to a struct and
// forgotten in its serialiser's list) it must not.
#include <string>

#include "util/fields.hpp"

struct ThreeFields {
  int a = 0;
  double b = 0.0;
  std::string c;
};

int main() {
  crumple::util::fieldCount<FIELDS>(ThreeFields{});
  return 0;
}
