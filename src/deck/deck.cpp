#include "deck/deck.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include "deck/card.hpp"
#include "deck/expression.hpp"
#include "deck/number.hpp"
#include "util/error.hpp"

namespace crumple::deck {

namespace {

namespace fs = std::filesystem;

std::string upper(std::string_view s) {
  std::string u(s);
  std::transform(u.begin(), u.end(), u.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return u;
}

bool startsWith(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

std::optional<Format> formatSuffix(char c) {
  if (c == '+') return Format::Long;
  if (c == '-') return Format::Standard;
  if (c == '%') return Format::I10;
  return std::nullopt;
}

struct KeywordLine {
  std::string name, trailing;
  std::optional<Format> format;  // from a + - % suffix
};

// "*NODE +", "*NODE+", "*TITLE CID=1", "*KEYWORD MEMORY=20M": the name is the first word; a
// format suffix may be glued to it or be the next word (Keyword Manual, "*KEYWORD").
KeywordLine parseKeywordLine(std::string_view line) {
  KeywordLine k;
  line = trim(line);
  const std::size_t end = line.find_first_of(" \t");
  std::string_view name = line.substr(0, end);
  std::string_view rest =
      end == std::string_view::npos ? std::string_view{} : trim(line.substr(end));
  if (name.size() > 1 && (k.format = formatSuffix(name.back()))) {
    name.remove_suffix(1);
  } else if (!rest.empty() && (rest.size() == 1 || rest[1] == ' ' || rest[1] == '\t') &&
             (k.format = formatSuffix(rest[0]))) {
    rest = trim(rest.substr(1));
  }
  k.name = upper(name);
  k.trailing = std::string(rest);
  return k;
}

// The format a *KEYWORD line sets: LONG=Y 20-character fields, LONG=S standard, I10=Y at
// least 10 characters. Anything else on the line (a memory size "*KEYWORD 100000000",
// MEMORY=20M, NCPU=4) does not concern reading.
Format keywordFormat(std::string_view trailing, Format format) {
  const std::string t = upper(trailing);
  if (t.find("LONG=Y") != std::string::npos) format = Format::Long;
  if (t.find("LONG=S") != std::string::npos) format = Format::Standard;
  if (t.find("I10=Y") != std::string::npos) format = Format::I10;
  if (t.find("I10=N") != std::string::npos) format = Format::Standard;
  return format;
}

// "CID=3" on a keyword line makes the keyword belong to load case 3 only (*CASE).
bool hasCaseId(std::string_view trailing) {
  const std::string u = upper(trailing);
  const auto p = u.find("CID=");
  return p != std::string::npos && (p == 0 || u[p - 1] == ' ' || u[p - 1] == '\t');
}

// The first character that is not a blank (a space or a tab; a line holds no other).
std::size_t firstNonBlank(std::string_view line) {
  std::size_t first = firstNonSpace(line, 0, line.size());
  while (first < line.size() && (line[first] == ' ' || line[first] == '\t')) ++first;
  return first;
}

// A control character other than tab, form feed, vertical tab and the DOS end-of-file mark
// means binary data: keyword decks are text.
bool isBinary(unsigned char u) {
  const bool allowed = u == '\t' || u == '\f' || u == '\v' || u == 0x1a || u == '\n' || u == '\r';
  return (u < 0x20 || u == 0x7f) && !allowed;
}

// Bytes below 0x20 and DEL, by their high bit. A byte's low seven bits plus one, wrapped to
// seven bits (DEL to 0), are below 0x21 exactly for those; a byte of 0x80 or above (UTF-8,
// Latin-1 text) is not one. No carry crosses a byte, so every byte is told exactly.
uint64_t controlBytes(uint64_t w) {
  constexpr uint64_t kLow7 = 0x7f7f7f7f7f7f7f7fULL;
  const uint64_t t = ((w & kLow7) + 0x0101010101010101ULL) & kLow7;
  return ~((t + 0x5f5f5f5f5f5f5f5fULL) | w) & 0x8080808080808080ULL;
}

// Offset of the first binary byte of `text` (isBinary, or a "\r": the caller has removed the
// one that ends a line), or npos. Eight
// bytes at a time: a word none of whose bytes is below 0x20 or 0x7f needs no closer look (a
// branch per byte was a fifth of reading a deck).
std::size_t firstBinaryByte(std::string_view text) {
  std::size_t i = 0;
  for (; i + 8 <= text.size(); i += 8) {
    uint64_t w;
    std::memcpy(&w, text.data() + i, 8);
    if (controlBytes(w) == 0) continue;
    for (std::size_t k = i; k < i + 8; ++k)
      if (isBinary(static_cast<unsigned char>(text[k])) || text[k] == '\r') return k;
  }
  for (; i < text.size(); ++i)
    if (isBinary(static_cast<unsigned char>(text[i])) || text[i] == '\r') return i;
  return std::string_view::npos;
}

// Where the line at `start` ends (its "\n", or the "\r" of its "\r\n", or the end of the
// text) when it holds no control byte but tabs and is not too long: the line end and the
// binary check in one pass, eight bytes at a time (a memchr, then a scan of the line, were
// each about as much); npos for any other line, which LineSplitter::next reads carefully.
std::size_t plainLineEnd(std::string_view text, std::size_t start) {
  const std::size_t limit = std::min(text.size(), start + kMaxLineLength);
  const auto end = [&](std::size_t k) {
    const bool dos = text[k] == '\r' && k + 1 < text.size() && text[k + 1] == '\n';
    return text[k] == '\n' || dos ? k : std::string_view::npos;
  };
  // Sixteen bytes a step (two words, one test), then eight; a tab is passed over.
  std::size_t i = start;
  for (std::size_t step = 16; step >= 8; step /= 2) {
    while (i + step <= limit) {
      uint64_t a, b = 0;
      std::memcpy(&a, text.data() + i, 8);
      if (step == 16) std::memcpy(&b, text.data() + i + 8, 8);
      const uint64_t first = controlBytes(a), second = step == 16 ? controlBytes(b) : 0;
      if ((first | second) == 0) {
        i += step;
        continue;
      }
      const int bit = first != 0 ? std::countr_zero(first) : 64 + std::countr_zero(second);
      const std::size_t k = i + static_cast<std::size_t>(bit / 8);
      if (text[k] != '\t') return end(k);
      i = k + 1;
    }
  }
  for (; i < limit; ++i)
    if (text[i] != '\t' && (static_cast<unsigned char>(text[i]) < 0x20 || text[i] == 0x7f))
      return end(i);
  return limit == text.size() ? limit : std::string_view::npos;
}

// The lines of a file's text one at a time, each without its end ("\n", or "\r\n" with the
// "\r" removed), as views into the text. A line longer than kMaxLineLength, or one holding a
// binary byte (isBinary, or a "\r" before its end), is an error: the lines before it are
// read, and nothing after it is looked at (a 2 GB line costs no more than its first 64 KiB).
class LineSplitter {
 public:
  LineSplitter(std::string_view text, const std::string& display)
      : text_(text), display_(display) {}

  // The next line into `line`; false when the text is exhausted.
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    ++line_no_;
    const std::size_t start = pos_;
    if (const std::size_t end = plainLineEnd(text_, start); end != std::string_view::npos) {
      line = text_.substr(start, end - start);
      pos_ = end + (end < text_.size() && text_[end] == '\r' ? 2 : 1);
      return true;
    }
    const std::size_t searched = std::min(text_.size() - start, kMaxLineLength + 2);
    const void* nl = std::memchr(text_.data() + start, '\n', searched);
    const std::size_t end =
        nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - text_.data())
           : start + searched;
    line = text_.substr(start, end - start);
    pos_ = end + 1;
    if (line.size() > kMaxLineLength) {
      throw util::InputError(fmt::format(
          "{}:{}: line longer than {} characters: this is not a keyword deck (or a line end is "
          "missing)",
          display_, line_no_, kMaxLineLength));
    }
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::size_t bad = firstBinaryByte(line);
    if (bad != std::string_view::npos) failBinary(line[bad], bad);
    return true;
  }
  int32_t lineNumber() const { return line_no_; }

 private:
  [[noreturn]] void failBinary(char byte, std::size_t at) const {
    throw util::InputError(
        fmt::format("{}:{}: byte 0x{:02x} in column {}: binary data, not a keyword deck (text)",
                    display_, line_no_, static_cast<unsigned char>(byte), at + 1));
  }

  std::string_view text_;
  const std::string& display_;
  std::size_t pos_ = 0;
  int32_t line_no_ = 0;
};

class Reader {
 public:
  // `main` is the deck's main file: *INCLUDE_PATH_RELATIVE entries are relative to its folder.
  Reader(Deck& deck, const Source& source, const fs::path& main, const ReadDeckOptions& options)
      : deck_(deck),
        source_(source),
        options_(options),
        main_{main.parent_path(), main.parent_path()} {}

