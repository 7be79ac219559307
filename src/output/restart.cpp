#include "output/restart.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "output/files.hpp"
#include "util/archive.hpp"
#include "util/error.hpp"

namespace crumple::output {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[8] = {'C', 'R', 'U', 'M', 'P', 'D', 'M', 'P'};
constexpr uint32_t kByteOrder = 0x01020304u;
constexpr std::size_t kHeader = sizeof(kMagic) + 4 + 4 + 8 + sizeof(Sha256);

using util::appendBytes;
template <class T>
void append(std::vector<char>& out, const T& v) {
  util::appendValue(out, v);
}

template <class T>
T take(const std::vector<char>& in, std::size_t& pos, const std::string& path) {
  if (in.size() - pos < sizeof(T))
    throw util::InputError(path + ": corrupted restart dump (a section runs past the end)");
  T v;
  std::memcpy(&v, in.data() + pos, sizeof(T));
  pos += sizeof(T);
  return v;
}

}  // namespace

void DumpRegistry::add(DumpSection section) {
  for (const auto& s : sections_)
    if (s.name == section.name)
      throw std::logic_error("restart section '" + section.name + "' registered twice");
  sections_.push_back(std::move(section));
}

std::vector<char> DumpRegistry::save(const comm::Communicator& comm) const {
  DumpEncoder out;
  for (const auto& s : sections_) {
    auto bytes = s.save();  // collective: every rank runs every section
    if (comm.isRoot()) out.add(s.name, bytes);
  }
  return comm.isRoot() ? out.finish() : std::vector<char>{};
}

DumpEncoder::DumpEncoder() {
  // The header is filled in by finish(); the payload starts with the section count.
  out_.resize(kHeader);
  append(out_, uint32_t(0));
}

void DumpEncoder::add(const std::string& name, const std::vector<char>& bytes) {
  append(out_, static_cast<uint32_t>(name.size()));
  appendBytes(out_, name.data(), name.size());
  append(out_, static_cast<uint64_t>(bytes.size()));
  appendBytes(out_, bytes.data(), bytes.size());
  ++count_;
}

std::vector<char> DumpEncoder::finish() {
  std::memcpy(out_.data() + kHeader, &count_, sizeof(count_));
  const uint64_t size = out_.size() - kHeader;
  const Sha256 sum = sha256(out_.data() + kHeader, size);
  char* h = out_.data();
  std::memcpy(h, kMagic, sizeof(kMagic));
  std::memcpy(h + 8, &kDumpVersion, 4);
  std::memcpy(h + 12, &kByteOrder, 4);
  std::memcpy(h + 16, &size, 8);
  std::memcpy(h + 24, sum.data(), sum.size());
  return std::move(out_);
}

void DumpRegistry::restore(const DumpContents& dump, const comm::Communicator& comm) const {
  for (const auto& s : sections_) {
    const auto it = dump.sections.find(s.name);
    if (it == dump.sections.end()) {
      if (s.optional) continue;
      throw util::InputError(dump.path + ": the restart dump has no '" + s.name +
                             "' section (written by another version of Crumple?)");
    }
    std::string error;
    try {
      s.load(it->second);
    } catch (const std::exception& e) {
      error = e.what();
    }
    if (comm.anyAll(!error.empty()))
      throw util::InputError(error.empty() ? "restart failed on another rank (see its message)"
                                           : fmt::format("{} (restart dump {}, section '{}')",
                                                         error, dump.path, s.name));
  }
}

std::vector<char> encodeDump(
    const std::vector<std::pair<std::string, std::vector<char>>>& sections) {
  DumpEncoder out;
  for (const auto& [name, bytes] : sections) out.add(name, bytes);
  return out.finish();
}

