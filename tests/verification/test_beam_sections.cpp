// Hughes-Liu beams with *INTEGRATION_BEAM cross-sections (SECTION_BEAM QR/IRID < 0) through the
// whole pipeline against beam theory: the elastic tip deflection of a W-section cantilever
// (its E I), the collapse load of its plastic hinge (its plastic modulus Z), and user points
// equal to the built-in 2 x 2 Gauss rule giving the built-in rule's answer to 1e-12.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "harness.hpp"

namespace {

using crumple::testing::Simulation;
using crumple::testing::termination;

// A W section in mm (flange 100 x 10, depth 200, web 6), steel in mm, ms, kg, kN, GPa; nu = 0.
constexpr double kE = 210.0, kRho = 7.85e-6, kL = 4000.0;
constexpr double kBf = 100.0, kTf = 10.0, kH = 200.0, kTw = 6.0;
constexpr double kArea = 2.0 * kBf * kTf + (kH - 2.0 * kTf) * kTw;
// Strong-axis second moment and plastic modulus of the section.
constexpr double kI =
    (kBf * kH * kH * kH - (kBf - kTw) * (kH - 2 * kTf) * (kH - 2 * kTf) * (kH - 2 * kTf)) / 12.0;
constexpr double kZ = kBf * kTf * (kH - kTf) + kTw * (kH - 2 * kTf) * (kH - 2 * kTf) / 4.0;
constexpr double kShrf = 5.0 / 6.0;
constexpr int kN = 20;

// f1 = (1.8751^2 / 2 pi) sqrt(E I / (rho A L^4)), Euler-Bernoulli cantilever.
double period() {
  const double f1 =
      1.8751 * 1.8751 / (2.0 * M_PI) * std::sqrt(kE * kI / (kRho * kArea * std::pow(kL, 4)));
  return 1.0 / f1;
}

// A cantilever of kN Hughes-Liu beams along x, clamped at node 1; orientation node on +y, so
// s = y (the flanges' width) and t = z (the depth): z loads bend it about its strong axis.
std::string wBeamDeck(const std::string& material, const std::string& extra) {
  std::string s = "*KEYWORD\n*TITLE\nW-section cantilever\n" + extra + material;
  s += fmt::format("*SECTION_BEAM\n         1         1{:10.6g}        -7         0\n", kShrf);
  s += "       0.0       0.0       0.0       0.0\n";
  s += "*INTEGRATION_BEAM\n         7         0       0.0         1         0\n";
  s += fmt::format("{:10.4g}{:10.4g}{:10.4g}{:10.4g}\n", kBf, kTf, kH, kTw);
  s += "*PART\nbeam\n         1         1         1\n*NODE\n";
  for (int i = 0; i <= kN; ++i)
    s += fmt::format("{:8d}{:16.9g}{:16.9g}{:16.9g}\n", i + 1, kL * i / kN, 0.0, 0.0);
  s += fmt::format("{:8d}{:16.9g}{:16.9g}{:16.9g}\n", 1000, 0.0, 10.0, 0.0);
  s += "*ELEMENT_BEAM\n";
  for (int i = 0; i < kN; ++i)
    s += fmt::format("{:8d}{:8d}{:8d}{:8d}{:8d}\n", i + 1, 1, i + 1, i + 2, 1000);
  s += "*BOUNDARY_SPC_NODE\n         1         0         1         1         1         1         1 "
       "        1\n";
  s += "      1000         0         1         1         1         1         1         1\n";
  return s + "*END\n";
}

std::string elastic() {
  return fmt::format("*MAT_ELASTIC\n         1{:10.4g}{:10.4g}       0.0\n", kRho, kE);
}

// The tip load P ramped over 4 periods and held for 2; the tip's mean deflection over the hold
// (the residual vibration averages out over whole periods) against Timoshenko's cantilever,
// P L^3 / (3 E I) + P L / (k G A) (the shear term is 0.3 % of the total), within 1 %.
TEST(VerificationBeamSection, WSectionElasticTipDeflectionGivesItsEI) {
  const double T = period(), P = 1.0;  // kN: tip deflection about 5 mm, 0.1 % of L
  const std::string load =
      termination(6.0 * T) +
      fmt::format(
          "*DEFINE_CURVE\n         1\n{:20.6g}{:20.6g}\n{:20.6g}{:20.6g}\n{:20.6g}{:20.6g}\n", 0.0,
          0.0, 4.0 * T, 1.0, 1e6, 1.0) +
      fmt::format("*LOAD_NODE_POINT\n{:10d}         3         1{:10.4g}\n", kN + 1, P);
  auto sim = Simulation::fromText("w_beam_elastic", wBeamDeck(elastic(), load));
  double sum = 0.0, time = 0.0;
  sim->run([&](const crumple::solver::Solver& s) {
    if (s.time() <= 4.0 * T) return;
    sum += (sim->x(kN + 1, 2) - sim->x0(kN + 1, 2)) * s.dt();
    time += s.dt();
  });
  const double tip = sum / time;
  const double G = 0.5 * kE;
  const double theory = P * kL * kL * kL / (3.0 * kE * kI) + P * kL / (kShrf * G * kArea);
  EXPECT_NEAR(tip / theory, 1.0, 0.01) << "tip " << tip << " mm, theory " << theory;
  std::printf("[ figure ] W-section cantilever tip %.5g mm, theory %.5g mm, ratio %.4f\n", tip,
              theory, tip / theory);
}

// An elastic-perfectly-plastic W section (*MAT_003, ETAN 0) whose tip is driven slowly down to
// about three times its elastic deflection at collapse: the clamp reaction levels off at the
// collapse load P_c = sigma_y Z / (L - Le / 2), the hinge forming at the first element's
// integration point (mid-length). The section's 32 points integrate sigma_y |t| exactly (no
// piece straddles the neutral axis), so the plateau is Z sigma_y within 2 % (the web's shear
// takes a little of its yield stress, the slow drive adds a little inertia).
TEST(VerificationBeamSection, WSectionPlasticHingeGivesItsPlasticModulus) {
  const double sigy = 0.25, T = period();
  const double pc = sigy * kZ / (kL - 0.5 * kL / kN);
  const double elastic_tip = pc * kL * kL * kL / (3.0 * kE * kI);
  const double t_end = 6.0 * T, speed = 3.0 * elastic_tip / t_end;
  const std::string material = fmt::format(
      "*MAT_PLASTIC_KINEMATIC\n         1{:10.4g}{:10.4g}       0.0{:10.4g}       0.0"
      "       1.0\n",
      kRho, kE, sigy);
  const std::string drive =
      termination(t_end) +
      fmt::format(
          "*DEFINE_CURVE\n         2\n{:20.6g}{:20.6g}\n{:20.6g}{:20.6g}\n{:20.6g}{:20.6g}\n", 0.0,
          0.0, T, 1.0, 1e6, 1.0) +
      fmt::format(
          "*BOUNDARY_PRESCRIBED_MOTION_NODE\n{:10d}         3         0         2{:10.4g}\n",
          kN + 1, -speed);
  auto sim = Simulation::fromText("w_beam_plastic", wBeamDeck(material, drive));
  double sum = 0.0, time = 0.0;
  sim->run([&](const crumple::solver::Solver& s) {
    if (s.time() < 4.0 * T) return;
    // The clamped node's internal force balances the tip load (quasi-static).
    sum += sim->sd.f[3 * sim->local(1) + 2] * s.dt();
    time += s.dt();
  });
  const double plateau = std::abs(sum / time);
  EXPECT_NEAR(plateau / pc, 1.0, 0.02) << "plateau " << plateau << " kN, P_c " << pc;
  std::printf(
      "[ figure ] W-section plastic hinge plateau %.5g kN, P_c = sigma_y Z / L' %.5g kN, "
      "ratio %.4f\n",
      plateau, pc, plateau / pc);
  EXPECT_LT(sim->x(kN + 1, 2), -2.5 * elastic_tip);
}

// User points (ICST 0, NIP 4) placed and weighted as the built-in 2 x 2 Gauss rule (QR 2) of
// a 10 x 6 rectangle (free format, all 17 digits): the same run to 1e-12. Not to the bit: the
// user section's second moments are summed from its points (3 g)^2 = 2.9999999999999996,
// where the built-in rule takes b t^3 / 12; they set the rotary inertia.
TEST(VerificationBeamSection, UserPointsEqualToGaussGiveTheGaussAnswer) {
  const double g = 1.0 / std::sqrt(3.0);
  auto deck = [&](const std::string& section) {
    std::string s = "*KEYWORD\n" + termination(2.0) + elastic() + section +
                    "*PART\nbeam\n         1         1         1\n*NODE\n";
    for (int i = 0; i <= 4; ++i)
      s += fmt::format("{:8d}{:16.9g}{:16.9g}{:16.9g}\n", i + 1, 50.0 * i, 0.0, 0.0);
    s += "*ELEMENT_BEAM\n";
    for (int i = 0; i < 4; ++i) s += fmt::format("{:8d}{:8d}{:8d}{:8d}\n", i + 1, 1, i + 1, i + 2);
    s += "*BOUNDARY_SPC_NODE\n         1         0         1         1         1         1       "
         "  1         1\n*INITIAL_VELOCITY_NODE\n         5       0.0       1.0       2.0\n";
    return s + "*END\n";
  };
  const std::string gauss =
      "*SECTION_BEAM\n         1         1       1.0         2         0\n"
      "      10.0      10.0       6.0       6.0\n";
  std::string user =
      "*SECTION_BEAM\n         1         1       1.0        -3         0\n"
      "      10.0      10.0       6.0       6.0\n"
      "*INTEGRATION_BEAM\n         3         4       1.0         0         0\n";
  for (const double s : {-g, g})
    for (const double t : {-g, g}) user += fmt::format("{:.17g},{:.17g},0.25\n", s, t);
  auto a = Simulation::fromText("beam_gauss_rule", deck(gauss));
  auto b = Simulation::fromText("beam_user_rule", deck(user));
  a->run();
  b->run();
  ASSERT_EQ(a->sd.x.size(), b->sd.x.size());
  EXPECT_GT(std::abs(a->x(5, 2) - a->x0(5, 2)), 1.0);  // it moved
  for (std::size_t k = 0; k < a->sd.x.size(); ++k) {
    EXPECT_NEAR(a->sd.x[k], b->sd.x[k], 1e-12 * (1.0 + std::abs(a->sd.x[k]))) << k;
    EXPECT_NEAR(a->sd.v[k], b->sd.v[k], 1e-12 * (1.0 + std::abs(a->sd.v[k]))) << k;
  }
}

}  // namespace
