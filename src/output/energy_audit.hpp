// The energy audit: at every glstat sample the energy ratio is held against the band an
// analyst trusts, [0.98, 1.02]; outside it, run.log gets the change of every term since the
// last sample, so that the term that moved (a one-cycle contact jump, hourglassing, wall work)
// is named where it happened instead of being found afterwards in glstat. The terms are those
// of the ratio (docs/theory.md, "Energy balance"): kinetic, internal, hourglass, contact
// (per interface), stonewall, and the external work in the reference.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "solver/solver.hpp"
#include "util/archive.hpp"

namespace crumple::output {

// One glstat sample as the audit sees it: the global terms and each contact interface's
// energy (stored penalty energy plus what its damping and friction dissipated).
struct EnergySample {
  double time = 0.0;
  int64_t cycle = 0;
  solver::Energies energies;
  std::vector<int64_t> contact_id;
  std::vector<double> contact_energy;
};

class EnergyAudit {
 public:
  static constexpr double kLow = 0.98, kHigh = 1.02;
  // Audits printed in full; later samples outside the band are counted, not printed.
  static constexpr int64_t kMaxPrinted = 20;

  struct Summary {
    double min_ratio = 1.0, max_ratio = 1.0;
    int64_t samples = 0, samples_outside = 0;
    double first_outside_time = -1.0;  // < 0: never outside
  };

  // Takes the next sample; returns the audit text for run.log when its ratio is outside the
  // band (and the audits printed are fewer than kMaxPrinted), else an empty string.
  std::string observe(const EnergySample& sample);
  const Summary& summary() const { return summary_; }
  // The closing line for run.log: whether the run stayed in the band.
  std::string verdict() const;

  void save(util::ArchiveWriter& w) const;
  void load(util::ArchiveReader& r);

 private:
  std::string audit(const EnergySample& now) const;
  // The restart state in dump order, for save and load alike.
  template <class Self, class F>
  static void visitState(Self& self, F&& f) {
    f(self.summary_);
    f(self.has_previous_);
    f(self.previous_.time);
    f(self.previous_.cycle);
    f(self.previous_.energies);
    f(self.previous_.contact_id);
    f(self.previous_.contact_energy);
    f(self.printed_);
  }
  Summary summary_;
  bool has_previous_ = false;
  EnergySample previous_;
  int64_t printed_ = 0;
};

}  // namespace crumple::output
