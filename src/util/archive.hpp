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

#include "util/error.hpp"

namespace crumple::util {

// Appends n bytes at p to out. resize + memcpy rather than insert: GCC 12 reports a false
// stringop-overflow for inserting a few bytes into an empty vector<char> once inlined.
inline void appendBytes(std::vector<char>& out, const void* p, std::size_t n) {
  if (n == 0) return;  // p may be null
  const std::size_t at = out.size();
  out.resize(at + n);
  std::memcpy(out.data() + at, p, n);
}
template <class T>
requires std::is_trivially_copyable_v<T>
void appendValue(std::vector<char>& out, const T& v) {
  appendBytes(out, &v, sizeof(T));
}

class ArchiveWriter {
 public:
  template <class T>
  requires std::is_trivially_copyable_v<T>
  void put(const T& v) { appendValue(bytes_, v); }
  void put(const std::string& s) {
    put<uint64_t>(s.size());
    appendBytes(bytes_, s.data(), s.size());
  }
  template <class T>
  void put(const std::vector<T>& v) {
    put<uint64_t>(v.size());
    if constexpr (std::is_trivially_copyable_v<T>) {
      appendBytes(bytes_, v.data(), v.size() * sizeof(T));
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

// Restart sections: reads a count written by the dumped run and checks it against this run's;
// a difference means the dump was written for another deck (util::InputError saying what).
inline void expectCount(ArchiveReader& in, std::size_t expected, const char* what) {
  uint64_t n = 0;
  in.get(n);
  if (n != expected)
    throw InputError("the restart dump does not belong to this deck: it holds " +
                     std::to_string(n) + " " + what + ", the deck " + std::to_string(expected));
}

}  // namespace crumple::util