  // `path` opens the file's includes (relative to its folder), `identity` recognises cycles,
  // `display` names it in messages.
  void readFile(const FileText& text, const fs::path& path, const std::string& identity,
                const std::string& display, Format format, int depth);

 private:
  struct FileState {
    fs::path dir;          // for opening files
    fs::path display_dir;  // for naming them
    Format format;
  };

  void finish(Keyword& kw, FileState& file, int depth);
  struct SearchDir {
    fs::path dir, display;
  };
  struct Candidate {
    fs::path full;
    std::string display;
  };

  void include(const Keyword& kw, FileState& file, int depth);
  void includeFile(const Card& card, const std::string& name, FileState& file, int depth);
  std::vector<Candidate> includeCandidates(const std::string& name, const FileState& file) const;
  void includePath(const Keyword& kw, const FileState& file);
  void parameters(const Keyword& kw);
  void parameter(const Card& card, int k);
  void parameterExpressions(const Keyword& kw);
  void parameterDuplication(const Keyword& kw);
  void define(const Card& card, std::string_view field, char type, const std::string& name,
              Parameter p);

  // Runs `step`; with ReadDeckOptions::collect_errors, an InputError from it is recorded in
  // Deck::errors and reading goes on without what `step` would have read.
  template <class Step>
  void attempt(Step&& step) {
    if (!options_.collect_errors) return step();
    try {
      step();
    } catch (const util::InputError& e) {
      deck_.errors.emplace_back(e.what());
    }
  }

