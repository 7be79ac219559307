#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "output/files.hpp"
#include "util/error.hpp"

namespace fs = std::filesystem;

namespace {

fs::path freshDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::temp_directory_path() /
                       ("crumple_" + std::string(info->test_suite_name()) + "_" + info->name() +
                        "_" + std::to_string(::getpid()));  // two suites at once do not collide
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void touch(const fs::path& file, const std::string& text = "x") {
  std::ofstream(file) << text;
}

// Everything a std::FILE* received, for checking the progress line.
class CapturedStream {
 public:
  CapturedStream() : file_(std::tmpfile()) {}
  ~CapturedStream() { std::fclose(file_); }
  CapturedStream(const CapturedStream&) = delete;
  CapturedStream& operator=(const CapturedStream&) = delete;
  std::FILE* get() const { return file_; }
  std::string text() const {
    std::fflush(file_);
    std::rewind(file_);
    std::string out;
    char buffer[1024];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, file_)) > 0;)
      out.append(buffer, n);
    return out;
  }

 private:
  std::FILE* file_;
};

}  // namespace

TEST(OutputCsv, HeaderAndRoundTripNumbers) {
  const fs::path file = freshDir() / "glstat.csv";
  {
    crumple::output::CsvWriter csv(file, {"time", "cycle", "dt", "kinetic"});
    ASSERT_TRUE(csv.isOpen());
    csv.row({1.0 / 3.0, 12, 2.1e-08, 0.1});
    csv.row({0, 1234567890123, -0.0, 1e300});
  }
  EXPECT_EQ(slurp(file),
            "time,cycle,dt,kinetic\n"
            "0.3333333333333333,12,2.1e-08,0.1\n"
            "0,1234567890123,-0,1e+300\n");
  // Every printed value reads back to the same double.
  EXPECT_EQ(std::stod("0.3333333333333333"), 1.0 / 3.0);
}

TEST(OutputCsv, RowWidthMustMatchHeader) {
  crumple::output::CsvWriter csv(freshDir() / "a.csv", {"a", "b"});
  EXPECT_THROW(csv.row({1.0}), std::invalid_argument);
  EXPECT_FALSE(crumple::output::CsvWriter().isOpen());
  EXPECT_THROW(crumple::output::CsvWriter(freshDir() / "no" / "a.csv", {"a"}), std::runtime_error);
}

TEST(OutputDigest, MatchesIndependentSha256) {
  const std::vector<double> x = {0.0, 1.0, -2.5, 1e-300, 3.141592653589793, 6.02214076e23};
  const std::vector<double> v = {
      0.1, -0.0, 7.0, -1.5e-8, std::numeric_limits<double>::denorm_min(), 123456.789};
  // python3 -c "import hashlib, struct; x=[0.0,1.0,-2.5,1e-300,3.141592653589793,6.02214076e23];
  //   v=[0.1,-0.0,7.0,-1.5e-8,2.0**-1074,123456.789];
  //   print(hashlib.sha256(struct.pack('<12d', *(x+v))).hexdigest())"
  EXPECT_EQ(crumple::output::stateDigest(x, v),
            "658618d948515e557f68955a6c01cbd5903574c3c9c88b669e314316fa124990");
  // FIPS 180-2 SHA-256 of the empty message.
  EXPECT_EQ(crumple::output::stateDigest({}, {}),
            "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  // x then v: swapping them changes the digest.
  EXPECT_NE(crumple::output::stateDigest(v, x), crumple::output::stateDigest(x, v));
}

TEST(OutputResultsDir, CreatesMissingFolderWithParents) {
  const fs::path dir = freshDir() / "a" / "b.out";
  crumple::output::prepareResultsDir(dir, false);
  EXPECT_TRUE(fs::is_directory(dir));
}

TEST(OutputResultsDir, AcceptsFolderWithoutResults) {
  const fs::path dir = freshDir();
  touch(dir / "taylor.k");
  EXPECT_NO_THROW(crumple::output::prepareResultsDir(dir, false));
  EXPECT_TRUE(fs::exists(dir / "taylor.k"));
}

TEST(OutputResultsDir, RefusesEarlierResultsWithoutOverwrite) {
  const fs::path dir = freshDir() / "taylor.out";
  fs::create_directories(dir);
  touch(dir / "summary.json");
  try {
    crumple::output::prepareResultsDir(dir, false);
    FAIL() << "expected InputError";
  } catch (const crumple::util::InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("'" + dir.string() +
                       "' already holds results of an earlier run "
                       "(summary.json); pass --overwrite"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("-o to choose another folder"), std::string::npos) << msg;
  }
  EXPECT_TRUE(fs::exists(dir / "summary.json"));

  // Pieces alone (an interrupted run) count as results too.
  const fs::path other = freshDir() / "other.out";
  fs::create_directories(other / "states");
  touch(other / "states" / "state_0000.pvtu");
  EXPECT_THROW(crumple::output::prepareResultsDir(other, false), crumple::util::InputError);
}

TEST(OutputResultsDir, OverwriteRemovesOnlyResults) {
  const fs::path dir = freshDir();
  for (const char* name : {"summary.json", "results.pvd", "glstat.csv", "matsum.csv", "nodout.csv",
                           "rcforc.csv", "rwforc.csv", "run.log", "mesh.vtu", "mesh.pvtu"}) {
    touch(dir / name);
  }
  fs::create_directories(dir / "states");
  touch(dir / "states" / "state_0000_0.vtu");
  touch(dir / "states" / "state_0000.pvtu");
  touch(dir / "states" / "state_0001_0.vtu.tmp");
  touch(dir / "results.pvd.tmp");
  // Not ours: must survive.
  touch(dir / "taylor.k");
  touch(dir / "notes.csv");
  touch(dir / "summary.json.bak");
  touch(dir / "draft.tmp");
  fs::create_directories(dir / "plots");
  touch(dir / "plots" / "old.vtu");

  crumple::output::prepareResultsDir(dir, true);

  std::vector<std::string> left;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    left.push_back(e.path().lexically_relative(dir).generic_string());
  }
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"draft.tmp", "notes.csv", "plots", "plots/old.vtu",
                                            "summary.json.bak", "taylor.k"}));
}

