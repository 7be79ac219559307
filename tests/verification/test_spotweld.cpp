// Spot-weld beams (*SECTION_BEAM ELFORM 9 with *MAT_SPOTWELD) and the bolt preload of
// *INITIAL_AXIAL_FORCE_BEAM through the whole pipeline, against closed-form answers:
// the axial stiffness E A / L, the yield force SIGY A and the hardening slope of a pulled weld,
// failure at the effective plastic strain EFAIL, at the force resultants NRR and NRS and at
// TFAIL, the work done on the weld against its internal energy, and a bolt preloading two
// elastic blocks (the preload force, and their compression F L / (E A)).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include "elements/beam.hpp"
#include "harness.hpp"

namespace {

using crumple::testing::Simulation;
using crumple::testing::termination;

// mm, ms, kg, GPa (kN). A weld of diameter 6 mm and length 2 mm.
constexpr double kE = 210.0, kNu = 0.3, kRho = 7.85e-6, kSigy = 0.3, kEh = 1.0;
constexpr double kD = 6.0, kL = 2.0;
const double kA = M_PI * kD * kD / 4.0;
constexpr double kG = kE / (2.0 * (1.0 + kNu));
constexpr double kSpeed = 0.02;  // mm/ms, pulling speed of node 2

struct Weld {
  double efail = 0, nrr = 0, nrs = 0, tfail = 0;
  int dof = 1;  // the direction node 2 is pulled in: 1 axial (x), 2 transverse (y)
  double speed = kSpeed;
};

// One weld beam along x from node 1 (clamped) to node 2, which moves at kSpeed along `dof`
// with its other freedoms fixed (its rotations too, so that a transverse pull shears the
// weld without bending it at the integration point).
std::string weldDeck(const Weld& w, double end_time) {
  std::string s = "*KEYWORD\n*TITLE\nspot weld beam\n" + termination(end_time);
  s += fmt::format(
      "*MAT_SPOTWELD\n         1{:10.4g}{:10.4g}{:10.4g}{:10.4g}{:10.4g}{:10.4g}{:10.4g}\n", kRho,
      kE, kNu, kSigy, kEh, 0.0, w.tfail);
  s += fmt::format("{:10.4g}{:10.5g}{:10.5g}{:10.5g}\n", w.efail, w.nrr, w.nrs, w.nrs);
  s += fmt::format(
      "*SECTION_BEAM\n         1         9       1.0         2         1\n{:10.4g}{:10.4g}\n", kD,
      kD);
  s += "*PART\nweld\n         1         1         1\n*NODE\n";
  s += fmt::format("{:8d}{:16.9g}{:16.9g}{:16.9g}\n{:8d}{:16.9g}{:16.9g}{:16.9g}\n", 1, 0.0, 0.0,
                   0.0, 2, kL, 0.0, 0.0);
  s += "*ELEMENT_BEAM\n       1       1       1       2\n";
  const int fixed[6] = {w.dof == 1 ? 0 : 1, w.dof == 2 ? 0 : 1, 1, 1, 1, 1};
  s += "*BOUNDARY_SPC_NODE\n         1         0         1         1         1         1         "
       "1         1\n";
  s += fmt::format("         2         0{:10d}{:10d}{:10d}{:10d}{:10d}{:10d}\n", fixed[0], fixed[1],
                   fixed[2], fixed[3], fixed[4], fixed[5]);
  s += fmt::format(
      "*DEFINE_CURVE\n         1\n{:20.6g}{:20.6g}\n{:20.6g}{:20.6g}\n"
      "*BOUNDARY_PRESCRIBED_MOTION_NODE\n         2{:10d}         0         1{:10.4g}\n",
      0.0, 1.0, 1000.0, 1.0, w.dof, w.speed);
  return s + "*END\n";
}

// What a run of the weld records: the axial force N and transverse force at each cycle
// against the displacement of node 2, the work done on the weld, and when it failed.
struct WeldRun {
  double fail_time = -1.0, fail_disp = 0.0, work = 0.0, e_int_at_fail = 0.0, fail_dt = 0.0;
  double last_force = 0.0;  // the force conjugate to the pull just before failure
};

double pullForce(const crumple::domain::BeamBlock& b, int dof) {
  double r[6];
  crumple::elements::beamSectionResultants(b, 0, r);
  return dof == 1 ? r[0] : std::hypot(r[1], r[2]);
}

// The callback after a step sees x(n+1) and the forces the step computed at x(n): each force
// is paired with the displacement of the callback before.
WeldRun pull(Simulation& sim, int dof, const std::function<void(double, double)>& each = {}) {
  WeldRun out;
  double u_now = 0.0, u_prev = 0.0, f_prev = 0.0;
  sim.run([&](const crumple::solver::Solver& s) {
    const auto& b = sim.sd.beam_blocks[0];
    const double u_next = sim.x(2, dof - 1) - sim.x0(2, dof - 1);
    if (out.fail_time >= 0.0) return;
    if (!b.active[0]) {
      // The failing step still strained the weld (its resultants are kept for output).
      out.work += 0.5 * (pullForce(b, dof) + f_prev) * (u_now - u_prev);
      out.fail_time = s.time();
      out.fail_dt = s.dt();
      out.fail_disp = u_now;
      out.e_int_at_fail = b.e_int[0];
      return;
    }
    const double f = pullForce(b, dof);
    out.work += 0.5 * (f + f_prev) * (u_now - u_prev);
    out.last_force = f;
    if (each) each(u_now, f);
    u_prev = u_now;
    f_prev = f;
    u_now = u_next;
  });
  return out;
}

void figure(const char* what, double value) {
  std::printf("[ figure ] %s %s %.6g\n",
              ::testing::UnitTest::GetInstance()->current_test_info()->name(), what, value);
}

// Elastic N = E A u / L; after yield N = A (SIGY + EH eps_p), eps_p = u / L - N / (E A): the
// linear-hardening uniaxial answer (all points of the section yield together).
TEST(VerificationSpotweld, AxialStiffnessYieldAndHardening) {
  // Both nodes are driven: no dynamics, so a fast pull (5 % strain in 500 steps) is exact.
  const double speed = 10.0 * kSpeed;
  auto sim = Simulation::fromText("spotweld_axial", weldDeck({.speed = speed}, 0.05 * kL / speed));
  double worst_elastic = 0.0, worst_plastic = 0.0;
  const double u_yield = kSigy / kE * kL;
  pull(*sim, 1, [&](double u, double f) {
    if (u < 0.9 * u_yield && u > 0.1 * u_yield) {
      worst_elastic = std::max(worst_elastic, std::abs(f / (kE * kA * u / kL) - 1.0));
    } else if (u > 2.0 * u_yield) {
      // sigma (1 + EH / E) = SIGY + EH eps with eps the (small) engineering strain u / L.
      const double sigma = (kSigy + kEh * u / kL) / (1.0 + kEh / kE);
      worst_plastic = std::max(worst_plastic, std::abs(f / (sigma * kA) - 1.0));
    }
  });
  EXPECT_LT(worst_elastic, 1e-3);
  EXPECT_LT(worst_plastic, 5e-3);
  const auto& b = sim->sd.beam_blocks[0];
  EXPECT_TRUE(b.active[0]);
  figure("elastic stiffness error", worst_elastic);
  figure("plastic force error", worst_plastic);
}

// EFAIL: deleted when eps_p reaches EFAIL, u = L (EFAIL + sigma_f / E).
TEST(VerificationSpotweld, FailsAtPlasticStrain) {
  const double efail = 0.01;
  const double sigma_f = kSigy + kEh * efail;
  const double u_fail = kL * (efail + sigma_f / kE);
  auto sim =
      Simulation::fromText("spotweld_efail", weldDeck({.efail = efail}, 1.5 * u_fail / kSpeed));
  const WeldRun r = pull(*sim, 1);
  ASSERT_GT(r.fail_time, 0.0);
  const double step = r.fail_dt * kSpeed;
  EXPECT_NEAR(r.fail_disp, u_fail, 2.0 * step + 1e-3 * u_fail);
  figure("failure displacement ratio", r.fail_disp / u_fail);
}

// NRR: the axial force at failure; the weld is still elastic there, so the failure comes at
// u = NRR L / (E A). The work done on the weld up to then is its internal energy (energy
// balance across failure: that energy leaves with the element, eroded internal energy).
TEST(VerificationSpotweld, FailsAtAxialResultant) {
  const double nrr = 0.8 * kSigy * kA;
  const double u_fail = nrr * kL / (kE * kA);
  auto sim = Simulation::fromText("spotweld_nrr", weldDeck({.nrr = nrr}, 1.5 * u_fail / kSpeed));
  const WeldRun r = pull(*sim, 1);
  ASSERT_GT(r.fail_time, 0.0);
  const double step = r.fail_dt * kSpeed;
  EXPECT_NEAR(r.fail_disp, u_fail, 2.0 * step);
  EXPECT_LE(r.last_force, nrr);
  EXPECT_NEAR(r.last_force / nrr, 1.0, 0.01);
  EXPECT_NEAR(r.e_int_at_fail / r.work, 1.0, 1e-3);
  EXPECT_NEAR(r.e_int_at_fail, 0.5 * nrr * u_fail, 0.01 * 0.5 * nrr * u_fail);
  const auto eroded = sim->solver->eroded();
  EXPECT_EQ(eroded.elements, 1);
  EXPECT_DOUBLE_EQ(eroded.internal, r.e_int_at_fail);
  // The solver's balance (eroded energy kept in the internal energy) holds across failure.
  EXPECT_NEAR(sim->solver->energies().ratio, 1.0, 0.01);
  figure("failure force ratio", r.last_force / nrr);
  figure("work / internal energy", r.work / r.e_int_at_fail);
}

// NRS, NRT: a transverse pull shears the weld, Q = G A u / L (SHRF 1, rotations held), and
// it fails at Q = NRS; a compressive axial force does not count, nor does it here.
TEST(VerificationSpotweld, FailsAtShearResultant) {
  const double nrs = 0.3 * kA * kSigy / std::sqrt(3.0);
  const double u_fail = nrs * kL / (kG * kA);
  auto sim =
      Simulation::fromText("spotweld_nrs", weldDeck({.nrs = nrs, .dof = 2}, 1.5 * u_fail / kSpeed));
  const WeldRun r = pull(*sim, 2);
  ASSERT_GT(r.fail_time, 0.0);
  EXPECT_NEAR(r.fail_disp / u_fail, 1.0, 0.01);
  EXPECT_NEAR(r.last_force / nrs, 1.0, 0.01);
  figure("shear failure displacement ratio", r.fail_disp / u_fail);
}

TEST(VerificationSpotweld, FailsAtTime) {
  const double tfail = 0.01;
  auto sim = Simulation::fromText("spotweld_tfail", weldDeck({.tfail = tfail}, 2.0 * tfail));
  const WeldRun r = pull(*sim, 1);
  ASSERT_GT(r.fail_time, 0.0);
  // Deleted by the first force pass at t(n) >= TFAIL; the callback sees t(n+1).
  EXPECT_GE(r.fail_time, tfail);
  EXPECT_LE(r.fail_time, tfail + 2.0 * r.fail_dt);
}

// A bolt (a spot-weld beam of diameter 10 mm) along the axis of an elastic column of two
// 20 mm blocks (nu = 0), its ends in the column's end faces, which move as nodal rigid bodies.
// The preload ramps to F over 0.5 ms (about 65 wave transits: quasi-static) and the curve ends
// there; over the following hold the bolt keeps F and the column is shortened by
// F L / (E A), uniaxial stress.
constexpr double kBoltForce = 10.0;  // kN
constexpr double kColumn = 40.0, kWidth = 20.0, kRamp = 0.5, kHold = 0.2;

std::string boltDeck() {
  auto face = [](int k) { return [k](int, int, int kk) { return kk == k; }; };
  std::string extra = termination(kRamp + kHold);
  extra += fmt::format("*MAT_ELASTIC\n         1{:10.4g}{:10.4g}       0.0\n", kRho, kE);
  extra += fmt::format("*MAT_SPOTWELD\n         2{:10.4g}{:10.4g}{:10.4g}{:10.4g}\n", kRho, kE, kNu,
                       1.0);
  extra +=
      "*SECTION_BEAM\n         2         9       1.0         2         1\n      10.0      10.0\n";
  extra += "*PART\nbolt\n         2         2         2\n";
  // Column nodes 1 + i + 3 j + 9 k: the axis is i = j = 1, node 5 at the bottom, 41 on top.
  extra += "*ELEMENT_BEAM\n     100       2       5      41\n";
  extra += crumple::testing::brickNodeSet(1, 2, 2, 4, face(0)) +
           crumple::testing::brickNodeSet(2, 2, 2, 4, face(4));
  extra += "*CONSTRAINED_NODAL_RIGID_BODY\n        11         0         1\n";
  extra += "*CONSTRAINED_NODAL_RIGID_BODY\n        12         0         2\n";
  extra += fmt::format("*DEFINE_CURVE\n         7\n{:20.6g}{:20.6g}\n{:20.6g}{:20.6g}\n", 0.0, 0.0,
                       kRamp, 1.0);
  extra += fmt::format(
      "*SET_BEAM\n         3\n       100\n*INITIAL_AXIAL_FORCE_BEAM\n"
      "         3         7{:10.4g}         0\n",
      kBoltForce);
  return crumple::testing::brickDeck(2, 2, 4, kWidth, kWidth, kColumn, extra);
}

TEST(VerificationSpotweld, BoltPreloadCompressesTheBlocks) {
  Simulation sim(Simulation::writeDeck("spotweld_bolt", boltDeck()));
  double force = 0.0, shortening = 0.0, time = 0.0, ramp_error = 0.0;
  sim.run([&](const crumple::solver::Solver& s) {
    const auto& b = sim.sd.beam_blocks[0];
    const double t_force = s.time() - s.dt();  // the pass's time t(n)
    if (t_force < kRamp) {
      ramp_error = std::max(ramp_error, std::abs(b.resultant[0][0] - kBoltForce * t_force / kRamp));
      return;
    }
    force += b.resultant[0][0] * s.dt();
    shortening += ((sim.x0(41, 2) - sim.x0(5, 2)) - (sim.x(41, 2) - sim.x(5, 2))) * s.dt();
    time += s.dt();
  });
  force /= time;
  shortening /= time;
  const double expected = kBoltForce * kColumn / (kE * kWidth * kWidth);
  EXPECT_LT(ramp_error, 1e-9 * kBoltForce);
  EXPECT_NEAR(force / kBoltForce, 1.0, 0.01);
  EXPECT_NEAR(shortening / expected, 1.0, 0.02);
  EXPECT_NEAR(sim.solver->energies().ratio, 1.0, 0.01);
  figure("bolt force ratio", force / kBoltForce);
  figure("column shortening ratio", shortening / expected);
}

}  // namespace
