// *LOAD_BLAST_ENHANCED with *LOAD_BLAST_SEGMENT_SET through the whole pipeline: a free plate
// facing a 1 kg TNT surface burst 5 m away takes the momentum the applied pressure carries,
// and, over the positive phase, its area times the Kingery-Bulmash reflected impulse.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "constraints/blast.hpp"
#include "harness.hpp"

namespace {

using crumple::testing::Simulation;

constexpr double kLbPerKg = 2.20462262185, kFtPerM = 3.28083989501, kPaPerPsi = 6894.75729317;

// A 0.2 x 0.2 m steel plate, 50 mm thick, one Belytschko-Tsay shell in the x-z plane facing
// +y (its right-hand normal points at the charge, above it at (0, 5, 0)); NEGPHS 1 keeps the
// positive phase only. TSSFAC 0.1: 900 steps over the 3 ms pulse.
std::string plateDeck() {
  return "*KEYWORD\n*TITLE\nplate under a surface burst\n"
         "*CONTROL_TERMINATION\n     0.014\n*CONTROL_TIMESTEP\n       0.0       0.1\n"
         "*MAT_ELASTIC\n         1    7850.0    2.0E11       0.3\n"
         "*SECTION_SHELL\n         1         2       0.0         2\n"
         "      0.05      0.05      0.05      0.05\n"
         "*PART\nplate\n         1         1         1\n"
         "*NODE\n"
         "       1            -0.1             0.0            -0.1\n"
         "       2            -0.1             0.0             0.1\n"
         "       3             0.1             0.0             0.1\n"
         "       4             0.1             0.0            -0.1\n"
         "*ELEMENT_SHELL\n       1       1       1       2       3       4\n"
         "*LOAD_BLAST_ENHANCED\n         7       1.0       0.0       5.0       0.0       0.0"
         "         2         2\n       0.0       0.0       0.0       0.0         0       0.0"
         "         1\n"
         "*LOAD_BLAST_SEGMENT_SET\n         7         1\n"
         "*SET_SEGMENT\n         1\n         1         2         3         4\n*END\n";
}

TEST(VerificationBlast, PlateMomentumIsTheImpulseOfTheAppliedPressure) {
  auto sim = Simulation::fromText("blast_plate", plateDeck());
  const auto& charge = sim->model.blasts.at(0);
  const double area = 0.04;
  // The applied pressure at the plate's current centroid, integrated as the central-difference
  // update applies it: F(t_n) over the step from t_n.
  double integral = 0.0;
  sim->run([&](const crumple::solver::Solver& s) {
    const double t = s.time() - s.dt();
    double cy = 0.0;
    for (int64_t id = 1; id <= 4; ++id) cy += 0.25 * sim->x(id, 1);
    const auto pulse = crumple::constraints::blastPulse(charge, 5.0 - cy);
    integral += crumple::constraints::blastPressure(charge, pulse, t, 1.0) * area * s.dt();
  });
  const double momentum = sim->momentum(1);
  EXPECT_LT(momentum, 0.0);  // pushed away from the charge
  EXPECT_NEAR(-momentum / integral, 1.0, 1e-3) << momentum << " vs " << integral;
  // The positive phase's impulse: the fitted reflected impulse (cos theta = 1), in Pa s.
  const double w13 = std::cbrt(kLbPerKg);
  const auto k = crumple::constraints::hemisphericalBurst(5.0 * kFtPerM / w13);
  const double impulse = k.ir * w13 * kPaPerPsi * 1e-3 * area;
  EXPECT_NEAR(-momentum / impulse, 1.0, 0.01) << momentum << " vs " << impulse;
  std::printf("[ figure ] blast plate momentum %.5g N s, applied impulse %.5g, A i_r %.5g\n",
              -momentum, integral, impulse);
}

}  // namespace
