#include "output/files.hpp"

#include <openssl/evp.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

#include "output/d3plot.hpp"
#include "util/error.hpp"

namespace crumple::output {

namespace fs = std::filesystem;

uint64_t fnv1a(const char* data, std::size_t size, uint64_t hash) {
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= static_cast<unsigned char>(data[i]);
    hash *= 0x100000001b3ull;
  }
  return hash;
}

namespace {
std::string csvHeader(const std::vector<std::string>& columns) {
  std::string line;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (i > 0) line.push_back(',');
    line += columns[i];
  }
  return line + '\n';
}
}  // namespace

HistoryFile::HistoryFile(const fs::path& path, std::string_view header)
    : path_(path), out_(path, std::ios::trunc | std::ios::binary) {
  if (!out_) throw std::runtime_error(fmt::format("cannot open '{}' for writing", path.string()));
  write(header);
}

CsvWriter::CsvWriter(const fs::path& path, const std::vector<std::string>& columns)
    : HistoryFile(path, csvHeader(columns)), columns_(columns.size()) {}

void HistoryFile::checkResume(const fs::path& path, const Position& resume) {
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  if (ec || size < resume.bytes)
    throw util::InputError(fmt::format(
        "'{}' is {} the restart dump expects ({} bytes): the results folder does not hold "
        "the run the dump was written by",
        path.string(), ec ? "missing, or not the file" : "shorter than", resume.bytes));
  {
    std::ifstream in(path, std::ios::binary);
    std::vector<char> prefix(resume.bytes);
    if (!prefix.empty()) in.read(prefix.data(), static_cast<std::streamsize>(prefix.size()));
    if (!in || fnv1a(prefix.data(), prefix.size()) != resume.hash)
      throw util::InputError(fmt::format(
          "'{}' differs from the file the restart dump was written with: the results folder "
          "does not hold the run the dump was written by",
          path.string()));
  }
}

HistoryFile::HistoryFile(const fs::path& path, const Position& resume) : path_(path) {
  checkResume(path, resume);
  std::error_code ec;
  // The rows after the dump belong to the interrupted continuation: the restarted run
  // writes them again.
  fs::resize_file(path, resume.bytes, ec);
  if (ec)
    throw util::InputError(
        fmt::format("cannot cut '{}' back to the dump: {}", path.string(), ec.message()));
  out_.open(path, std::ios::app | std::ios::binary);
  if (!out_) throw std::runtime_error(fmt::format("cannot open '{}' for writing", path.string()));
  pos_ = resume;
}

void HistoryFile::put(const char* data, std::size_t size) {
  out_.write(data, static_cast<std::streamsize>(size));
  pos_.bytes += size;
  pos_.hash = fnv1a(data, size, pos_.hash);
}

void CsvWriter::row(const std::vector<double>& values) {
  if (values.size() != columns_) {
    throw std::invalid_argument(fmt::format("CSV row has {} values but the header has {} columns",
                                            values.size(), columns_));
  }
  // "{}" is fmt's shortest representation that reads back to the same double: every value
  // round-trips (like %.17g) without %.17g's noise (0.1 stays 0.1), and integral values such as
  // cycle numbers print as integers (12, not 12.000).
  fmt::memory_buffer line;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) line.push_back(',');
    fmt::format_to(std::back_inserter(line), "{}", values[i]);
  }
  line.push_back('\n');
  put(line.data(), line.size());
}

void HistoryFile::flush() {
  out_.flush();
  checkStream(out_, path_);
}

void checkStream(const std::ostream& out, const fs::path& path) {
  // errno still holds the reason of the failed write(2): the streams keep no other record.
  if (!out) {
    throw std::runtime_error(
        fmt::format("error while writing '{}': {}", path.string(), std::strerror(errno)));
  }
}

void writeTextFile(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) {
    throw std::runtime_error(
        fmt::format("cannot open '{}' for writing: {}", path.string(), std::strerror(errno)));
  }
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.flush();
  checkStream(out, path);
  out.close();
  checkStream(out, path);
}

namespace {

void hashDoubles(EVP_MD_CTX* ctx, const std::vector<double>& values) {
  if constexpr (std::endian::native == std::endian::little) {
    if (!values.empty() &&
        EVP_DigestUpdate(ctx, values.data(), values.size() * sizeof(double)) != 1) {
      throw std::runtime_error("SHA-256 update failed");
    }
  } else {
    // The digest is defined on little-endian bytes so it compares across machines.
    std::array<unsigned char, sizeof(double)> bytes;
    for (double v : values) {
      const auto bits = std::bit_cast<uint64_t>(v);
      for (std::size_t b = 0; b < bytes.size(); ++b)
        bytes[b] = static_cast<unsigned char>(bits >> (8 * b));
      if (EVP_DigestUpdate(ctx, bytes.data(), bytes.size()) != 1) {
        throw std::runtime_error("SHA-256 update failed");
      }
    }
  }
}

}  // namespace