  Deck& deck_;
  const Source& source_;
  const ReadDeckOptions options_;
  // The files being read, outermost first (identity, display name): an *INCLUDE of one of
  // them is a cycle.
  std::vector<std::pair<std::string, std::string>> open_;
  SearchDir main_;
  std::vector<SearchDir> search_;
  int dflag_ = 1;
  std::string case_block_;
};

void Reader::readFile(const FileText& text, const fs::path& path, const std::string& identity,
                      const std::string& display, Format format, int depth) {
  const auto file_index = static_cast<int32_t>(deck_.files.size());
  deck_.files.push_back(display);
  deck_.texts.push_back(text.owner);
  FileState file{path.parent_path(), fs::path(display).parent_path(), format};
  open_.emplace_back(identity, display);
  // Closed however reading ends: with collect_errors the includer reads on after an error.
  struct Close {
    std::vector<std::pair<std::string, std::string>>& open;
    ~Close() { open.pop_back(); }
  } close{open_};

  std::optional<Keyword> current;
  LineSplitter lines(text.text, display);
  std::string_view line;
  while (lines.next(line)) {
    const int32_t line_no = lines.lineNumber();
    // Encrypted input (Keyword Manual, "Encryption"): only LS-DYNA holds the key, and the
    // cipher text that follows would otherwise be reported as binary data.
    // Only its first non-blank character tells what a line is (a trim of the whole line was
    // a tenth of reading it).
    const std::string_view from = line.substr(firstNonBlank(line));
    if (!from.empty() && from[0] == '-' && startsWith(from, "-----BEGIN PGP MESSAGE-----"))
      throw util::InputError(display + ":" + std::to_string(line_no) +
                             ": encrypted (PGP) input cannot be read");
    if (!from.empty() && from[0] == '$') continue;  // a comment
    if (line.empty() || line[0] != '*') {
      // Lines before the first keyword (a header) are not part of any keyword.
      if (current) current->lines.push_back({line, file_index, line_no});
      continue;
    }
    if (current) finish(*current, file, depth);
    current.reset();
    KeywordLine k = parseKeywordLine(line);
    if (k.name == "*END") break;  // the rest of this file is not read (Keyword Manual, *END)
    if (k.name == "*KEYWORD") {
      file.format = keywordFormat(k.trailing, file.format);
      continue;
    }
    if (startsWith(k.name, "*CASE_BEGIN")) {
      case_block_ = k.name;
      continue;
    }
    if (startsWith(k.name, "*CASE_END")) {
      case_block_.clear();
      continue;
    }
    current.emplace();
    current->name = std::move(k.name);
    current->trailing = std::move(k.trailing);
    current->format = k.format.value_or(file.format);
    current->file = file_index;
    current->line = line_no;
    if (!case_block_.empty())
      current->case_block = case_block_;
    else if (hasCaseId(current->trailing))
      current->case_block = current->trailing;
  }
  if (current) finish(*current, file, depth);
}

void Reader::finish(Keyword& kw, FileState& file, int depth) {
  if (!kw.case_block.empty()) {
    deck_.keywords.push_back(std::move(kw));
    return;
  }
  if (kw.name == "*INCLUDE") return include(kw, file, depth);
  if (kw.name == "*INCLUDE_PATH" || kw.name == "*INCLUDE_PATH_RELATIVE")
    return includePath(kw, file);
  if (kw.name == "*PARAMETER") return parameters(kw);
  if (kw.name == "*PARAMETER_EXPRESSION") return parameterExpressions(kw);
  if (kw.name == "*PARAMETER_DUPLICATION") return parameterDuplication(kw);
  deck_.keywords.push_back(std::move(kw));
}

void Reader::include(const Keyword& kw, FileState& file, int depth) {
  const CardSpec& spec = keywordSpec("*INCLUDE").card("card 1");
  CardCursor cur(kw, deck_);
  cur.skipBlankLines();
  // One file name per line, as many lines as there are files (Keyword Manual, *INCLUDE).
  while (!cur.atEnd()) {
    attempt([&] {
      const Card& card = cur.read(spec);
      // A name longer than a line continues on the next line after a trailing " +".
      std::string name = card.text("FILENAME");
      while (name.size() >= 2 && name.substr(name.size() - 2) == " +" && !cur.atEnd()) {
        name.resize(name.size() - 2);
        name += cur.read(spec).text("FILENAME");
      }
      includeFile(card, name, file, depth);
    });
    cur.flush();
    cur.skipBlankLines();
  }
}

void Reader::includeFile(const Card& card, const std::string& name, FileState& file, int depth) {
  if (depth > 40)
    card.fail("FILENAME", "*INCLUDE nested more than 40 deep (does a file include itself?)");
  std::string tried;
  for (const auto& c : includeCandidates(name, file)) {
    const auto in = source_.load(c.full);
    if (!in) {
      tried += (tried.empty() ? "" : ", ") + c.display;
      continue;
    }
    const std::string identity = source_.identity(c.full);
    const auto again = std::find_if(open_.begin(), open_.end(),
                                    [&](const auto& o) { return o.first == identity; });
    if (again != open_.end()) {
      // Reading on would never end: name the chain so the user sees which line to cut.
      std::string chain;
      for (auto o = again; o != open_.end(); ++o) chain += o->second + " -> ";
      card.fail("FILENAME", "include cycle: " + chain + c.display);
    }
    return readFile(*in, c.full, identity, c.display, card.keyword().format, depth + 1);
  }
  // A name is the whole line, blanks included, as LS-DYNA reads it: "a.k b.k" is one name.
  const std::string hint = name.find_first_of(" \t") == std::string::npos
                               ? ""
                               : "; *INCLUDE takes one file name per line";
  throw util::InputError(deck_.loc(card.keyword()).str() + ": " + card.keyword().name +
                         ": cannot open '" + name + "' (tried " + tried + ")" + hint);
}

// Where an *INCLUDE name may be, in order: the name (backslashes read as '/') in the
// including file's folder, then in the *INCLUDE_PATH folders; then its last component in the
// same folders, so that a deck written on another machine ("D:\models\mesh.k") finds the file
// beside it. An absolute name is tried as written; a Windows drive path never is.
std::vector<Reader::Candidate> Reader::includeCandidates(const std::string& name,
                                                         const FileState& file) const {
  std::string written = name;
  std::replace(written.begin(), written.end(), '\\', '/');
  const fs::path p(written);
  const bool drive = written.size() > 1 && std::isalpha(static_cast<unsigned char>(written[0])) &&
                     written[1] == ':';
  std::vector<SearchDir> dirs{{file.dir, file.display_dir}};
  dirs.insert(dirs.end(), search_.begin(), search_.end());
  std::vector<Candidate> out;
  auto add = [&](const fs::path& full, const fs::path& display) {
    const std::string shown = display.lexically_normal().string();
    const bool seen =
        std::any_of(out.begin(), out.end(), [&](const Candidate& c) { return c.display == shown; });
    if (!seen) out.push_back({full, shown});
  };
  if (p.is_absolute()) {
    add(p, p);
  } else if (!drive) {
    for (const auto& d : dirs) add(d.dir / p, d.display / p);
  }
  const fs::path base = p.filename();
  if (!base.empty())
    for (const auto& d : dirs) add(d.dir / base, d.display / base);
  return out;
}

// Directories searched for *INCLUDE files after the including file's own folder, in order
// (Keyword Manual, *INCLUDE_PATH). *INCLUDE_PATH_RELATIVE entries are relative to the folder
// of the main deck (Keyword Manual, *INCLUDE_PATH_RELATIVE), so that a shared file can name
// folders beside the case that includes it; relative *INCLUDE_PATH entries are taken relative
// to the file that holds them.
void Reader::includePath(const Keyword& kw, const FileState& file) {
  const CardSpec& spec = keywordSpec("*INCLUDE_PATH").card("card 1");
  const SearchDir& base =
      kw.name == "*INCLUDE_PATH_RELATIVE" ? main_ : SearchDir{file.dir, file.display_dir};
  CardCursor cur(kw, deck_);
  cur.skipBlankLines();
  while (!cur.atEnd()) {
    std::string written = cur.read(spec).text("PATH");
    std::replace(written.begin(), written.end(), '\\', '/');
    const fs::path p(written);
    if (p.is_absolute())
      search_.push_back({p, p});
    else
      search_.push_back({base.dir / p, (base.display / p).lexically_normal()});
    cur.flush();
    cur.skipBlankLines();
  }
}

// *PARAMETER_DUPLICATION DFLAG (Keyword Manual, *PARAMETER_DUPLICATION): 1 warn and keep the
// first definition (default), 2 warn and take the new one, 3 error, 4 take the new one
// silently, 5 keep the first silently.
void Reader::define(const Card& card, std::string_view field, char type, const std::string& name,
                    Parameter p) {
  p.name = name;
  p.type = type;
  p.where = card.where();
  auto it = deck_.parameters.find(upper(name));
  if (it == deck_.parameters.end()) {
    deck_.parameters.emplace(upper(name), std::move(p));
    return;
  }
  const std::string first = it->second.where.str();
  switch (dflag_) {
    case 3:
      card.fail(field, "parameter '" + name + "' is already defined at " + first +
                           " (*PARAMETER_DUPLICATION DFLAG=3)");
    case 2:
    case 4:
      if (dflag_ == 2)
        deck_.notes.push_back({card.keyword().name, name,
                               "duplicate definition replaces the one at " + first +
                                   " (*PARAMETER_DUPLICATION DFLAG=2)",
                               card.where()});
      it->second = std::move(p);
      return;
    case 5:
      return;
    default:
      deck_.notes.push_back({card.keyword().name, name,
                             "duplicate definition ignored, the one at " + first +
                                 " is kept (*PARAMETER_DUPLICATION DFLAG=1)",
                             card.where()});
      return;
  }
}

namespace {
// PRMR: the type letter R, I or C, then the name ("R vel", "I  n"; Keyword Manual *PARAMETER).
std::pair<char, std::string> typeAndName(const Card& card, std::string_view field) {
  const std::string s = card.text(field);
  const char t = static_cast<char>(std::toupper(static_cast<unsigned char>(s[0])));
  if (t != 'R' && t != 'I' && t != 'C')
    card.fail(field, "'" + s + "' does not start with the type R, I or C");
  std::string name(trim(std::string_view(s).substr(1)));
  if (name.empty()) card.fail(field, "'" + s + "' has no parameter name after the type");
  return {t, name};
}
}  // namespace

void Reader::parameters(const Keyword& kw) {
  const CardSpec& spec = keywordSpec("*PARAMETER").card("card 1");
  CardCursor cur(kw, deck_);
  cur.skipBlankLines();
  while (!cur.atEnd()) {
    attempt([&] {
      const Card& card = cur.read(spec);
      for (int k = 1; k <= 4; ++k) attempt([&] { parameter(card, k); });
    });
    cur.flush();
    cur.skipBlankLines();
  }
}

// The k-th PRMRk / VALk pair of a *PARAMETER card, if not blank.
void Reader::parameter(const Card& card, int k) {
  const std::string prmr = "PRMR" + std::to_string(k), val = "VAL" + std::to_string(k);
  if (card.blank(prmr)) return;
  const auto [type, name] = typeAndName(card, prmr);
  Parameter p;
  p.text = card.text(val);
  if (type == 'R') {
    const auto v = parseReal(p.text);
    if (!v) card.fail(val, "'" + p.text + "' is not a number");
    p.value = *v;
  } else if (type == 'I') {
    const auto v = parseInteger(p.text);
    if (!v) card.fail(val, "'" + p.text + "' is not an integer");
    p.value = static_cast<double>(*v);
  }
  define(card, prmr, type, name, std::move(p));
}

void Reader::parameterExpressions(const Keyword& kw) {
  const CardSpec& spec = keywordSpec("*PARAMETER_EXPRESSION").card("card 1");
  CardCursor cur(kw, deck_);
  cur.skipBlankLines();
  const ParameterLookup lookup = numericParameters(deck_);
  while (!cur.atEnd()) {
    attempt([&] {
      const Card& card = cur.read(spec);
      const auto [type, name] = typeAndName(card, "PRMR");
      Parameter p;
      p.text = card.text("EXPRESSION");
      if (type != 'C') {
        try {
          p.value = evaluateExpression(p.text, lookup);
        } catch (const ExpressionError& e) {
          card.fail("EXPRESSION", e.what());
        }
        // An integer parameter takes the integer part, as a Fortran INT() would.
        if (type == 'I') p.value = std::trunc(p.value);
      }
      define(card, "PRMR", type, name, std::move(p));
    });
    cur.flush();
    cur.skipBlankLines();
  }
}

void Reader::parameterDuplication(const Keyword& kw) {
  CardCursor cur(kw, deck_);
  cur.skipBlankLines();
  const Card& card = cur.readOptional(keywordSpec("*PARAMETER_DUPLICATION").card("card 1"));
  dflag_ = static_cast<int>(card.integer("DFLAG"));
  if (dflag_ < 1 || dflag_ > 5) card.fail("DFLAG", std::to_string(dflag_) + " is not 1 to 5");
}

}  // namespace

const Parameter* Deck::parameter(std::string_view name) const {
  const auto it = parameters.find(upper(name));
  return it == parameters.end() ? nullptr : &it->second;
}

namespace {

// A read-only mapping of a file, unmapped with its last owner.
struct Mapping {
  void* address = nullptr;
  std::size_t size = 0;
  Mapping(const Mapping&) = delete;
  Mapping& operator=(const Mapping&) = delete;
  Mapping(void* a, std::size_t n) : address(a), size(n) {}
  ~Mapping() { ::munmap(address, size); }
};

// The whole file through a stream: for what cannot be mapped.
std::optional<FileText> copyOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  auto text = std::make_shared<std::string>(std::istreambuf_iterator<char>(in),
                                            std::istreambuf_iterator<char>());
  if (in.bad()) throw util::InputError(path.string() + ": read error");
  const std::string_view view = *text;
  return FileText{std::move(text), view};
}

}  // namespace

