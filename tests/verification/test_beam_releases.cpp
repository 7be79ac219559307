// Beam end releases (*ELEMENT_BEAM RT1 RR1 RT2 RR2) through the whole pipeline against beam
// theory, for the resultant (ELFORM 2) and the Hughes-Liu (ELFORM 1) beam:
//   - a beam clamped at both ends whose last element releases its end's rotation about the
//     bending axis deflects as a propped cantilever (clamped-pinned), 7 P L^3 / (768 E I) at
//     mid-span under a central load, against P L^3 / (192 E I) without the release;
//   - a cantilever whose tip element releases the tip's transverse translation passes no
//     shear: a load on the tip accelerates the tip node alone (P t^2 / (2 m)) and leaves the
//     rest of the beam at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "harness.hpp"

namespace {

using crumple::testing::Simulation;
using crumple::testing::termination;

// A 20 x 20 mm steel bar 1000 mm long (mm, ms, kg, kN, GPa), nu = 0.3, in kN elements.
constexpr double kE = 210.0, kNu = 0.3, kRho = 7.85e-6, kL = 1000.0, kH = 20.0;
constexpr double kArea = kH * kH, kI = kH * kH * kH * kH / 12.0;
constexpr int kN = 20;

// The section: ELFORM 1 (Hughes-Liu, 2 x 2 Gauss, SHRF 5/6) or ELFORM 2 (resultant, A ISS ITT
// J SA).
std::string section(int elform) {
  if (elform == 1)
    return fmt::format(
        "*SECTION_BEAM\n         1         1{:10.6g}         2         0\n"
        "{:10.4g}{:10.4g}{:10.4g}{:10.4g}\n",
        5.0 / 6.0, kH, kH, kH, kH);
  return fmt::format(
      "*SECTION_BEAM\n         1         2\n{:10.6g}{:10.6g}{:10.6g}{:10.6g}{:10.6g}\n", kArea, kI,
      kI, 2.0 * kI * 0.843, 5.0 / 6.0 * kArea);
}

// kN beams along x from node 1 to node kN + 1, orientation node on +y (s = y, t = z: z loads
// bend about s), the last element's end codes `last_codes` (RT1 RR1 RT2 RR2 as written);
// `extra` holds loads, constraints and the termination.
std::string barDeck(int elform, const std::string& last_codes, const std::string& extra) {
  std::string s = "*KEYWORD\n*TITLE\nbeam end releases\n" + extra;
  s += fmt::format("*MAT_ELASTIC\n         1{:10.4g}{:10.4g}{:10.4g}\n", kRho, kE, kNu);
  s += section(elform) + "*PART\nbar\n         1         1         1\n*NODE\n";
  for (int i = 0; i <= kN; ++i)
    s += fmt::format("{:8d}{:16.9g}{:16.9g}{:16.9g}\n", i + 1, kL * i / kN, 0.0, 0.0);
  s += fmt::format("{:8d}{:16.9g}{:16.9g}{:16.9g}\n", 1000, 0.0, 10.0, 0.0);
  s += "*ELEMENT_BEAM\n";
  for (int i = 0; i < kN; ++i)
    s += fmt::format("{:8d}{:8d}{:8d}{:8d}{:8d}{}\n", i + 1, 1, i + 1, i + 2, 1000,
                     i + 1 == kN ? last_codes : "");
  return s + "*END\n";
}

std::string clamp(int node) {
  return fmt::format(
      "{:10d}         0         1         1         1         1         1         1\n", node);
}

// First period of the clamped-pinned beam, f1 = (3.9266^2 / 2 pi) sqrt(E I / (rho A L^4)).
double proppedPeriod() {
  const double f1 =
      3.9266 * 3.9266 / (2.0 * M_PI) * std::sqrt(kE * kI / (kRho * kArea * std::pow(kL, 4)));
  return 1.0 / f1;
}

// The mid-span deflection under a central load P ramped over 4 periods and held for 2, the
// mean over the hold (the residual vibration averages out over whole periods).
double midSpanDeflection(int elform, const std::string& last_codes, double P) {
  const double T = proppedPeriod();
  const std::string extra =
      termination(6.0 * T) +
      fmt::format(
          "*DEFINE_CURVE\n         1\n{:20.6g}{:20.6g}\n{:20.6g}{:20.6g}\n{:20.6g}{:20.6g}\n", 0.0,
          0.0, 4.0 * T, 1.0, 1e6, 1.0) +
      fmt::format("*LOAD_NODE_POINT\n{:10d}         3         1{:10.4g}\n", kN / 2 + 1, P) +
      "*BOUNDARY_SPC_NODE\n" + clamp(1) + clamp(kN + 1) + clamp(1000);
  auto sim = Simulation::fromText(fmt::format("beam_release_{}", elform),
                                  barDeck(elform, last_codes, extra));
  double sum = 0.0, time = 0.0;
  sim->run([&](const crumple::solver::Solver& s) {
    if (s.time() <= 4.0 * T) return;
    sum += (sim->x(kN / 2 + 1, 2) - sim->x0(kN / 2 + 1, 2)) * s.dt();
    time += s.dt();
  });
  return sum / time;
}

// RR2 = 2: the last element lets its end's rotation about y (= s) pass; the clamp there then
// holds the beam like a pin. RT2 = 1 lets its axial translation pass too, so the deflection
// stretches no membrane force into the beam (clamped at both ends, the 1 kN of a deflection of
// L / 300 would stiffen it by 3 %); the clamped-clamped comparison takes a load small enough
// for that to stay under 0.1 %. Timoshenko's shear term (P L / (4 k G A) at most) is 0.1 %.
void proppedCantilever(int elform) {
  const double P = 0.1;
  const double released = midSpanDeflection(elform, "       0       0       1       2", P);
  const double clamped = midSpanDeflection(elform, "", P);
  const double pinned_theory = 7.0 * P * kL * kL * kL / (768.0 * kE * kI);
  const double clamped_theory = P * kL * kL * kL / (192.0 * kE * kI);
  EXPECT_NEAR(released / pinned_theory, 1.0, 0.01) << released << " " << pinned_theory;
  EXPECT_NEAR(clamped / clamped_theory, 1.0, 0.01) << clamped << " " << clamped_theory;
  std::printf(
      "[ figure ] ELFORM %d clamped-pinned mid-span %.5g mm (theory %.5g, ratio %.4f); "
      "clamped-clamped %.5g mm (theory %.5g, ratio %.4f)\n",
      elform, released, pinned_theory, released / pinned_theory, clamped, clamped_theory,
      clamped / clamped_theory);
}

TEST(VerificationBeamRelease, ResultantBeamWithAReleasedEndRotationIsPinned) {
  proppedCantilever(2);
}

TEST(VerificationBeamRelease, HughesLiuBeamWithAReleasedEndRotationIsPinned) {
  proppedCantilever(1);
}

// RT2 = 3: the tip element lets the tip's translation along z (= t) pass. A constant load P on
// the tip then moves the tip node alone: its velocity P t / m with m = rho A L_e / 2 (the
// central differences give that to the step's order), its travel P t^2 / (2 m); the beam
// behind it stays at rest but for the chord's turn, which adds an axial force of order
// (z / L_e)^2 (the slide is small, as beam_release.hpp assumes: 1e-4 of P here).
void slidingTip(int elform) {
  const double P = 0.001, m = kRho * kArea * (kL / kN) / 2.0, t_end = 1.0;
  const std::string extra =
      termination(t_end) +
      fmt::format("*DEFINE_CURVE\n         1\n{:20.6g}{:20.6g}\n{:20.6g}{:20.6g}\n", 0.0, 1.0, 1e6,
                  1.0) +
      fmt::format("*LOAD_NODE_POINT\n{:10d}         3         1{:10.4g}\n", kN + 1, P) +
      "*BOUNDARY_SPC_NODE\n" + clamp(1) + clamp(1000);
  auto sim = Simulation::fromText(fmt::format("beam_slide_{}", elform),
                                  barDeck(elform, "       0       0       3       0", extra));
  double t = 0.0;
  sim->run([&](const crumple::solver::Solver& s) { t = s.time(); });
  const double tip = sim->x(kN + 1, 2) - sim->x0(kN + 1, 2), speed = sim->v(kN + 1, 2);
  EXPECT_NEAR(speed / (P * t / m), 1.0, 0.02) << speed;
  EXPECT_NEAR(tip / (P * t * t / (2.0 * m)), 1.0, 0.03) << tip;
  const double behind = std::abs(sim->x(kN, 2) - sim->x0(kN, 2));
  EXPECT_LT(behind, 1e-4 * tip) << "the beam behind the slide moved " << behind;
  std::printf(
      "[ figure ] ELFORM %d sliding tip %.6g mm (P t^2 / 2m %.6g), speed %.6g (P t / m "
      "%.6g), node behind %.3g mm\n",
      elform, tip, P * t * t / (2.0 * m), speed, P * t / m, behind);
}

TEST(VerificationBeamRelease, ResultantBeamWithAReleasedTipSlidePassesNoShear) {
  slidingTip(2);
}

TEST(VerificationBeamRelease, HughesLiuBeamWithAReleasedTipSlidePassesNoShear) {
  slidingTip(1);
}

}  // namespace