namespace {

// SHA-256 of whatever `feed` passes to EVP_DigestUpdate.
template <class Feed>
Sha256 sha256Of(Feed&& feed) {
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx(EVP_MD_CTX_new(), &EVP_MD_CTX_free);
  if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1) {
    throw std::runtime_error("SHA-256 initialisation failed");
  }
  feed(ctx.get());
  Sha256 digest{};
  unsigned int length = 0;
  if (EVP_DigestFinal_ex(ctx.get(), digest.data(), &length) != 1 || length != digest.size()) {
    throw std::runtime_error("SHA-256 finalisation failed");
  }
  return digest;
}

}  // namespace

Sha256 sha256(const char* data, std::size_t size) {
  return sha256Of([&](EVP_MD_CTX* ctx) {
    if (size > 0 && EVP_DigestUpdate(ctx, data, size) != 1)
      throw std::runtime_error("SHA-256 update failed");
  });
}

std::string stateDigest(const std::vector<double>& x, const std::vector<double>& v) {
  const Sha256 digest = sha256Of([&](EVP_MD_CTX* ctx) {
    hashDoubles(ctx, x);
    hashDoubles(ctx, v);
  });
  std::string hex;
  hex.reserve(2 * digest.size());
  for (unsigned char byte : digest) fmt::format_to(std::back_inserter(hex), "{:02x}", byte);
  return hex;
}

namespace {

// Files a run (or `crumple partition`) writes at the top of the results folder.
// results.pvd.tmp is what a run killed while rewriting the collection leaves (vtk.cpp writes
// through a temporary file); it is ours as much as results.pvd.
// The LS-DYNA ASCII files (ascii.hpp) are written under LS-DYNA's names, without extension.
constexpr std::array<const char*, 20> kResultFiles = {
    "summary.json",    "results.pvd", "glstat.csv", "run.log",     "matsum.csv",
    "nodout.csv",      "rcforc.csv",  "rwforc.csv", "secforc.csv", "partition.json",
    "results.pvd.tmp", "glstat",      "matsum",     "nodout",      "rcforc",
    "rwforc",          "sleout",      "secforc",    "jntforc.csv", "jntforc"};

// A piece, or the temporary file of a piece whose writing was interrupted.
bool isPieceFile(fs::path p) {
  if (p.extension() == ".tmp") p = p.stem();
  return p.extension() == ".vtu" || p.extension() == ".pvtu";
}

bool isRegularFileOrLink(const fs::path& p) {
  std::error_code ec;
  const fs::file_status s = fs::symlink_status(p, ec);
  return !ec && (fs::is_regular_file(s) || fs::is_symlink(s));
}

// VTU/PVTU files directly in `folder`, sorted so messages and removal order are reproducible.
std::vector<fs::path> pieceFiles(const fs::path& folder) {
  std::vector<fs::path> found;
  std::error_code ec;
  if (!fs::is_directory(fs::symlink_status(folder, ec))) return found;
  for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
    if (isPieceFile(e.path()) && isRegularFileOrLink(e.path())) found.push_back(e.path());
  }
  if (ec) {
    throw util::InputError(
        fmt::format("cannot list results folder '{}': {}", folder.string(), ec.message()));
  }
  std::sort(found.begin(), found.end());
  return found;
}

// Every result file of an earlier run in `dir`, markers first.
std::vector<fs::path> earlierResults(const fs::path& dir) {
  std::vector<fs::path> found;
  for (const char* name : kResultFiles) {
    if (isRegularFileOrLink(dir / name)) found.push_back(dir / name);
  }
  for (const fs::path& p : pieceFiles(dir)) found.push_back(p);
  for (const fs::path& p : pieceFiles(dir / kStatesFolder)) found.push_back(p);
  // Restart dumps (restart.hpp: d3dump_<cycle>, and the temporary file of one being written):
  // a new run must not leave an older run's dumps to be restarted from by mistake.
  std::error_code ec;
  std::vector<fs::path> dumps;
  if (fs::is_directory(fs::symlink_status(dir, ec)))
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
      const std::string name = e.path().filename().string();
      if ((name.rfind(kDumpPrefix, 0) == 0 || name == kDumpTemporary) &&
          isRegularFileOrLink(e.path()))
        dumps.push_back(e.path());
      // The d3plot family: a shorter new run must not leave an older run's later members.
      if (d3plotIndex(name) >= 0 && isRegularFileOrLink(e.path())) dumps.push_back(e.path());
    }
  std::sort(dumps.begin(), dumps.end());
  found.insert(found.end(), dumps.begin(), dumps.end());
  return found;
}

}  // namespace

void copyRunFolder(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::create_directories(to / kStatesFolder, ec);
  auto copyOne = [&](const fs::path& src, const fs::path& dst, bool link) {
    std::error_code e;
    if (link) fs::create_hard_link(src, dst, e);
    if (!link || e) fs::copy_file(src, dst, fs::copy_options::overwrite_existing, e);
    if (e)
      throw util::InputError(fmt::format("cannot copy '{}' into the new results folder: {}",
                                         src.string(), e.message()));
  };
  for (const auto& entry : fs::directory_iterator(from, ec)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && name.rfind("d3dump_", 0) != 0)
      copyOne(entry.path(), to / name, false);
  }
  for (const auto& entry : fs::directory_iterator(from / kStatesFolder, ec))
    if (entry.is_regular_file())
      copyOne(entry.path(), to / kStatesFolder / entry.path().filename(), true);
}