std::optional<FileText> DiskSource::load(const fs::path& path) const {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return std::nullopt;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  struct stat st {};
  const bool sized = ::fstat(fd, &st) == 0;
  const auto size = sized ? static_cast<std::size_t>(st.st_size) : 0;
  // Not populated up front: a file that is no deck (a 2 GB line) is refused after its first
  // 64 KiB, and only what is read is brought in.
  void* address = size > 0 ? ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0) : MAP_FAILED;
  ::close(fd);
  if (sized && size == 0) return FileText{};
  if (address == MAP_FAILED) return copyOf(path);
  ::madvise(address, size, MADV_SEQUENTIAL);
  auto mapping = std::make_shared<Mapping>(address, size);
  return FileText{std::move(mapping), std::string_view(static_cast<const char*>(address), size)};
}

std::string DiskSource::identity(const fs::path& path) const {
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(path, ec);
  return ec ? path.lexically_normal().string() : canonical.string();
}

MemorySource::MemorySource(std::map<std::string, std::string> files) {
  for (auto& [name, text] : files)
    files_[fs::path(name).lexically_normal().string()] =
        std::make_shared<const std::string>(std::move(text));
}

std::optional<FileText> MemorySource::load(const fs::path& path) const {
  const auto it = files_.find(path.lexically_normal().string());
  if (it == files_.end()) return std::nullopt;
  return FileText{it->second, *it->second};
}

std::string MemorySource::identity(const fs::path& path) const {
  return path.lexically_normal().string();
}

Deck readDeck(const std::filesystem::path& path) {
  return readDeck(path, DiskSource{}, ReadDeckOptions{});
}

Deck readDeck(const std::filesystem::path& path, const ReadDeckOptions& options) {
  return readDeck(path, DiskSource{}, options);
}

Deck readDeck(const std::filesystem::path& path, const Source& source) {
  return readDeck(path, source, ReadDeckOptions{});
}

Deck readDeck(const std::filesystem::path& path, const Source& source,
              const ReadDeckOptions& options) {
  Deck deck;
  const auto in = source.load(path);
  if (!in) throw util::InputError(path.string() + ": cannot open the file");
  Reader reader(deck, source, path, options);
  reader.readFile(*in, path, source.identity(path), path.string(), Format::Standard, 0);
  return deck;
}

}  // namespace crumple::deck
