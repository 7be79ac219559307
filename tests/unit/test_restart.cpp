// Restart dumps: the file format (checksum, truncation, sections), the dump rotation, the CSV
// continuation, and the solver's state sections round-tripped through a second solver.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>

#include "comm/communicator.hpp"
#include "domain/subdomain.hpp"
#include "model/build.hpp"
#include "output/files.hpp"
#include "output/restart.hpp"
#include "solver/solver.hpp"
#include "temp_dir.hpp"

namespace crumple {
namespace {

using testing::errorOf;
using testing::TempDir;

std::vector<char> bytesOf(const std::string& s) {
  return {s.begin(), s.end()};
}

TEST(RestartFile, SectionsRoundTrip) {
  const auto file =
      output::encodeDump({{"a", bytesOf("first")}, {"empty", {}}, {"b", {'\0', 'x'}}});
  const auto d = output::decodeDump(file, "dump");
  ASSERT_EQ(d.sections.size(), 3u);
  EXPECT_EQ(d.sections.at("a"), bytesOf("first"));
  EXPECT_TRUE(d.sections.at("empty").empty());
  EXPECT_EQ(d.sections.at("b"), (std::vector<char>{'\0', 'x'}));
}

TEST(RestartFile, CorruptionTruncationAndForeignFilesAreNamed) {
  const auto file = output::encodeDump({{"nodes", std::vector<char>(1000, 'n')}});
  auto flipped = file;
  flipped[flipped.size() / 2] ^= 0x10;
  EXPECT_NE(errorOf([&] { output::decodeDump(flipped, "d3dump_7"); }).find("d3dump_7: corrupted"),
            std::string::npos);
  auto cut = file;
  cut.resize(cut.size() - 1);
  EXPECT_NE(errorOf([&] { output::decodeDump(cut, "d3dump_7"); }).find("truncated"),
            std::string::npos);
  EXPECT_NE(errorOf([&] {
              output::decodeDump(bytesOf("*KEYWORD\n"), "x.k");
            }).find("not a Crumple restart dump"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { output::decodeDump({}, "empty"); }).find("not a Crumple"),
            std::string::npos);
}

TEST(RestartFile, KeepsTheTwoNewestAndNoTemporary) {
  TempDir tmp("restart_rotation");
  for (int64_t c : {10, 20, 30, 40}) output::writeDumpFile(tmp.path(), c, output::encodeDump({}));
  const auto all = output::dumpFiles(tmp.path());
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(output::dumpCycle(all[0]), 30);
  EXPECT_EQ(output::dumpCycle(all[1]), 40);
  EXPECT_FALSE(std::filesystem::exists(tmp.path() / output::kDumpTemporary));
  EXPECT_EQ(output::resolveDump(tmp.path()), all[1]);
  EXPECT_EQ(output::readDump(all[0]).cycle, 30);
}

TEST(RestartFile, RegistryRefusesDuplicatesAndMissingSections) {
  output::DumpRegistry reg;
  int loaded = 0;
  reg.add({"x", [] { return std::vector<char>{'1'}; },
           [&](const std::vector<char>& b) { loaded += b.at(0) - '0'; }});
  EXPECT_THROW(reg.add({"x", nullptr, nullptr}), std::logic_error);
  reg.add({"later", [] { return std::vector<char>{}; },
           [&](const std::vector<char>&) { loaded += 10; }, true});
  const auto& comm = comm::world();
  auto d = output::decodeDump(reg.save(comm), "d");
  d.sections.erase("later");  // a dump written before the optional section existed
  reg.restore(d, comm);
  EXPECT_EQ(loaded, 1);
  d.sections.erase("x");
  EXPECT_NE(errorOf([&] { reg.restore(d, comm); }).find("no 'x' section"), std::string::npos);
}

TEST(RestartCsv, ContinuesAfterTheDumpAndRefusesAnotherRunsFile) {
  TempDir tmp("restart_csv");
  const auto path = tmp.path() / "h.csv";
  output::CsvWriter::Position at_dump;
  {
    output::CsvWriter w(path, {"a", "b"});
    w.row({1, 2});
    at_dump = w.position();
    w.row({3, 4});  // written after the dump: cut on restart
    w.flush();
  }
  {
    output::CsvWriter w(path, {"a", "b"}, at_dump);
    w.row({5, 6});
  }
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "a,b\n1,2\n5,6\n");
  auto other = at_dump;
  other.hash ^= 1;
  EXPECT_NE(
      errorOf([&] { output::CsvWriter::checkResume(path, other); }).find("does not hold the run"),
      std::string::npos);
  auto longer = at_dump;
  longer.bytes = 1000;
  EXPECT_NE(errorOf([&] { output::CsvWriter::checkResume(path, longer); }).find("shorter"),
            std::string::npos);
}

// Two solvers on the same deck: the second is initialised, takes the first's state after 40
// cycles, and both run on: every node must agree bit for bit.
struct DeckRun {
  model::Model model;
  domain::Subdomain sd;
  std::unique_ptr<solver::Solver> s;
  explicit DeckRun(const std::string& deck, double end_time)
      : model(model::readModel(deck)),
        sd((model.controls.end_time = end_time, domain::buildSerialSubdomain(model))) {
    s = std::make_unique<solver::Solver>(model, sd, comm::world());
    s->initialize();
  }
};

using Section = solver::Solver::StateSection;
constexpr Section kSections[] = {Section::Scalars, Section::Nodes, Section::Elements,
                                 Section::Constraints};

void expectContinuesBitwise(const std::string& deck, double end_time) {
  DeckRun a(deck, end_time), b(deck, end_time);
  for (int i = 0; i < 40; ++i) a.s->step();
  for (Section sec : kSections) b.s->loadState(sec, a.s->saveState(sec));
  EXPECT_EQ(b.s->cycle(), 40);
  EXPECT_EQ(b.s->time(), a.s->time());
  for (int i = 0; i < 60 && !a.s->finished(); ++i) {
    a.s->step();
    b.s->step();
  }
  EXPECT_EQ(a.sd.x, b.sd.x) << deck;
  EXPECT_EQ(a.sd.v, b.sd.v) << deck;
  EXPECT_EQ(a.sd.w, b.sd.w) << deck;
  const auto ea = a.s->energies(), eb = b.s->energies();
  EXPECT_EQ(ea.internal, eb.internal);
  EXPECT_EQ(ea.kinetic, eb.kinetic);
  EXPECT_EQ(ea.external_work, eb.external_work);
  EXPECT_EQ(ea.total, eb.total);
}

TEST(RestartSolver, ShellsBeamsSpringsContinueBitwise) {
  expectContinuesBitwise(std::string(CRUMPLE_SOURCE_DIR) + "/tests/data/decks/structures.k", 1.0);
}

TEST(RestartSolver, RigidBodiesWeldsAndLoadsContinueBitwise) {
  expectContinuesBitwise(std::string(CRUMPLE_SOURCE_DIR) + "/tests/data/decks/rigid_welds.k", 0.06);
  expectContinuesBitwise(std::string(CRUMPLE_SOURCE_DIR) + "/tests/data/decks/mixed_conditions.k",
                         0.05);
}

TEST(RestartSolver, DumpOfAnotherDeckIsRefused) {
  DeckRun a(std::string(CRUMPLE_SOURCE_DIR) + "/tests/data/decks/structures.k", 1.0);
  DeckRun b(std::string(CRUMPLE_SOURCE_DIR) + "/examples/bar_impact/bar_impact.k", 0.05);
  a.s->step();
  const auto scalars = a.s->saveState(Section::Scalars);
  const auto nodes = a.s->saveState(Section::Nodes);
  const std::string msg = errorOf([&] {
    b.s->loadState(Section::Scalars, scalars);
    b.s->loadState(Section::Nodes, nodes);
  });
  EXPECT_NE(msg.find("does not belong to this deck"), std::string::npos) << msg;
}

}  // namespace
}  // namespace crumple
