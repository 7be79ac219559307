// Runs a deck through the library (reader -> model -> subdomain -> solver) for verification
// tests, and writes small block-mesh decks for them.
#pragma once

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "comm/communicator.hpp"
#include "domain/subdomain.hpp"
#include "model/build.hpp"
#include "solver/solver.hpp"

namespace crumple::testing {

class Simulation {
 public:
  explicit Simulation(const std::filesystem::path& deck)
      : model(model::readModel(deck)), sd(domain::buildSerialSubdomain(model)) {
    solver = std::make_unique<solver::Solver>(model, sd, comm::world());
    solver->initialize();
  }
  // The deck `text` written to a fresh file under the test temp folder; returns its path.
  static std::filesystem::path writeDeck(const std::string& name, const std::string& text) {
    // One folder per process: two suites running at once (worktrees) do not share decks.
    const auto dir = std::filesystem::temp_directory_path() /
                     ("crumple_verification_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto path = dir / (name + ".k");
    std::ofstream(path) << text;
    return path;
  }
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // Writes `text` to a fresh file under the test temp folder and reads it.
  static std::unique_ptr<Simulation> fromText(const std::string& name, const std::string& text) {
    return std::make_unique<Simulation>(writeDeck(name, text));
  }

  void run(const std::function<void(const solver::Solver&)>& each_cycle = {}) {
    while (!solver->finished()) {
      solver->step();
      if (each_cycle) each_cycle(*solver);
    }
  }

  // Node's current position / velocity component by user id.
  double x(int64_t node_id, int c) const { return sd.x[3 * local(node_id) + std::size_t(c)]; }
  double x0(int64_t node_id, int c) const { return sd.x0[3 * local(node_id) + std::size_t(c)]; }
  double v(int64_t node_id, int c) const { return sd.v[3 * local(node_id) + std::size_t(c)]; }
  std::size_t local(int64_t node_id) const {
    return static_cast<std::size_t>(model.nodeIndex(node_id));  // serial: local == model index
  }
  double momentum(int c) const {
    double p = 0.0;
    for (std::size_t n = 0; n < sd.numNodes(); ++n) p += sd.mass[n] * sd.v[3 * n + std::size_t(c)];
    return p;
  }

  model::Model model;
  domain::Subdomain sd;
  std::unique_ptr<solver::Solver> solver;
};

// Period of a node's free vibration from the first two downward zero crossings of its z
// displacement (linear interpolation between cycles); 0 (and a failed expectation) when the
// run ends before two crossings.
inline double measuredPeriod(Simulation& sim, int64_t node) {
  std::vector<double> crossings;
  double z_prev = 0.0, t_prev = 0.0;
  sim.run([&](const solver::Solver& s) {
    const double z = sim.x(node, 2) - sim.x0(node, 2);
    if (z_prev > 0.0 && z <= 0.0)
      crossings.push_back(t_prev + (s.time() - t_prev) * z_prev / (z_prev - z));
    z_prev = z;
    t_prev = s.time();
  });
  EXPECT_GE(crossings.size(), 2u);
  return crossings.size() >= 2 ? crossings[1] - crossings[0] : 0.0;
}

// *CONTROL_TERMINATION at time t.
inline std::string termination(double t) {
  return fmt::format("*CONTROL_TERMINATION\n{:10.6g}\n", t);
}

// A brick of nx x ny x nz hexes on [0,lx]x[0,ly]x[0,lz], part 1, node (i,j,k) has id
// 1 + i + (nx+1) j + (nx+1)(ny+1) k. `extra` holds the material, controls and loads.
inline std::string brickDeck(int nx, int ny, int nz, double lx, double ly, double lz,
                             const std::string& extra) {
  std::string s = "*KEYWORD\n*TITLE\nverification brick\n" + extra;
  s +=
      "*PART\nbrick\n         1         1         1\n*SECTION_SOLID\n         1         1\n*NODE\n";
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        s += fmt::format("{:8d}{:16.9g}{:16.9g}{:16.9g}\n", 1 + i + (nx + 1) * (j + (ny + 1) * k),
                         lx * i / nx, ly * j / ny, lz * k / nz);
  s += "*ELEMENT_SOLID\n";
  auto id = [&](int i, int j, int k) { return 1 + i + (nx + 1) * (j + (ny + 1) * k); };
  int e = 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        s +=
            fmt::format("{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}{:8d}\n", e++, 1, id(i, j, k),
                        id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                        id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1));
  return s + "*END\n";
}

// *SET_NODE_LIST of the brick nodes selected by pred(i, j, k).
template <class Pred>
std::string brickNodeSet(int set_id, int nx, int ny, int nz, Pred pred) {
  std::string s = fmt::format("*SET_NODE_LIST\n{:10d}\n", set_id);
  int col = 0;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        if (pred(i, j, k)) {
          s += fmt::format("{:10d}", 1 + i + (nx + 1) * (j + (ny + 1) * k));
          if (++col == 8) {
            s += "\n";
            col = 0;
          }
        }
  if (col) s += "\n";
  return s;
}

// A unit cube (brickDeck(1, 1, 1, ...)) in uniaxial strain: face x = 1 displaced by -a(t), the
// values of curve 1 (*BOUNDARY_PRESCRIBED_MOTION_SET, displacement), face x = 0 held in x, the
// lateral faces held in their normal directions (node sets 1-4).
inline std::string uniaxialStrainCrush() {
  std::string s = brickNodeSet(1, 1, 1, 1, [](int i, int, int) { return i == 1; });
  s += "*BOUNDARY_PRESCRIBED_MOTION_SET\n         1         1         2         1      -1.0\n";
  for (int d = 0; d < 3; ++d) {
    s += brickNodeSet(2 + d, 1, 1, 1, [d](int i, int j, int k) {
      const int c = d == 0 ? i : d == 1 ? j : k;
      return c == 0 || (d > 0 && c == 1);
    });
    s += fmt::format("*BOUNDARY_SPC_SET\n{:10d}{:10d}{:10d}{:10d}{:10d}\n", 2 + d, 0, int(d == 0),
                     int(d == 1), int(d == 2));
  }
  return s;
}

// Node sets 4, 5, 6 (the faces x = 0, y = 0, z = 0 of a unit cube) held along their normals:
// rollers, so the cube stretches or shears freely otherwise.
inline std::string rollersOnLowFaces() {
  std::string s;
  for (int d = 0; d < 3; ++d) {
    s += brickNodeSet(4 + d, 1, 1, 1, [d](int i, int j, int k) {
      return (d == 0 ? i : d == 1 ? j : k) == 0;
    });
    s += fmt::format("*BOUNDARY_SPC_SET\n{:10d}{:10d}{:10d}{:10d}{:10d}\n", 4 + d, 0,
                     d == 0 ? 1 : 0, d == 1 ? 1 : 0, d == 2 ? 1 : 0);
  }
  return s;
}

// A unit cube pulled along x at the constant velocity v to the strain `strain` (face x = 1
// prescribed), on rollers on the faces x = 0, y = 0, z = 0 and otherwise free: uniaxial stress,
// the lateral faces contracting as the material lets them (the wave transit, 2e-7 s for steel,
// is short beside the pull, 1.2e-4 s to 12 % at 1000 /s, so inertia leaves the lateral stress
// negligible).
inline std::string uniaxialPull(const std::string& material, double v, double strain = 0.12) {
  const double t_end = strain / v;
  std::string s = material + termination(t_end);
  s += fmt::format("*DEFINE_CURVE\n{:10d}\n{:20.12g}{:20.12g}\n{:20.12g}{:20.12g}\n", 90, 0.0, v,
                   2.0 * t_end, v);
  s += brickNodeSet(1, 1, 1, 1, [](int i, int, int) { return i == 1; });
  s += fmt::format("*BOUNDARY_PRESCRIBED_MOTION_SET\n{:10d}{:10d}{:10d}{:10d}{:10.1f}\n", 1, 1, 0,
                   90, 1.0);
  return brickDeck(1, 1, 1, 1.0, 1.0, 1.0, s + rollersOnLowFaces());
}

// A unit cube whose faces x = 1, y = 1, z = 1 move by -a(t) along their normals (a from curve
// 1) and whose faces x = 0, y = 0, z = 0 are held: V/V0 = (1 - a)^3, no shear.
inline std::string triaxialCompression(const std::string& material, double t_end) {
  std::string s = material + termination(t_end);
  for (int d = 0; d < 3; ++d) {
    s += brickNodeSet(1 + d, 1, 1, 1, [d](int i, int j, int k) {
      return (d == 0 ? i : d == 1 ? j : k) == 1;
    });
    s += brickNodeSet(4 + d, 1, 1, 1, [d](int i, int j, int k) {
      return (d == 0 ? i : d == 1 ? j : k) == 0;
    });
    s += fmt::format("*BOUNDARY_PRESCRIBED_MOTION_SET\n{:10d}{:10d}{:10d}{:10d}{:10.1f}\n", 1 + d,
                     d + 1, 2, 1, -1.0);
    const int dof = d + 1;
    s += fmt::format("*BOUNDARY_SPC_SET\n{:10d}{:10d}{:10d}{:10d}{:10d}\n", 4 + d, 0,
                     dof == 1 ? 1 : 0, dof == 2 ? 1 : 0, dof == 3 ? 1 : 0);
  }
  return brickDeck(1, 1, 1, 1.0, 1.0, 1.0, s);
}

// A wall force history (time, normal force) of a body striking a wall: how long the force
// stays above 5% of `reference` and its mean over the middle 60% of the expected contact
// `duration` (the front is smeared over a few elements, so the plateau is measured away from
// its ends). `samples` counts the values averaged.
struct WallPlateau {
  double mean = 0.0, duration = 0.0;
  int samples = 0;
};
inline WallPlateau wallPlateau(const std::vector<std::pair<double, double>>& force,
                               double reference, double duration) {
  double t_first = -1.0, t_last = -1.0;
  for (const auto& [t, f] : force)
    if (f > 0.05 * reference) {
      if (t_first < 0) t_first = t;
      t_last = t;
    }
  WallPlateau w;
  double sum = 0.0;
  for (const auto& [t, f] : force)
    if (t > t_first + 0.2 * duration && t < t_first + 0.8 * duration) {
      sum += f;
      ++w.samples;
    }
  w.mean = w.samples > 0 ? sum / w.samples : 0.0;
  w.duration = t_last - t_first;
  return w;
}

inline std::filesystem::path sourceDir() {
  return CRUMPLE_SOURCE_DIR;
}

// ---- cantilever helpers (test_structures.cpp, test_tshells.cpp) ----

// The static deflection shape of a tip-loaded cantilever, xi = x / L, tip value 1: close to
// the first mode, so an initial velocity in this shape excites almost only mode 1.
inline double staticShape(double xi) {
  return 0.5 * xi * xi * (3.0 - xi);
}

// Mean tip deflection over the hold after a slow ramp of the tip load P: the residual
// vibration averages out over whole periods.
inline double quasiStaticTip(Simulation& sim, int64_t tip, double t_hold) {
  double sum = 0.0, time = 0.0;
  sim.run([&](const crumple::solver::Solver& s) {
    if (s.time() <= t_hold) return;
    sum += (sim.x(tip, 2) - sim.x0(tip, 2)) * s.dt();
    time += s.dt();
  });
  return sum / time;
}

// Ramp over 4 periods, hold for 2: tip load split over the tip nodes in `loads`.
inline std::string tipLoad(double period, const std::string& loads) {
  return termination(6.0 * period) +
         fmt::format(
             "*DEFINE_CURVE\n         1\n{:20.6g}{:20.6g}\n{:20.6g}{:20.6g}\n{:20.6g}{:20.6g}\n",
             0.0, 0.0, 4.0 * period, 1.0, 1000.0, 1.0) +
         "*LOAD_NODE_POINT\n" + loads;
}

}  // namespace crumple::testing