DumpContents decodeDump(const std::vector<char>& bytes, const std::string& path) {
  if (bytes.size() < sizeof(kMagic) || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
    throw util::InputError(path + ": not a Crumple restart dump (it does not start with " +
                           "CRUMPDMP)");
  if (bytes.size() < kHeader)
    throw util::InputError(path + ": truncated restart dump (the header is incomplete)");
  std::size_t pos = sizeof(kMagic);
  const auto version = take<uint32_t>(bytes, pos, path);
  const auto order = take<uint32_t>(bytes, pos, path);
  const auto size = take<uint64_t>(bytes, pos, path);
  Sha256 sum{};
  std::memcpy(sum.data(), bytes.data() + pos, sum.size());
  pos += sum.size();
  if (order != kByteOrder)
    throw util::InputError(path + ": restart dump written on a machine of other byte order");
  if (version != kDumpVersion)
    throw util::InputError(
        fmt::format("{}: restart dump format version {} (this Crumple reads version {})", path,
                    version, kDumpVersion));
  if (bytes.size() - kHeader != size)
    throw util::InputError(fmt::format(
        "{}: truncated or padded restart dump: the header announces {} bytes of state, the "
        "file holds {}",
        path, size, bytes.size() - kHeader));
  if (sha256(bytes.data() + kHeader, size) != sum)
    throw util::InputError(path +
                           ": corrupted restart dump (checksum mismatch); use the other dump");
  DumpContents d;
  d.path = path;
  d.cycle = dumpCycle(path);
  const auto count = take<uint32_t>(bytes, pos, path);
  for (uint32_t i = 0; i < count; ++i) {
    const auto len = take<uint32_t>(bytes, pos, path);
    if (bytes.size() - pos < len)
      throw util::InputError(path + ": corrupted restart dump (a section name runs past the end)");
    std::string name(bytes.data() + pos, len);
    pos += len;
    const auto n = take<uint64_t>(bytes, pos, path);
    if (bytes.size() - pos < n)
      throw util::InputError(path + ": corrupted restart dump (section '" + name +
                             "' runs past the end)");
    d.sections[name].assign(bytes.data() + pos, bytes.data() + pos + n);
    pos += n;
  }
  if (pos != bytes.size())
    throw util::InputError(path + ": corrupted restart dump (bytes after the last section)");
  return d;
}

DumpContents readDump(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw util::InputError("cannot open restart dump '" + path.string() + "'");
  std::vector<char> bytes;
  in.seekg(0, std::ios::end);
  const auto size = in.tellg();
  if (size < 0) throw util::InputError("cannot read restart dump '" + path.string() + "'");
  bytes.resize(static_cast<std::size_t>(size));
  in.seekg(0);
  if (!bytes.empty()) in.read(bytes.data(), size);
  if (!in) throw util::InputError("cannot read restart dump '" + path.string() + "'");
  return decodeDump(bytes, path.string());
}

int64_t dumpCycle(const fs::path& path) {
  const std::string name = path.filename().string();
  const std::string prefix = kDumpPrefix;
  if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) return -1;
  int64_t cycle = 0;
  for (std::size_t i = prefix.size(); i < name.size(); ++i) {
    if (name[i] < '0' || name[i] > '9' || cycle > (int64_t(1) << 58)) return -1;
    cycle = 10 * cycle + (name[i] - '0');
  }
  return cycle;
}

std::vector<fs::path> dumpFiles(const fs::path& dir) {
  std::vector<std::pair<int64_t, fs::path>> found;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (const int64_t c = dumpCycle(e.path()); c >= 0 && e.is_regular_file(ec))
      found.emplace_back(c, e.path());
  std::sort(found.begin(), found.end());
  std::vector<fs::path> out;
  for (auto& f : found) out.push_back(std::move(f.second));
  return out;
}

fs::path writeDumpFile(const fs::path& dir, int64_t cycle, const std::vector<char>& bytes) {
  const fs::path tmp = dir / kDumpTemporary;
  const fs::path final_path = dir / fmt::format("{}{:010d}", kDumpPrefix, cycle);
  // POSIX I/O for fsync: the rename below must not make visible a file whose blocks are
  // still only in the page cache when the machine goes down.
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0)
    throw std::runtime_error(
        fmt::format("cannot create '{}': {}", tmp.string(), std::strerror(errno)));
  std::size_t done = 0;
  int err = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      err = n < 0 ? errno : ENOSPC;
      break;
    }
    done += static_cast<std::size_t>(n);
  }
  if (err == 0 && ::fsync(fd) != 0) err = errno;
  if (::close(fd) != 0 && err == 0) err = errno;
  std::error_code ec;
  if (err != 0) {
    fs::remove(tmp, ec);
    throw std::runtime_error(
        fmt::format("cannot write restart dump '{}': {}", final_path.string(), std::strerror(err)));
  }
  fs::rename(tmp, final_path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw std::runtime_error(fmt::format("cannot rename '{}' to '{}': {}", tmp.string(),
                                         final_path.string(), ec.message()));
  }
  // Keep the two newest: if the newest turns out unreadable, the one before it still is.
  auto all = dumpFiles(dir);
  for (std::size_t i = 0; i + 2 < all.size(); ++i) fs::remove(all[i], ec);
  return final_path;
}

fs::path resolveDump(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_directory(path, ec)) return path;
  const auto all = dumpFiles(path);
  if (all.empty())
    throw util::InputError("'" + path.string() + "' holds no restart dump (" + kDumpPrefix +
                           "<cycle>)");
  return all.back();
}

}  // namespace crumple::output