void prepareResultsDir(const fs::path& dir, bool overwrite) {
  std::error_code ec;
  const fs::file_status status = fs::status(dir, ec);
  if (fs::exists(status) && !fs::is_directory(status)) {
    throw util::InputError(fmt::format(
        "results folder '{}' exists and is not a folder; use -o to choose another", dir.string()));
  }
  const std::vector<fs::path> earlier = earlierResults(dir);
  if (!earlier.empty() && !overwrite) {
    throw util::InputError(fmt::format(
        "results folder '{}' already holds results of an earlier run ({}); pass --overwrite to "
        "replace them or -o to choose another folder",
        dir.string(), earlier.front().lexically_relative(dir).generic_string()));
  }
  for (const fs::path& p : earlier) {
    if (!fs::remove(p, ec) && ec) {
      throw util::InputError(
          fmt::format("cannot remove '{}' from the results folder: {}", p.string(), ec.message()));
    }
  }
  // The states folder goes only if it is now empty: anything else in it is not ours.
  const fs::path states = dir / kStatesFolder;
  if (fs::is_directory(fs::symlink_status(states, ec)) && fs::is_empty(states, ec)) {
    fs::remove(states, ec);
  }
  fs::create_directories(dir, ec);
  if (ec) {
    throw util::InputError(
        fmt::format("cannot create results folder '{}': {}", dir.string(), ec.message()));
  }
  // An existing folder may be read-only: better to say so now than after the set-up.
  if (::access(dir.c_str(), W_OK | X_OK) != 0) {
    throw util::InputError(
        fmt::format("cannot write to results folder '{}': {}", dir.string(), std::strerror(errno)));
  }
}

void removeRunOutput(const fs::path& dir, bool remove_dir) {
  std::error_code ec;
  try {
    for (const fs::path& p : earlierResults(dir)) fs::remove(p, ec);
  } catch (const std::exception&) {
    return;  // the folder cannot be listed: leave it as it is
  }
  if (fs::is_directory(fs::symlink_status(dir / kStatesFolder, ec)))
    fs::remove(dir / kStatesFolder, ec);  // only if empty
  if (remove_dir) fs::remove(dir, ec);    // likewise
}

Progress::Progress(std::FILE* stream, bool interactive, double end_time)
    : stream_(stream),
      interactive_(interactive),
      end_time_(end_time),
      start_(std::chrono::steady_clock::now()),
      // Backdated so the first update draws at once.
      last_draw_(start_ - std::chrono::seconds(1)) {}

namespace {

double fractionDone(double time, double end_time) {
  if (!(end_time > 0.0)) return 1.0;
  const double f = time / end_time;
  if (!(f > 0.0)) return 0.0;  // also catches NaN
  return std::min(f, 1.0);
}

std::string hms(double seconds) {
  const auto s = static_cast<int64_t>(std::llround(seconds));
  return fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60);
}

}  // namespace

std::string Progress::line(int64_t cycle, double time, double dt, double energy_ratio) const {
  const double f = fractionDone(time, end_time_);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  // The remaining time assumes the rest of the run goes at the average speed so far; before any
  // progress there is nothing to extrapolate from.
  const double remaining = elapsed * (1.0 - f) / f;
  const std::string eta = f > 0.0 && std::isfinite(remaining) ? hms(remaining) : "-:--:--";
  return fmt::format("cycle {}  t {:.3e}  dt {:.1e}  {:.1f}%  ETA {}  energy ratio {:.4f}", cycle,
                     time, dt, 100.0 * f, eta, energy_ratio);
}

void Progress::update(int64_t cycle, double time, double dt, double energy_ratio) {
  if (stream_ == nullptr) return;
  if (interactive_) {
    // A terminal redraws the same line; five times a second is smooth and costs nothing.
    const auto now = std::chrono::steady_clock::now();
    if (now - last_draw_ < std::chrono::milliseconds(200)) return;
    last_draw_ = now;
    // \033[K clears what a longer previous line left to the right.
    std::fprintf(stream_, "\r%s\033[K", line(cycle, time, dt, energy_ratio).c_str());
    std::fflush(stream_);
    return;
  }
  // Logs get one line per decile crossed; the 100% line is finish()'s, so it is never doubled.
  const double f = fractionDone(time, end_time_);
  if (next_decile_ > 9 || 10.0 * f < next_decile_) return;
  while (next_decile_ <= 9 && 10.0 * f >= next_decile_) ++next_decile_;
  std::fprintf(stream_, "%s\n", line(cycle, time, dt, energy_ratio).c_str());
  std::fflush(stream_);
}

void Progress::finish(int64_t cycle, double time, double dt, double energy_ratio) {
  if (stream_ == nullptr) return;
  const std::string text = line(cycle, time, dt, energy_ratio);
  if (interactive_) {
    std::fprintf(stream_, "\r%s\033[K\n", text.c_str());
  } else {
    std::fprintf(stream_, "%s\n", text.c_str());
  }
  std::fflush(stream_);
}

}  // namespace crumple::output
