// Explicit dynamic relaxation (LS-DYNA Keyword Manual vol. I, *CONTROL_DYNAMIC_RELAXATION and
// *DEFINE_CURVE SIDR; Theory Manual, "Dynamic Relaxation"; docs/theory.md): the cycle of
// solver.cpp run as a damped pseudo-dynamic iteration towards static equilibrium under the
// relaxation phase's loads, then the transient analysis from its end.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "solver/solver.hpp"

namespace crumple::solver {

namespace {

// 2^32 units of the largest magnitude: each value is rounded to a multiple of max / 2^32 and
// the integers are added (exactly, in any order, over threads and ranks), so the sum has the
// same bits at any rank count; its error is below n max 2^-33 for n values.
constexpr double kUnits = 4294967296.0;

// The exact-order-free sums of each column of `values` (rows of `width` numbers) over every
// rank.
std::vector<double> exactSums(const std::vector<double>& values, std::size_t width,
                              const comm::Communicator& comm) {
  std::vector<double> sums(width, 0.0);
  for (std::size_t k = 0; k < width; ++k) {
    double largest = 0.0;
    for (std::size_t i = k; i < values.size(); i += width)
      largest = std::max(largest, std::fabs(values[i]));
    largest = -comm.minAll(-largest);
    if (!(largest > 0.0)) continue;
    const double unit = largest / kUnits;
    long long units = 0;
    for (std::size_t i = k; i < values.size(); i += width) units += std::llround(values[i] / unit);
    sums[k] = double(comm.sumAll(units)) * unit;
  }
  return sums;
}

}  // namespace

double Solver::distortionalKineticEnergy() const {
  // Rows of m, m vx, m vy, m vz, 1/2 m v.v + 1/2 I w.w over the deformable owned nodes.
  constexpr std::size_t kWidth = 5;
  std::vector<double> rows;
  rows.reserve(kWidth * sd_.numNodes());
  for (std::size_t n = 0; n < sd_.numNodes(); ++n) {
    if (!sd_.node_owned[n] || (rigid_ && rigid_->countsNode(n))) continue;
    const double m = sd_.mass[n];
    const double* v = &sd_.v[3 * n];
    double ke = 0.5 * m * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (sd_.rotations) {
      const double* w = &sd_.w[3 * n];
      ke += 0.5 * sd_.inertia[n] * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    }
    rows.insert(rows.end(), {m, m * v[0], m * v[1], m * v[2], ke});
  }
  const std::vector<double> s = exactSums(rows, kWidth, comm_);
  const double translation =
      s[0] > 0.0 ? 0.5 * (s[1] * s[1] + s[2] * s[2] + s[3] * s[3]) / s[0] : 0.0;
  return std::max(0.0, s[4] - translation);
}

void Solver::scaleVelocities(double factor) {
  const std::size_t n = sd_.v.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) sd_.v[i] *= factor;
  if (sd_.rotations)
    for (double& w : sd_.w) w *= factor;
  if (rigid_) rigid_->scaleVelocities(factor);
}

Solver::Relaxation Solver::relax() {
  const auto& dr = model_.controls.relaxation;
  Relaxation r;
  boundary_.setPhase(model::Phase::Relaxation);
  if (rigid_) rigid_->setPhase(model::Phase::Relaxation);
  // The relaxation starts at rest: the deck's initial velocities are those of the transient.
  scaleVelocities(0.0);
  dr_tssf_ = dr.tssfdr > 0.0 ? dr.tssfdr : model_.controls.tssfac;
  end_time_ = dr.drterm > 0.0 ? dr.drterm : 1e300;
  while (true) {
    step();
    scaleVelocities(dr.drfctr);
    const double ke = distortionalKineticEnergy();
    r.peak = std::max(r.peak, ke);
    if (cycle_ % dr.nrcyck == 0) {
      r.ratio = r.peak > 0.0 ? ke / r.peak : 0.0;
      // Nothing moved at all: the phase's loads are in equilibrium (or absent).
      if (r.ratio < dr.drtol) {
        r.converged = true;
        break;
      }
    }
    if (dr.drterm > 0.0 && time_ >= dr.drterm * (1.0 - 1e-12)) {
      r.ratio = r.peak > 0.0 ? ke / r.peak : 0.0;
      break;
    }
  }
  r.cycles = cycle_;
  r.time = time_;
  const Energies e = energies();
  r.energy = e.internal + e.hourglass + e.drilling;
  startTransient();
  return r;
}

void Solver::startTransient() {
  dr_tssf_ = 0.0;
  end_time_ = model_.controls.end_time;
  boundary_.setPhase(model::Phase::Transient);
  time_ = 0.0;
  cycle_ = 0;
  dt_ = 0.0;
  v_old_.clear();
  w_old_.clear();
  std::fill(sd_.v.begin(), sd_.v.end(), 0.0);
  std::fill(sd_.w.begin(), sd_.w.end(), 0.0);
  setInitialVelocities();
  if (rigid_) {
    rigid_->setPhase(model::Phase::Transient);
    rigid_->restoreInitialVelocities();
    rigid_->setInitialVelocities(sd_);
  }
  // The relaxation's work (its loads, the damping that took the kinetic energy out) stays out
  // of the transient's balance: that starts from the relaxed state's total energy.
  external_work_ = work_ahead_ = damping_work_ = damping_ahead_ = rigidwall_energy_ =
      rigidwall_ahead_ = 0.0;
  initial_energy_ = 0.0;
  initial_energy_ = energies().total;
}

}  // namespace crumple::solver
