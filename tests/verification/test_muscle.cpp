// *MAT_MUSCLE (*MAT_156) on a truss through the whole pipeline, against the Hill model the
// Keyword Manual gives (materials/laws/muscle.hpp): sigma = PIS a(t) f_l(lambda) f_v(eps_dot /
// (SRM f_r)) + PIS f_p(lambda) + DMP eps_dot, force sigma A.
//   - isometric: at the optimal length with full activation the force is PIS A; at other
//     stretches (set by SNO) it follows the length curve SVS; an activation curve scales it;
//   - passive: the exponential parallel element (SSP = 0) and a passive curve (SSP < 0), with
//     no activation;
//   - force-velocity: at a constant lengthening or shortening speed the force is the SVR
//     curve's at the normalised strain rate (with SFR and DMP), and the work done on the
//     muscle equals its internal energy plus the kinetic energy (energy balance);
//   - mass RO / SNO A L0, the element restricted to trusses, bad input named by its field;
//   - the corpus deck (../shared/decks/muscle_mat156_eccentric) reads and runs its first
//     20000 cycles held at its initial length (no jump), its force the hand calculation of
//     the same model and its internal energy the work of that force.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "harness.hpp"
#include "util/curve.hpp"
#include "util/error.hpp"

namespace {

using crumple::testing::Simulation;
using crumple::testing::termination;

// SI units. A muscle of 0.1 m initial length and 1e-4 m^2 area, PIS 2e5 Pa (20 N at A).
constexpr double kL0 = 0.1, kA = 1e-4, kPis = 2e5, kRho = 1060.0, kSrm = 2.0;

// The length curve (SVS, curve 10): a trapezoid with a plateau of 1 on [0.9, 1.1], 0 at 0.5
// and 1.5; the velocity curve (SVR, curve 11): Hill-like, 0 at -1, 1 at 0, 1.5 at 1.
const std::vector<double> kSvsX = {0.5, 0.9, 1.1, 1.5}, kSvsY = {0.0, 1.0, 1.0, 0.0};
const std::vector<double> kSvrX = {-1.0, -0.5, 0.0, 0.5, 1.0}, kSvrY = {0.0, 0.2, 1.0, 1.4, 1.5};
// A passive curve (curve 12) and a ramped activation (curve 13: 0 to 1 over 1 s).
const std::vector<double> kSspX = {1.0, 1.2, 1.4}, kSspY = {0.0, 0.1, 0.5};
const std::vector<double> kAlmX = {0.0, 1.0, 10.0}, kAlmY = {0.0, 1.0, 1.0};

double curveAt(const std::vector<double>& x, const std::vector<double>& y, double t) {
  double v = 0.0, s = 0.0;
  crumple::util::valueAndSlope(std::span<const double>(x), std::span<const double>(y), t, v, s);
  return v;
}

std::string curve(int id, const std::vector<double>& x, const std::vector<double>& y) {
  std::string s = fmt::format("*DEFINE_CURVE\n{:10d}\n", id);
  for (std::size_t i = 0; i < x.size(); ++i) s += fmt::format("{:20.10g}{:20.10g}\n", x[i], y[i]);
  return s;
}

struct Muscle {
  double sno = 1.0, ssm = 0.0, cer = 0.0, dmp = 0.0;
  double alm = 1.0, sfr = 0.0, svs = -10, svr = -11, ssp = 1.0;
  double speed = 0.0;  // velocity of node 2 along x (lengthening > 0), ramped over t_ramp
  double t_ramp = 0.01;
  int elform = 3;
  bool free_end = false;  // node 2 loose along x (no motion prescribed)
};

// One truss along x from node 1 (fixed) to node 2 (driven along x, held otherwise).
std::string muscleDeck(const Muscle& m, double end_time) {
  std::string s = "*KEYWORD\n*TITLE\nmuscle truss\n" + termination(end_time);
  s += fmt::format(
      "*MAT_MUSCLE\n         1{:10.4g}{:10.6g}{:10.4g}{:10.4g}{:10.4g}{:10.4g}{:10.4g}\n", kRho,
      m.sno, kSrm, kPis, m.ssm, m.cer, m.dmp);
  s += fmt::format("{:10.4g}{:10.4g}{:10.4g}{:10.4g}{:10.4g}\n", m.alm, m.sfr, m.svs, m.svr, m.ssp);
  s += curve(10, kSvsX, kSvsY) + curve(11, kSvrX, kSvrY) + curve(12, kSspX, kSspY) +
       curve(13, kAlmX, kAlmY) + curve(14, {0.0, 2.0}, {2.0, 2.0});
  s += fmt::format("*SECTION_BEAM\n         1{:10d}\n{:10.4g}{:10.4g}\n", m.elform, kA, kA);
  s += "*PART\nmuscle\n         1         1         1\n*NODE\n";
  s += fmt::format("{:8d}{:16.9g}{:16.9g}{:16.9g}\n{:8d}{:16.9g}{:16.9g}{:16.9g}\n", 1, 0.0, 0.0,
                   0.0, 2, kL0, 0.0, 0.0);
  s += "*ELEMENT_BEAM\n       1       1       1       2\n";
  // Node 2 held along x too when it does not move (a prescribed velocity with SF 0 would
  // take LS-DYNA's default SF 1).
  s += fmt::format(
      "*BOUNDARY_SPC_NODE\n{:10d}{:10d}{:10d}{:10d}{:10d}{:10d}{:10d}{:10d}\n"
      "{:10d}{:10d}{:10d}{:10d}{:10d}{:10d}{:10d}{:10d}\n",
      1, 0, 1, 1, 1, 1, 1, 1, 2, 0, m.speed == 0.0 && !m.free_end ? 1 : 0, 1, 1, 1, 1, 1);
  if (m.speed != 0.0) {
    s += curve(1, {0.0, m.t_ramp, 1e3}, {0.0, 1.0, 1.0});
    s += fmt::format(
        "*BOUNDARY_PRESCRIBED_MOTION_NODE\n         2         1         0         1{:10.4g}\n",
        m.speed);
  }
  return s + "*END\n";
}

// The truss's axial force (its resultant).
double force(const Simulation& sim) {
  return sim.sd.beam_blocks.at(0).resultant.at(0)[0];
}

void figure(const char* what, double value) {
  std::printf("[ figure ] %s %s %.6g\n",
              ::testing::UnitTest::GetInstance()->current_test_info()->name(), what, value);
}

// Held at the stretch SNO (node 2 still) with ALM = 1: F = PIS A f_l(SNO). The stretches and
// the length curve's values there, beside the test.
TEST(VerificationMuscle, IsometricForceFollowsTheLengthCurve) {
  struct Case {
    double sno, f_l;
  };
  const Case cases[] = {{1.0, 1.0}, {1.1, 1.0}, {0.7, 0.5}, {1.3, 0.5}, {1.45, 0.125}};
  for (const Case& c : cases) {
    auto sim = Simulation::fromText("muscle_iso", muscleDeck({.sno = c.sno}, 0.02));
    sim->run();
    EXPECT_NEAR(force(*sim), kPis * kA * c.f_l, 1e-9 * kPis * kA) << "SNO " << c.sno;
    EXPECT_NEAR(c.f_l, curveAt(kSvsX, kSvsY, c.sno), 1e-12);
  }
}

// ALM < 0: the activation curve of time; isometric at the optimal length, F = PIS A a(t).
TEST(VerificationMuscle, ActivationCurveScalesTheActiveForce) {
  auto sim = Simulation::fromText("muscle_alm", muscleDeck({.alm = -13}, 1.5));
  double worst = 0.0;
  sim->run([&](const crumple::solver::Solver& s) {
    // The force of this step was computed at t(n), a step before the time the callback sees:
    // within the activation's change over two steps of that.
    const double t = s.time();
    const double err = std::abs(force(*sim) / (kPis * kA) - curveAt(kAlmX, kAlmY, t));
    worst = std::max(worst, err / (2.0 * s.dt()));
  });
  EXPECT_LT(worst, 1.0);  // the curve's slope is 1 / s
  EXPECT_NEAR(force(*sim), kPis * kA, 1e-9 * kPis * kA);
}

// No activation, SSP = 0: F = PIS A (exp(CER (lambda - 1) / SSM) - 1) / (exp(CER) - 1) above
// lambda = 1, nothing below; SSP < 0: PIS A times the curve.
TEST(VerificationMuscle, PassiveElementExponentialAndCurve) {
  const double cer = 5.0, ssm = 0.5;
  for (double sno : {0.9, 1.2, 1.3, 1.5}) {
    auto sim = Simulation::fromText(
        "muscle_pe",
        muscleDeck({.sno = sno, .ssm = ssm, .cer = cer, .alm = 0.0, .ssp = 0.0}, 0.02));
    sim->run();
    const double fp = sno > 1.0 ? std::expm1(cer * (sno - 1.0) / ssm) / std::expm1(cer) : 0.0;
    EXPECT_NEAR(force(*sim), kPis * kA * fp, 1e-9 * kPis * kA) << "SNO " << sno;
    // At the strain SSM the parallel element carries PIS.
    if (sno == 1.5) {
      EXPECT_NEAR(force(*sim), kPis * kA, 1e-9 * kPis * kA);
    }
  }
  for (double sno : {1.1, 1.3}) {
    auto sim =
        Simulation::fromText("muscle_pc", muscleDeck({.sno = sno, .alm = 0.0, .ssp = -12}, 0.02));
    sim->run();
    EXPECT_NEAR(force(*sim), kPis * kA * curveAt(kSspX, kSspY, sno), 1e-9 * kPis * kA);
  }
}

// A constant speed v (after a short ramp) on the plateau of the length curve: F = PIS A
// f_v(v / (L0 SRM f_r)) + DMP v / L0 A. Checked over the steady part of the run, and the
// work done on the muscle (the prescribed node's reaction) against the internal plus kinetic
// energy.
TEST(VerificationMuscle, ForceVelocityAndEnergyBalance) {
  struct Case {
    double speed, sfr, dmp;
  };
  const double v_ref = kL0 * kSrm;  // the speed of normalised strain rate 1
  const Case cases[] = {{0.25 * v_ref, 0.0, 0.0},
                        {-0.25 * v_ref, 0.0, 0.0},
                        {-0.75 * v_ref, 0.0, 0.0},
                        {0.25 * v_ref, -14, 0.0},
                        {0.6 * v_ref, 0.0, 50.0}};
  for (const Case& c : cases) {
    // Travel 0.08 L0 from SNO 0.96 or 1.04, within the plateau [0.9, 1.1].
    const double sno = c.speed > 0 ? 0.96 : 1.04, end = 0.08 * kL0 / std::abs(c.speed);
    auto sim = Simulation::fromText(
        "muscle_fv",
        muscleDeck({.sno = sno, .dmp = c.dmp, .sfr = c.sfr, .speed = c.speed, .t_ramp = 0.05 * end},
                   end));
    const double l_orig = kL0 / sno;
    const double rate = c.speed / l_orig, rate_max = kSrm * (c.sfr < 0 ? 2.0 : 1.0);
    const double want = kA * (kPis * curveAt(kSvrX, kSvrY, rate / rate_max) + c.dmp * rate);
    double worst = 0.0;
    sim->run([&](const crumple::solver::Solver& s) {
      if (s.time() > 0.1 * end) worst = std::max(worst, std::abs(force(*sim) / want - 1.0));
    });
    EXPECT_LT(worst, 1e-9) << "speed " << c.speed << " SFR " << c.sfr << " DMP " << c.dmp;
    const auto e = sim->solver->energies();
    EXPECT_NEAR(e.external_work, e.internal + e.kinetic, 1e-3 * std::abs(e.external_work));
    // The work is about F times the travel (the ramp is slower and shorter).
    EXPECT_NEAR(e.internal, want * 0.08 * kL0 * (c.speed > 0 ? 1.0 : -1.0),
                0.06 * std::abs(want) * 0.08 * kL0);
    figure("force / Hill", force(*sim) / want);
  }
}

// The nodal masses take RO / SNO (Keyword Manual): the element's mass is RO A l_orig.
TEST(VerificationMuscle, MassIsDensityOverSno) {
  auto sim = Simulation::fromText("muscle_mass", muscleDeck({.sno = 1.25}, 1e-3));
  double mass = 0.0;
  for (std::size_t n = 0; n < sim->sd.numNodes(); ++n) mass += sim->sd.mass[n];
  EXPECT_NEAR(mass, kRho / 1.25 * kA * kL0, 1e-12 * kRho * kA * kL0);
}

// A free muscle (node 2 loose along x, SNO 1.2: pulled by its passive and active elements
// towards its optimal length) stays stable on the step of its tangents and conserves energy.
TEST(VerificationMuscle, FreeMuscleIsStableAndConservesEnergy) {
  auto sim = Simulation::fromText(
      "muscle_free",
      muscleDeck({.sno = 1.2, .ssm = 0.3, .cer = 3.0, .dmp = 20.0, .ssp = 0.0, .free_end = true},
                 0.05));
  sim->run();
  const auto e = sim->solver->energies();
  EXPECT_TRUE(std::isfinite(sim->x(2, 0)));
  EXPECT_NEAR(e.internal + e.kinetic, 0.0, 1e-3 * kPis * kA * 0.2 * kL0);
  EXPECT_LT(sim->x(2, 0), kL0);  // it has shortened
}

TEST(VerificationMuscle, RefusedOnBeamsAndBadInputNamed) {
  const auto message = [](const std::string& text) {
    try {
      Simulation sim(Simulation::writeDeck("muscle_bad", text));
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message(muscleDeck({.elform = 1}, 1.0)).find("runs only on trusses"),
            std::string::npos);
  const std::string sno0 = message(muscleDeck({.sno = 0.0}, 1.0));
  EXPECT_NE(sno0.find("SNO"), std::string::npos) << sno0;
  EXPECT_NE(sno0.find(".k:"), std::string::npos) << sno0;
  const std::string cer = message(muscleDeck({.alm = 0.0, .ssp = 0.0}, 1.0));
  EXPECT_NE(cer.find("SSM"), std::string::npos) << cer;
}

// The corpus deck (never copied into the project): a cat soleus (*MAT_156 on one truss,
// ELFORM 3, A = 1) fully activated from 0.95 s, stretched at 27 mm/s by 6 mm from 2.50 s to
// 2.72 s, held, relaxed at 7.72 s, ending at 12.72 s. Its *PARAMETER values, beside the
// test: the optimal length (l_orig, SNO = path length / lceOptAT), PIS = fceOptAT and
// SRM = vceMax, and the times of the ramp and of the stimulation.
TEST(VerificationMuscle, CatSoleusEccentricCorpusDeckRunsAndHoldsItsLength) {
  const std::filesystem::path deck =
      std::filesystem::path(CRUMPLE_SHARED_DIR) /
      "decks/muscle_mat156_eccentric/MPP_R931/mat156/eccentric/ramp_27mmps_6mm/"
      "ramp_27mmps_6mm.k";
  if (!std::filesystem::exists(deck)) GTEST_SKIP() << deck << " is absent";
  constexpr double kLopt = 0.0425377, kFopt = 21.598751, kVmax = 4.5;
  const double stim_on = 0.95;
  Simulation sim(deck);
  const auto curveOf = [&](int64_t id) -> const crumple::model::Curve& {
    return sim.model.curves.at(static_cast<std::size_t>(sim.model.curveIndex(id)));
  };
  const auto& fl = curveOf(10);
  const auto& fp = curveOf(11);
  const auto& fv = curveOf(12);
  // The Hill model by hand at the muscle's length l, lengthening speed v and activation a.
  const auto hill = [&](double l, double v, double a) {
    const double lambda = l / kLopt, x = v / kLopt / kVmax;
    return kFopt * (a * fl.valueExtrapolated(lambda) * fv.valueExtrapolated(x) +
                    fp.valueExtrapolated(lambda));
  };
  const auto length = [&] {
    double d2 = 0.0;
    for (int c = 0; c < 3; ++c) d2 += std::pow(sim.x(2, c) - sim.x(1, c), 2);
    return std::sqrt(d2);
  };
  // The whole run is 12.7 s of about 8e5 cycles of a few microseconds each, too long for the
  // suite (its figures: docs/theory.md, "Muscles"): here its first 20000 cycles, in which the
  // muscle is held at its initial length, unstimulated.
  double worst = 0.0, work = 0.0, l_prev = length(), f_prev = 0.0;
  for (int cycle = 0; cycle < 20000 && !sim.solver->finished(); ++cycle) {
    sim.solver->step();
    const double l = length(), f = force(sim);
    // The force of x(n) against the model at x(n+1): the same while the muscle is held.
    worst = std::max(worst, std::abs(f - hill(l, 0.0, 0.0)));
    work += 0.5 * (f + f_prev) * (l - l_prev);
    l_prev = l;
    f_prev = f;
  }
  EXPECT_LT(sim.solver->time(), stim_on);
  EXPECT_LT(worst, 1e-12 * kFopt);
  EXPECT_NEAR(length(), 0.0425377 * 0.95 + 0.003, 1e-12);  // pathLenS: no jump at the start
  EXPECT_NEAR(sim.solver->energies().internal, work, 1e-12);
  figure("passive force N", force(sim));
  figure("time reached s", sim.solver->time());
}

}  // namespace
