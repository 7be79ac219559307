// VTU/PVTU/PVD files are checked by reading them back with VTK's own readers
// (tests/tools/read_vtu.py), not by comparing bytes: what matters is that ParaView reads them.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "output/vtk.hpp"

namespace fs = std::filesystem;
using crumple::output::Association;
using crumple::output::FieldView;
using crumple::output::MeshView;
using nlohmann::json;

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

// The first interpreter that can import vtk: the Debian bindings live in the system Python,
// which a pyenv/virtualenv python3 earlier on PATH does not see.
std::optional<std::string> pythonWithVtk() {
  static const std::optional<std::string> found = []() -> std::optional<std::string> {
    std::vector<std::string> candidates;
    if (const char* env = std::getenv("CRUMPLE_PYTHON")) candidates.emplace_back(env);
    candidates.emplace_back("python3");
    candidates.emplace_back("/usr/bin/python3");
    for (const std::string& py : candidates) {
      const std::string cmd = "'" + py + "' -c 'import vtk' >/dev/null 2>&1";
      if (std::system(cmd.c_str()) == 0) return py;
    }
    return std::nullopt;
  }();
  return found;
}

// Runs read_vtu.py on `file` and parses its JSON; fails the test when VTK reports any error.
json readBack(const std::string& python, const fs::path& file) {
  const fs::path script = fs::path(CRUMPLE_SOURCE_DIR) / "tests" / "tools" / "read_vtu.py";
  const std::string cmd =
      "'" + python + "' '" + script.string() + "' '" + file.string() + "' --values --volumes";
  std::FILE* pipe = popen(cmd.c_str(), "r");
  if (pipe == nullptr) {
    ADD_FAILURE() << "cannot run " << cmd;
    return {};
  }
  std::string out;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
  const int status = pclose(pipe);
  if (status != 0) {
    ADD_FAILURE() << cmd << " exited with status " << status << "\n" << out;
    return {};
  }
  return json::parse(out);
}

// One hexahedron (unit cube), one wedge and one tetrahedron, all given LS-DYNA style as
// (degenerate) 8-node hexahedra, plus a hexahedron collapsed in a way that is neither.
struct ThreeCells {
  std::vector<double> points;
  std::vector<int32_t> hexes;
  ThreeCells() {
    auto add = [&](double x, double y, double z) {
      points.insert(points.end(), {x, y, z});
      return static_cast<int32_t>(points.size() / 3 - 1);
    };
    // Hexahedron: bottom face counter-clockwise seen from above, then the top face.
    std::vector<int32_t> h;
    for (double z : {0.0, 1.0}) {
      h.push_back(add(0, 0, z));
      h.push_back(add(1, 0, z));
      h.push_back(add(1, 1, z));
      h.push_back(add(0, 1, z));
    }
    hexes.insert(hexes.end(), h.begin(), h.end());
    // Pentahedron N1 N2 N3 N4 N5 N5 N6 N6: a unit-square base and a ridge at x = 2.5, z = 1.
    const int32_t w1 = add(2, 0, 0), w2 = add(3, 0, 0), w3 = add(3, 1, 0), w4 = add(2, 1, 0);
    const int32_t w5 = add(2.5, 0, 1), w6 = add(2.5, 1, 1);
    hexes.insert(hexes.end(), {w1, w2, w3, w4, w5, w5, w6, w6});
    // Tetrahedron N1 N2 N3 N4 N4 N4 N4 N4 of volume 1/6.
    const int32_t t1 = add(4, 0, 0), t2 = add(5, 0, 0), t3 = add(4, 1, 0), t4 = add(4.3, 0.3, 1);
    hexes.insert(hexes.end(), {t1, t2, t3, t4, t4, t4, t4, t4});
    // Only N7 = N8: not a shape LS-DYNA defines, so it stays a hexahedron.
    hexes.insert(hexes.end(), {h[0], h[1], h[2], h[3], h[4], h[5], h[6], h[6]});
  }
  MeshView view() const {
    return {points.size() / 3, points.data(), hexes.size() / 8, hexes.data()};
  }
};

}  // namespace

