// Impact problems with known answers (shared/reference/verification.md #1 and #2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

#include "harness.hpp"

namespace {

using crumple::testing::Simulation;
using crumple::testing::sourceDir;

// #1: elastic bar (nu = 0, so uniaxial stress holds exactly) at v0 onto a stonewall.
// 1D wave theory: wall stress rho c0 v0 while the bar touches, for 2L/c0, rebound at v0.
// The mesh has 100 elements along the bar: the front is smeared over a few elements, so the
// plateau is measured away from its ends; 3% on stress and duration, 5% on rebound speed.
class VerificationImpactElform : public ::testing::TestWithParam<int> {};

TEST_P(VerificationImpactElform, ElasticBarOnRigidWall) {
  // The example deck, with its section switched to the element formulation under test.
  std::ifstream in(sourceDir() / "examples/bar_impact/bar_impact.k");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string section = "*SECTION_SOLID\n         1         1\n";
  ASSERT_NE(text.find(section), std::string::npos);
  text.replace(text.find(section), section.size(),
               fmt::format("*SECTION_SOLID\n         1{:10d}\n", GetParam()));
  auto owned = Simulation::fromText(fmt::format("bar_impact_elform{}", GetParam()), text);
  Simulation& sim = *owned;
  const double rho = 7.85e-6, E = 210.0, v0 = 10.0, L = 100.0, area = 100.0;
  const double c0 = std::sqrt(E / rho);
  const double stress = rho * c0 * v0, duration = 2.0 * L / c0;
  std::vector<std::pair<double, double>> force;  // (time, wall normal force)
  sim.run([&](const auto& s) {
    force.emplace_back(s.time(), s.boundary().walls().at(0).normal_force);
  });

  double peak = 0.0;
  for (const auto& [t, f] : force) peak = std::max(peak, f);
  const auto wall = crumple::testing::wallPlateau(force, peak, duration);
  ASSERT_GT(wall.samples, 10);
  const double plateau = wall.mean / area;
  EXPECT_NEAR(plateau, stress, 0.03 * stress) << "wall stress";
  EXPECT_NEAR(wall.duration, duration, 0.03 * duration) << "contact duration";

  double mass = 0.0;
  for (double m : sim.sd.mass) mass += m;
  const double rebound = sim.momentum(2) / mass;
  EXPECT_NEAR(rebound, v0, 0.05 * v0) << "rebound speed";
  // Energy: kinetic + internal + stonewall absorption balances the initial kinetic energy.
  const auto e = sim.solver->energies();
  EXPECT_NEAR(e.ratio, 1.0, 0.01);
}

INSTANTIATE_TEST_SUITE_P(OnePointAndFullyIntegrated, VerificationImpactElform,
                         ::testing::Values(1, 2));

// #2: Taylor bar (Kamoulakos 1990): final length within 2% of 21.47 mm, footprint radius
// within 5% of 7.1 mm, hourglass energy below 5% of internal energy, on the flagship example.
TEST(VerificationImpact, TaylorBar) {
  Simulation sim(sourceDir() / "examples/taylor_bar/taylor_bar.k");
  sim.run();
  double length = 0.0, radius = 0.0;
  for (std::size_t n = 0; n < sim.sd.numNodes(); ++n) {
    const double* x = &sim.sd.x[3 * n];
    length = std::max(length, x[2]);
    if (std::abs(sim.sd.x0[3 * n + 2]) < 1e-9) radius = std::max(radius, std::hypot(x[0], x[1]));
  }
  EXPECT_NEAR(length, 21.47, 0.02 * 21.47) << "final length";
  EXPECT_NEAR(radius, 7.1, 0.05 * 7.1) << "footprint radius";
  const auto e = sim.solver->energies();
  EXPECT_LT(e.hourglass, 0.05 * e.internal);
  EXPECT_NEAR(e.ratio, 1.0, 0.02);
  RecordProperty("final_length_mm", std::to_string(length));
  RecordProperty("footprint_radius_mm", std::to_string(radius));
}

}  // namespace
