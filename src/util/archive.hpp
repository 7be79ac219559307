// A minimal binary archive for shipping plain data between ranks of the same build (same
// endianness and layout): trivially copyable values, strings, vectors and maps.
#pragma once

#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace crumple::util {

class ArchiveWriter {
 public:
  template <class T>
  requires std::is_trivially_copyable_v<T>
  void put(const T& v) {
    const auto* p = reinterpret_cast<const char*>(&v);
    bytes_.insert(bytes_.end(), p, p + sizeof(T));
  }
  void put(const std::string& s) {
    put<uint64_t>(s.size());
    bytes_.insert(bytes_.end(), s.begin(), s.end());
  }
  template <class T>
  void put(const std::vector<T>& v) {
    put<uint64_t>(v.size());
    if constexpr (std::is_trivially_copyable_v<T>) {
      if (v.empty()) return;  // data() may be null
      const auto* p = reinterpret_cast<const char*>(v.data());
      bytes_.insert(bytes_.end(), p, p + v.size() * sizeof(T));
    } else {
      for (const auto& x : v) put(x);
    }
  }
  template <class K, class V>
  void put(const std::map<K, V>& m) {
    put<uint64_t>(m.size());
    for (const auto& [k, v] : m) {
      put(k);
      put(v);
    }
  }
  std::vector<char>& bytes() { return bytes_; }

 private:
  std::vector<char> bytes_;
};

class ArchiveReader {
 public:
  explicit ArchiveReader(const std::vector<char>& bytes) : bytes_(bytes) {}
  template <class T>
  requires std::is_trivially_copyable_v<T>
  void get(T& v) {
    need(sizeof(T));
    std::memcpy(&v, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
  }
  void get(std::string& s) {
    uint64_t n = 0;
    get(n);
    need(n);
    s.assign(bytes_.data() + pos_, n);
    pos_ += n;
  }
  template <class T>
  void get(std::vector<T>& v) {
    uint64_t n = 0;
    get(n);
    if constexpr (std::is_trivially_copyable_v<T>) {
      need(n * sizeof(T));
      v.resize(n);
      if (n == 0) return;  // memcpy with a null pointer is undefined even for no bytes
      std::memcpy(v.data(), bytes_.data() + pos_, n * sizeof(T));
      pos_ += n * sizeof(T);
    } else {
      v.resize(n);
      for (auto& x : v) get(x);
    }
  }
  template <class K, class V>
  void get(std::map<K, V>& m) {
    uint64_t n = 0;
    get(n);
    m.clear();
    for (uint64_t i = 0; i < n; ++i) {
      K k{};
      V v{};
      get(k);
      get(v);
      m.emplace(std::move(k), std::move(v));
    }
  }
  bool atEnd() const { return pos_ == bytes_.size(); }

 private:
  void need(std::size_t n) const {
    if (pos_ + n > bytes_.size()) throw std::runtime_error("archive: truncated data");
  }
  const std::vector<char>& bytes_;
  std::size_t pos_ = 0;
};

}  // namespace crumple::util