TEST(OutputVtk, HexWedgeTetReadBackByVtk) {
  const auto python = pythonWithVtk();
  if (!python) GTEST_SKIP() << "no python3 that can import vtk";
  const ThreeCells mesh;
  const MeshView view = mesh.view();
  std::vector<double> velocity(3 * view.num_points);
  for (std::size_t i = 0; i < velocity.size(); ++i) velocity[i] = 0.5 * static_cast<double>(i);
  std::vector<int64_t> node_id(view.num_points);
  for (std::size_t i = 0; i < node_id.size(); ++i) node_id[i] = 1000 + static_cast<int64_t>(i);
  const std::vector<int64_t> part = {7, 8, 9, 7};
  std::vector<double> stress(6 * view.num_cells);
  for (std::size_t i = 0; i < stress.size(); ++i) stress[i] = -1.25 * static_cast<double>(i);

  const fs::path dir = freshDir();
  const fs::path file = dir / "cells.vtu";
  crumple::output::writeVtu(file, view,
                            {{"velocity", Association::Point, 3, velocity.data(), nullptr},
                             {"node_id", Association::Point, 1, nullptr, node_id.data()},
                             {"part", Association::Cell, 1, nullptr, part.data()},
                             {"stress", Association::Cell, 6, stress.data(), nullptr}});
  EXPECT_FALSE(fs::exists(dir / "cells.vtu.tmp"));

  const json r = readBack(*python, file);
  ASSERT_FALSE(r.is_null());
  EXPECT_EQ(r["points"], view.num_points);
  EXPECT_EQ(r["cells"], 4);
  EXPECT_EQ(r["cell_types"], json::array({12, 13, 10, 12}));
  // Positive volumes of the right size show the node order VTK expects for each shape.
  const auto& volumes = r["volumes"];
  EXPECT_NEAR(volumes[0].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(volumes[1].get<double>(), 0.5, 1e-12);
  EXPECT_NEAR(volumes[2].get<double>(), 1.0 / 6.0, 1e-12);

  const auto& vel = r["point_data"]["velocity"];
  EXPECT_EQ(vel["type"], "double");
  EXPECT_EQ(vel["components"], 3);
  EXPECT_EQ(vel["values"][3 * 9 + 2].get<double>(), velocity[3 * 9 + 2]);
  const auto& ids = r["point_data"]["node_id"];
  EXPECT_EQ(ids["components"], 1);
  EXPECT_EQ(ids["values"][17].get<double>(), 1017.0);
  EXPECT_EQ(r["cell_data"]["part"]["values"], json::array({7.0, 8.0, 9.0, 7.0}));
  const auto& st = r["cell_data"]["stress"];
  EXPECT_EQ(st["components"], 6);
  EXPECT_EQ(st["values"][6 * 2 + 4].get<double>(), stress[6 * 2 + 4]);
}

TEST(OutputVtk, PiecesCollectionReadBackByVtk) {
  const auto python = pythonWithVtk();
  if (!python) GTEST_SKIP() << "no python3 that can import vtk";
  const ThreeCells mesh;
  // Two pieces, as two ranks would write them: the hexahedron alone, and the wedge and tet
  // with their own local point numbering.
  const std::vector<double> p0(mesh.points.begin(), mesh.points.begin() + 3 * 8);
  const std::vector<double> p1(mesh.points.begin() + 3 * 8, mesh.points.end());
  const std::vector<int32_t> h0(mesh.hexes.begin(), mesh.hexes.begin() + 8);
  std::vector<int32_t> h1(mesh.hexes.begin() + 8, mesh.hexes.begin() + 24);
  for (int32_t& n : h1) n -= 8;
  const MeshView v0{8, p0.data(), 1, h0.data()};
  const MeshView v1{p1.size() / 3, p1.data(), 2, h1.data()};

  const fs::path dir = freshDir();
  fs::create_directories(dir / "states");
  crumple::output::PvdWriter pvd(dir / "results.pvd");
  const std::vector<double> times = {0.0, 2.5e-5};
  for (std::size_t s = 0; s < times.size(); ++s) {
    std::vector<double> disp0(p0.size(), static_cast<double>(s));
    std::vector<double> disp1(p1.size(), static_cast<double>(s));
    const std::vector<int64_t> rank0 = {0}, rank1 = {1, 1};
    auto fields = [](const std::vector<double>& d, const std::vector<int64_t>& r) {
      return std::vector<FieldView>{{"displacement", Association::Point, 3, d.data(), nullptr},
                                    {"rank", Association::Cell, 1, nullptr, r.data()}};
    };
    const std::string stem = "state_" + std::to_string(s);
    crumple::output::writeVtu(dir / "states" / (stem + "_0.vtu"), v0, fields(disp0, rank0));
    crumple::output::writeVtu(dir / "states" / (stem + "_1.vtu"), v1, fields(disp1, rank1));
    crumple::output::writePvtu(dir / "states" / (stem + ".pvtu"),
                               {stem + "_0.vtu", stem + "_1.vtu"}, fields(disp0, rank0));
    pvd.addState(times[s], "states/" + stem + ".pvtu");

    // The collection is complete after every state, so an interrupted run stays readable.
    const json r = readBack(*python, dir / "results.pvd");
    ASSERT_FALSE(r.is_null());
    ASSERT_EQ(r["states"].size(), s + 1);
    EXPECT_FALSE(fs::exists(dir / "results.pvd.tmp"));
  }

  const json r = readBack(*python, dir);  // a results folder means its results.pvd
  ASSERT_FALSE(r.is_null());
  ASSERT_EQ(r["states"].size(), 2u);
  for (std::size_t s = 0; s < 2; ++s) {
    const auto& state = r["states"][s];
    EXPECT_EQ(state["timestep"].get<double>(), times[s]);
    EXPECT_EQ(state["points"], 8 + p1.size() / 3);
    EXPECT_EQ(state["cells"], 3);
    EXPECT_EQ(state["cell_types"], json::array({12, 13, 10}));
    EXPECT_EQ(state["cell_data"]["rank"]["values"], json::array({0.0, 1.0, 1.0}));
    EXPECT_EQ(state["point_data"]["displacement"]["range"],
              json::array({static_cast<double>(s), static_cast<double>(s)}));
  }
}

TEST(OutputVtk, PvdListsStatesInOrder) {
  const fs::path dir = freshDir();
  crumple::output::PvdWriter pvd(dir / "results.pvd");
  pvd.addState(0.0, "states/a.pvtu");
  pvd.addState(1e-3, "states/b&c.pvtu");
  std::ifstream in(dir / "results.pvd");
  std::stringstream text;
  text << in.rdbuf();
  const std::string xml = text.str();
  EXPECT_NE(xml.find("<VTKFile type=\"Collection\""), std::string::npos);
  const auto a = xml.find("timestep=\"0\" group=\"\" part=\"0\" file=\"states/a.pvtu\"");
  const auto b = xml.find("timestep=\"0.001\" group=\"\" part=\"0\" file=\"states/b&amp;c.pvtu\"");
  EXPECT_NE(a, std::string::npos);
  EXPECT_NE(b, std::string::npos);
  EXPECT_LT(a, b);
}

TEST(OutputVtk, WriteFailureNamesThePath) {
  const ThreeCells mesh;
  const fs::path file = freshDir() / "missing" / "cells.vtu";
  try {
    crumple::output::writeVtu(file, mesh.view(), {});
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}

TEST(OutputVtk, RejectsOutOfRangeNodeAndFieldWithoutData) {
  const ThreeCells mesh;
  MeshView view = mesh.view();
  view.num_points = 5;
  const fs::path dir = freshDir();
  EXPECT_THROW(crumple::output::writeVtu(dir / "bad.vtu", view, {}), std::invalid_argument);
  EXPECT_THROW(crumple::output::writeVtu(dir / "bad.vtu", mesh.view(),
                                         {{"nothing", Association::Point, 1, nullptr, nullptr}}),
               std::invalid_argument);
  EXPECT_FALSE(fs::exists(dir / "bad.vtu"));
}
