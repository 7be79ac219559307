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
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "deck/layout.hpp"
#include "util/source_loc.hpp"

namespace crumple::deck {

struct DataLine {
  std::string_view text;  // without the line end; a view into Deck::texts
  int32_t file = 0;       // index into Deck::files
  int32_t line = 0;       // 1-based
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
  std::string name;  // as first written, for messages
  char type = 'R';   // 'R' real, 'I' integer, 'C' character
  double value = 0.0;
  std::string text;  // the value as written (the string of a 'C' parameter)
  util::SourceLoc where;
};

// Something the reader accepted but wants the user to know (a duplicate *PARAMETER).
struct ReaderNote {
  std::string keyword, field, reason;
  util::SourceLoc where;
};

// The text of one file as read: a view and what keeps it alive (a mapping of the file, or a
// copy of it in memory).
struct FileText {
  std::shared_ptr<const void> owner;
  std::string_view text;
};

struct Deck {
  std::vector<std::string> files;  // display names, as the user would recognise them
  // What the data lines' views point into: lines are not copied out of the files (a copy per
  // line was one allocation per line of the deck).
  std::vector<std::shared_ptr<const void>> texts;
  std::vector<Keyword> keywords;
  // Keyed by the upper-cased name: LS-DYNA parameter names are case-insensitive (a deck may
  // define tEnd and use &TEnd). Look names up through parameter().
  std::map<std::string, Parameter> parameters;
  std::vector<ReaderNote> notes;
  // With ReadDeckOptions::collect_errors: what was skipped, each as the exception would have
  // said it ("file:line: ...").
  std::vector<std::string> errors;

  // The parameter of that name in any case, or null.
  const Parameter* parameter(std::string_view name) const;

  util::SourceLoc loc(int32_t file, int32_t line) const { return {files.at(file), line}; }
  util::SourceLoc loc(const Keyword& k) const { return loc(k.file, k.line); }
  util::SourceLoc loc(const DataLine& l) const { return loc(l.file, l.line); }
};

// Where the reader gets the text of the deck and of the files it includes: the disk for a
// run, a set of files in memory for the fuzzer and tests (so that fuzzed *INCLUDE lines can
// never read files on the machine).
class Source {
 public:
  virtual ~Source() = default;
  // The file's text, or nullopt when there is no such regular file.
  virtual std::optional<FileText> load(const std::filesystem::path& path) const = 0;
  // One name per file, whatever the spelling ("a/../b.k" and "b.k"): include cycles are
  // recognised by it.
  virtual std::string identity(const std::filesystem::path& path) const = 0;
};

// Maps the file into memory (read-only): reading then costs no copy of the deck.
class DiskSource : public Source {
 public:
  std::optional<FileText> load(const std::filesystem::path& path) const override;
  std::string identity(const std::filesystem::path& path) const override;
};

// Files by name (compared after lexical normalisation); nothing else exists.
class MemorySource : public Source {
 public:
  explicit MemorySource(std::map<std::string, std::string> files);
  std::optional<FileText> load(const std::filesystem::path& path) const override;
  std::string identity(const std::filesystem::path& path) const override;

 private:
  std::map<std::string, std::shared_ptr<const std::string>> files_;
};

// Longest data or keyword line read (characters, without the line end). Real decks use 80
// columns (160 in LONG=Y format, a little more free-format); a longer line means the file is
// not a keyword deck (or its line ends are not "\n").
inline constexpr std::size_t kMaxLineLength = 64 * 1024;

struct ReadDeckOptions {
  // Record an error in one *INCLUDE (the file cannot be opened, a cycle, a bad line in it:
  // too long, binary, encrypted) or in one *PARAMETER / *PARAMETER_EXPRESSION card in
  // Deck::errors and read on without that file (from the bad line on) or parameter, so that
  // one pass lists every such error. The main file failing to open or holding a bad line is
  // still thrown.
  bool collect_errors = false;
};

// Reads `path` and everything it includes. Throws util::InputError naming file:line (for a
// missing include, the *INCLUDE line) on anything that prevents reading: a missing file, an
// include cycle, a line longer than kMaxLineLength, binary data (control characters),
// encrypted input; see ReadDeckOptions for reading on instead.
Deck readDeck(const std::filesystem::path& path);
Deck readDeck(const std::filesystem::path& path, const ReadDeckOptions& options);
Deck readDeck(const std::filesystem::path& path, const Source& source);
Deck readDeck(const std::filesystem::path& path, const Source& source,
              const ReadDeckOptions& options);

}  // namespace crumple::deck
