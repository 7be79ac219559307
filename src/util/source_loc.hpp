// Where a piece of input came from, so that every message can name file and line.
#pragma once

#include <string>

namespace crumple::util {

struct SourceLoc {
  std::string file;  // path as the user would recognise it (relative to the working dir)
  int line = 0;      // 1-based; 0 = unknown
  std::string str() const { return line > 0 ? file + ":" + std::to_string(line) : file; }
};

}  // namespace crumple::util
