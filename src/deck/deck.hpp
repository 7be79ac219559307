// A keyword deck as read from disk: the keyword blocks in input order with their data lines
// (comments removed), *INCLUDE files expanded in place, *PARAMETER values collected, and the
// file:line of everything kept for messages. Nothing here knows what a keyword means beyond
// what reading needs (LS-DYNA Keyword Manual Vol. I, "Introduction: keyword format"):
//   *KEYWORD (LONG=Y|S, I10=Y|N), *END, *INCLUDE (+ - % format suffixes), *INCLUDE_PATH,
//   *INCLUDE_PATH_RELATIVE, *PARAMETER, *PARAMETER_EXPRESSION, *PARAMETER_DUPLICATION,
//   *CASE_BEGIN_n / *CASE_END_n blocks and keyword lines with CID=n (marked, not read).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "deck/layout.hpp"
#include "util/source_loc.hpp"

namespace crumple::deck {

struct DataLine {
  std::string text;  // without the line end
  int32_t file = 0;  // index into Deck::files
  int32_t line = 0;  // 1-based
};

struct Keyword {
  std::string name;      // upper case, without a format suffix: "*SET_NODE_LIST_TITLE"
  std::string trailing;  // the rest of the keyword line: "CID=1", "MEMORY=20M", ...
  Format format = Format::Standard;
  int32_t file = 0;
  int32_t line = 0;
  // Non-empty for a keyword that belongs to one load case only (inside *CASE_BEGIN_n ...
  // *CASE_END_n, or written with CID=n): it names the block, and the builder skips it.
  std::string case_block;
  std::vector<DataLine> lines;  // data cards, comments removed, blank lines kept
};

struct Parameter {
  char type = 'R';  // 'R' real, 'I' integer, 'C' character
  double value = 0.0;
  std::string text;  // the value as written (the string of a 'C' parameter)
  util::SourceLoc where;
};

// Something the reader accepted but wants the user to know (a duplicate *PARAMETER).
struct ReaderNote {
  std::string keyword, field, reason;
  util::SourceLoc where;
};

struct Deck {
  std::vector<std::string> files;  // display names, as the user would recognise them
  std::vector<Keyword> keywords;
  std::map<std::string, Parameter> parameters;  // case-sensitive names
  std::vector<ReaderNote> notes;

  util::SourceLoc loc(int32_t file, int32_t line) const { return {files.at(file), line}; }
  util::SourceLoc loc(const Keyword& k) const { return loc(k.file, k.line); }
  util::SourceLoc loc(const DataLine& l) const { return loc(l.file, l.line); }
};

// Reads `path` and everything it includes. Throws util::InputError naming file:line (for a
// missing include, the *INCLUDE line) on anything that prevents reading.
Deck readDeck(const std::filesystem::path& path);

}  // namespace crumple::deck
