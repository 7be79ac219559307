// Small output helpers that know no physics: CSV histories, the state digest, the results
// folder guard and the progress line.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace crumple::output {

// FNV-1a, 64 bits: the hash of the CSV prefixes a restart dump records (rows are hashed as they
// are written, a few bytes at a time; it tells another run's file from this run's).
inline constexpr uint64_t kFnvOffset = 0xcbf29ce484222325ull;
uint64_t fnv1a(const char* data, std::size_t size, uint64_t hash = kFnvOffset);

// A history file written a few rows at a time, which a restarted run continues: it counts
// the bytes written and hashes them (FNV-1a 64), so that a restart dump records how far the
// file is written and the continued run finds the file of the same run and cuts it back there.
// The CSV histories and LS-DYNA's ASCII files (ascii.hpp) are written through it.
class HistoryFile {
 public:
  struct Position {
    uint64_t bytes = 0;
    uint64_t hash = kFnvOffset;
  };
  HistoryFile() = default;
  // A new file (replacing any) that starts with `header`.
  HistoryFile(const std::filesystem::path& path, std::string_view header);
  // Continues the file at `resume` (restart): its first resume.bytes bytes must hash to
  // resume.hash, else util::InputError (the folder holds another run's file); the bytes after
  // them (written after the dump) are cut off and new text is appended.
  HistoryFile(const std::filesystem::path& path, const Position& resume);
  // The check of that constructor alone, so that every file can be checked before any is cut.
  static void checkResume(const std::filesystem::path& path, const Position& resume);
  bool isOpen() const { return out_.is_open(); }
  void write(std::string_view text) { put(text.data(), text.size()); }
  // Hands the text to the system; throws std::runtime_error naming the file when a write failed
  // (a full disk: the stream buffers, so the failure shows here).
  void flush();
  const Position& position() const { return pos_; }

 protected:
  void put(const char* data, std::size_t size);

 private:
  std::filesystem::path path_;
  std::ofstream out_;
  Position pos_;
};

// A CSV file with a header row; numbers written with 17 significant digits (round-trip).
class CsvWriter : public HistoryFile {
 public:
  CsvWriter() = default;
  CsvWriter(const std::filesystem::path& path, const std::vector<std::string>& columns);
  // Continues the file at `resume` (restart), as HistoryFile's.
  CsvWriter(const std::filesystem::path& path, const std::vector<std::string>& columns,
            const Position& resume)
      : HistoryFile(path, resume), columns_(columns.size()) {}
  // One row; `values` must have as many entries as the header. Integers print exactly.
  void row(const std::vector<double>& values);

 private:
  std::size_t columns_ = 0;
};

// When a history falls due: every `interval` from 0 (0: never), and once more at the end.
struct HistorySchedule {
  double interval = 0.0;
  double next = 0.0;
  // The time of the last row written: the end of a run whose last cycle was also a sample
  // time writes it once (not kept in a dump: a restart starts after the dump's time).
  double written = -1.0e300;
  bool due(double t, bool last) const {
    return interval > 0.0 && t != written && (last || t >= next * (1 - 1e-9));
  }
  void advance(double t) {
    written = t;
    while (next <= t * (1 + 1e-9)) next += interval;
  }
};

// SHA-256 of raw bytes (the checksum of restart dumps: with the CPU's SHA extensions it is
// faster than a byte-wise FNV, and it catches any corruption).
using Sha256 = std::array<unsigned char, 32>;
Sha256 sha256(const char* data, std::size_t size);

// Writes `text` to `path` (replacing it) and checks that every byte reached the system: throws
// std::runtime_error naming the file and the reason (e.g. "No space left on device") otherwise.
void writeTextFile(const std::filesystem::path& path, const std::string& text);

// Throws std::runtime_error naming `path` when `out` has failed: for streams written bit by bit
// (run.log), checked after each flush.
void checkStream(const std::ostream& out, const std::filesystem::path& path);

// SHA-256 over x then v, each as little-endian IEEE float64, nodes in the given order
// (ascending global node id), as 64 lowercase hex characters. x and v are packed xyz.
std::string stateDigest(const std::vector<double>& x, const std::vector<double>& v);

// The subfolder of the results folder that holds the VTU/PVTU pieces of the plot states (the
// .pvd stays at the top so ParaView users find one file to open).
inline constexpr const char* kStatesFolder = "states";

// Restart dumps in the results folder are d3dump_<cycle, 10 digits> (restart.hpp); the
// temporary file while one is written is .d3dump.tmp.
inline constexpr const char* kDumpPrefix = "d3dump_";
inline constexpr const char* kDumpTemporary = ".d3dump.tmp";

// Makes `dir` ready for a run's results. If it already holds results of an earlier run
// (summary.json, results.pvd, glstat.csv or run.log) and `overwrite` is false, throws
// util::InputError telling the user to pass --overwrite or choose another -o; with
// `overwrite`, only those result files and the VTU pieces are removed. Creates `dir`, and
// throws util::InputError when the folder cannot be created or written to (checked here, so
// the run stops before its first cycle).
// Every file a run writes (the ARCHITECTURE.md output files, partition.json, *.vtu and *.pvtu
// at the top and in kStatesFolder) counts as a result; nothing else is ever touched.
void prepareResultsDir(const std::filesystem::path& dir, bool overwrite);

// A restart into a new folder (`--restart DUMP -o NEWDIR`): copies the dumped run's results
// from `from` into the empty or new folder `to` (every file but the restart dumps, and the
// plot states, hard-linked where the file system allows: they are only ever removed, never
// rewritten), so that the restart cuts them back and continues them there; `from` is left as
// it was. Throws util::InputError naming the file that could not be copied.
void copyRunFolder(const std::filesystem::path& from, const std::filesystem::path& to);

// Undoes a run that failed before its first state: removes the result files and pieces from
// `dir` (as prepareResultsDir would with `overwrite`) and, when `remove_dir` (the run created
// it), the folder itself if nothing else is left in it. Never throws: it runs on an error path.
void removeRunOutput(const std::filesystem::path& dir, bool remove_dir);

// The progress line: refreshed in place (\r) when `interactive` (a terminal), otherwise one
// line each 10% of the end time. Shows cycle, time, dt, % done, ETA and energy ratio.
class Progress {
 public:
  Progress(std::FILE* stream, bool interactive, double end_time);
  void update(int64_t cycle, double time, double dt, double energy_ratio);
  void finish(int64_t cycle, double time, double dt, double energy_ratio);

 private:
  std::FILE* stream_;
  bool interactive_;
  double end_time_;
  int next_decile_ = 1;
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::string line(int64_t cycle, double time, double dt, double energy_ratio) const;
};

}  // namespace crumple::output
