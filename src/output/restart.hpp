// Restart dumps (docs/reliability.md, "Restart"): the complete state of a run, as named
// sections keyed by global ids, so that a dump written at N ranks continues at M ranks.
//
// File layout (little-endian, as written by this build):
//   8 bytes  magic "CRUMPDMP"
//   u32      format version (kDumpVersion)
//   u32      0x01020304 (byte order of the writer)
//   u64      payload size in bytes
//   32 bytes SHA-256 of the payload
//   payload: u32 section count, then per section: u32 name length, name, u64 size, bytes
// A dump is written by rank 0 to a temporary name and renamed (a crash while writing leaves
// the previous dumps intact); the two newest are kept.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "comm/communicator.hpp"
#include "output/files.hpp"

namespace crumple::output {

// 3: solids keep the last pass's bulk viscosity and (viscous forms too) hourglass forces.
// 4: the laws with an equation of state keep the least ln(V / V0) as their third history
// variable (*MAT_JOHNSON_COOK's damage and temperature move to the fourth and fifth), and the
// model's equations of state carry the tabulated forms' points.
// 5: contact keeps the penalty energy each node check held last cycle (booked as contact
// energy when the check ends while penetrated), and *MAT_JOHNSON_COOK a sixth history
// variable (the spall flag).
// 6: shells keep their drilling-constraint energy apart from the hourglass energy; joints no
// longer keep their dampers' last relative velocity; the solver keeps the stonewall energy of
// the last step's half ahead (a sixth accumulator per rank).
inline constexpr uint32_t kDumpVersion = 6;

// One part of the state. `save` is collective (every rank calls every section's save, in
// registration order) and returns the section's bytes on rank 0 (what other ranks return is
// ignored). `load` runs on every rank with the bytes rank 0 saved, after the solver is
// initialised. An optional section may be missing from a dump written before it existed.
struct DumpSection {
  std::string name;
  std::function<std::vector<char>()> save;
  std::function<void(const std::vector<char>&)> load;
  bool optional = false;
};

// A dump read back: its sections by name.
struct DumpContents {
  std::string path;
  std::map<std::string, std::vector<char>> sections;
  int64_t cycle = 0;  // from the file name, -1 if it does not follow the pattern
};

// The sections of a run's state. Whoever owns some state registers it once before the run
// starts; dumps and restarts then take every registered section along.
class DumpRegistry {
 public:
  void add(DumpSection section);  // throws std::logic_error on a duplicate name
  // Collective: the dump file's bytes (valid on rank 0, empty elsewhere).
  std::vector<char> save(const comm::Communicator& comm) const;
  // Every rank: each section's load, in registration order. After each section the ranks
  // agree whether any failed (a load may fail on one rank only, e.g. rank 0's file checks),
  // and then every rank throws util::InputError: the failing rank's message there, a pointer
  // to it elsewhere. A missing required section is an InputError naming the dump.
  void restore(const DumpContents& dump, const comm::Communicator& comm) const;

 private:
  std::vector<DumpSection> sections_;
};

// Builds a dump file section by section (each section's bytes are copied once).
class DumpEncoder {
 public:
  DumpEncoder();
  void add(const std::string& name, const std::vector<char>& bytes);
  std::vector<char> finish();  // the header with size and checksum, then the payload

 private:
  std::vector<char> out_;
  uint32_t count_ = 0;
};

// Sections -> file bytes (header, checksum, payload).
std::vector<char> encodeDump(
    const std::vector<std::pair<std::string, std::vector<char>>>& sections);
// File bytes -> sections; a util::InputError naming `path` if the bytes are not a dump, are
// truncated, fail the checksum or come from another format version.
DumpContents decodeDump(const std::vector<char>& bytes, const std::string& path);
// Reads and decodes a dump file.
DumpContents readDump(const std::filesystem::path& path);

// Writes `bytes` as dir/d3dump_<cycle> through the temporary name and a rename, then removes
// all but the two newest dumps. Returns the dump's path; throws std::runtime_error (the
// earlier dumps untouched) if the file cannot be written completely.
std::filesystem::path writeDumpFile(const std::filesystem::path& dir, int64_t cycle,
                                    const std::vector<char>& bytes);
// Dumps in `dir`, oldest (lowest cycle) first.
std::vector<std::filesystem::path> dumpFiles(const std::filesystem::path& dir);
// The cycle in a dump's file name, or -1.
int64_t dumpCycle(const std::filesystem::path& path);
// --restart argument: a dump file, or a folder whose newest dump is taken.
std::filesystem::path resolveDump(const std::filesystem::path& path);

}  // namespace crumple::output
