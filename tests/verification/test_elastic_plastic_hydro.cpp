// *MAT_ELASTIC_PLASTIC_HYDRO (010) in a whole run: a unit hex crushed in uniaxial strain (face
// x = 1 driven by -a(t), face x = 0 held in x, the lateral faces held in their normal
// directions), its axial stress against the answer worked by hand from the Keyword Manual's
// definition (vol. II, *MAT_010): the pressure of the linear EOS p = K (1/V - 1), V = 1 - a, and
// the deviator of uniaxial strain eps = ln V, elastic (q = 2G |eps|) up to SIG0 and then on
// sigma_y = SIG0 + EH eps_p with deps_p = 2G |deps| / (3G + EH): s_xx = -p - 2/3 q.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "harness.hpp"

using crumple::testing::brickDeck;
using crumple::testing::Simulation;
using crumple::testing::termination;
using crumple::testing::uniaxialStrainCrush;

TEST(VerificationMaterials, ElasticPlasticHydroUniaxialStrain) {
  constexpr double G = 37593.0, K = 140000.0, sig0 = 180.0, eh = 500.0;
  std::string s =
      "*MAT_ELASTIC_PLASTIC_HYDRO\n         1   8.90e-3   37593.0     180.0     500.0\n"
      "*EOS_LINEAR_POLYNOMIAL\n         1       0.0  140000.0\n"
      "*DEFINE_CURVE\n         1\n                 0.0                 0.0\n"
      "                 0.5                0.08\n" +
      termination(0.5);
  s += uniaxialStrainCrush();
  std::string deck = brickDeck(1, 1, 1, 1.0, 1.0, 1.0, s);
  // The part takes the EOS: *PART card  PID SECID MID EOSID.
  const std::string part = "         1         1         1\n";
  deck.replace(deck.find(part, deck.find("*PART")), part.size(),
               "         1         1         1         1\n");
  auto sim = Simulation::fromText("hydro_crush", deck);
  auto expected = [&](double a) {
    const double eps = -std::log(1.0 - a), ey = sig0 / (2.0 * G);
    const double q = eps <= ey ? 2.0 * G * eps : sig0 + eh * (eps - ey) * 2.0 * G / (3.0 * G + eh);
    return -K * (1.0 / (1.0 - a) - 1.0) - 2.0 / 3.0 * q;
  };
  // The stress of a step is computed on the positions before it (as the crushable foam test).
  double a = 0.0, worst = 0.0, shear = 0.0;
  int checked = 0;
  sim->run([&](const auto&) {
    const auto& blk = sim->sd.solid_blocks.at(0);
    worst =
        std::max(worst, std::abs(blk.sigAt(0, 0) - expected(a)) / (1.0 + std::abs(expected(a))));
    shear = std::max(shear, std::abs(blk.sigAt(3, 0)));
    a = sim->x0(8, 0) - sim->x(8, 0);  // node 8 = (1, 1, 1)
    ++checked;
  });
  EXPECT_GT(checked, 1000);
  EXPECT_NEAR(a, 0.08, 1e-6);
  // At a = 0.08: p = 12174, q = 180 + 500 x 0.0810 x 0.664 = 206.9, s_xx = -12312.
  EXPECT_NEAR(expected(0.08), -12312.0, 1.0);
  // What is left is the hex's midpoint integration of ln V (as for the crushable foam).
  EXPECT_LT(worst, 1e-3);
  EXPECT_LT(shear, 1e-9);
}
