// A fresh folder under the system temp dir for a test's files, removed with the object; and
// the message of the InputError a callable throws.
#pragma once

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

#include "util/error.hpp"

namespace crumple::testing {

class TempDir {
 public:
  explicit TempDir(const std::string& prefix = "crumple_test") {
    static std::atomic<int> counter{0};
    dir_ = std::filesystem::temp_directory_path() /
           (prefix + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(dir_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const auto p = dir_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p;
  }
  const std::filesystem::path& path() const { return dir_; }

 private:
  std::filesystem::path dir_;
};

// The message of the util::InputError that `f` throws ("" if none).
template <class F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const util::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace crumple::testing