TEST(OutputResultsDir, OverwriteKeepsStatesFolderHoldingOtherFiles) {
  const fs::path dir = freshDir();
  fs::create_directories(dir / "states");
  touch(dir / "states" / "state_0001.vtu");
  touch(dir / "states" / "README");
  crumple::output::prepareResultsDir(dir, true);
  EXPECT_FALSE(fs::exists(dir / "states" / "state_0001.vtu"));
  EXPECT_TRUE(fs::exists(dir / "states" / "README"));
}

TEST(OutputResultsDir, RefusesAFileInPlaceOfTheFolder) {
  const fs::path file = freshDir() / "taylor.out";
  touch(file);
  EXPECT_THROW(crumple::output::prepareResultsDir(file, true), crumple::util::InputError);
  EXPECT_TRUE(fs::is_regular_file(file));
}

TEST(OutputProgress, LineFormat) {
  CapturedStream out;
  crumple::output::Progress progress(out.get(), false, 2e-5);
  progress.finish(12345, 1.234e-05, 2.1e-08, 1.0003);
  const std::string text = out.text();
  EXPECT_EQ(text.rfind("cycle 12345  t 1.234e-05  dt 2.1e-08  61.7%  ETA ", 0), 0u) << text;
  EXPECT_NE(text.find("  energy ratio 1.0003\n"), std::string::npos) << text;
}

TEST(OutputProgress, LogGetsOneLinePerDecileAndAFinalLine) {
  CapturedStream out;
  crumple::output::Progress progress(out.get(), false, 1.0);
  int64_t cycle = 0;
  for (double t : {0.0, 0.05, 0.1, 0.15, 0.25, 0.95, 1.0}) progress.update(++cycle, t, 1e-3, 1.0);
  progress.finish(++cycle, 1.0, 1e-3, 1.0);
  const std::string text = out.text();
  // 10% (at t = 0.1), 20%, 30..90% at once, then finish's 100%.
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 4) << text;
  EXPECT_EQ(text.find('\r'), std::string::npos);
  EXPECT_NE(text.find("cycle 3  t 1.000e-01"), std::string::npos) << text;
  EXPECT_NE(text.find("cycle 5  t 2.500e-01"), std::string::npos) << text;
  EXPECT_NE(text.find("cycle 6  t 9.500e-01"), std::string::npos) << text;
  EXPECT_NE(text.find("cycle 8  t 1.000e+00  dt 1.0e-03  100.0%  ETA 0:00:00"), std::string::npos)
      << text;
}

TEST(OutputProgress, TerminalRedrawsInPlaceAtMostFiveTimesASecond) {
  CapturedStream out;
  crumple::output::Progress progress(out.get(), true, 1.0);
  progress.update(1, 0.1, 1e-3, 1.0);  // drawn: the first update always is
  progress.update(2, 0.2, 1e-3, 1.0);  // too soon after the first
  std::this_thread::sleep_for(std::chrono::milliseconds(250));
  progress.update(3, 0.3, 1e-3, 1.0);
  progress.finish(4, 1.0, 1e-3, 1.0);
  const std::string text = out.text();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\r'), 3) << text;
  EXPECT_EQ(text.find("cycle 2 "), std::string::npos) << text;
  EXPECT_NE(text.find("\rcycle 3 "), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
  EXPECT_EQ(text.back(), '\n');
}

// A full disk, simulated by /dev/full (every write fails with ENOSPC): the writers must report
// the file and the reason instead of ending "normally" with truncated results.
TEST(OutputFullDisk, CsvWriterReportsTheFileOnFlush) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  crumple::output::CsvWriter csv("/dev/full", {"time", "value"});
  // Rows go to the stream's buffer; the failure shows when they are handed to the system.
  for (int i = 0; i < 10; ++i) csv.row({0.1 * i, 1.0});
  try {
    csv.flush();
    FAIL() << "flush to /dev/full succeeded";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("error while writing '/dev/full'"), std::string::npos) << what;
    EXPECT_NE(what.find("No space left on device"), std::string::npos) << what;
  }
}

TEST(OutputFullDisk, TextFileReportsTheFile) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  try {
    crumple::output::writeTextFile("/dev/full", std::string(100, 'x'));
    FAIL() << "writing /dev/full succeeded";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("'/dev/full': No space left on device"), std::string::npos)
        << e.what();
  }
  // The same call on a real file writes it whole.
  const fs::path dir = freshDir();
  crumple::output::writeTextFile(dir / "a.json", "{}\n");
  EXPECT_EQ(slurp(dir / "a.json"), "{}\n");
}

TEST(OutputResultsDir, RemoveRunOutputTakesOnlyWhatARunWrites) {
  const fs::path dir = freshDir();
  touch(dir / "run.log");
  touch(dir / "glstat.csv");
  fs::create_directories(dir / crumple::output::kStatesFolder);
  touch(dir / crumple::output::kStatesFolder / "state_00000.vtu");
  touch(dir / "notes.txt");
  crumple::output::removeRunOutput(dir, true);
  // The user's file stays, and with it the folder.
  ASSERT_TRUE(fs::exists(dir / "notes.txt"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove(dir / "notes.txt");
  touch(dir / "summary.json");
  crumple::output::removeRunOutput(dir, true);
  EXPECT_FALSE(fs::exists(dir));
}
