#include "output/energy_audit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace crumple::output {

namespace {

struct Term {
  const char* name;
  double change;
};

// The change of each term of the balance between two samples. The external work enters the
// reference (initial energy + external work), so an energy source shows as a change of
// (total - external work) that no term's work explains.
std::vector<Term> changes(const solver::Energies& a, const solver::Energies& b) {
  return {{"kinetic", b.kinetic - a.kinetic},
          {"internal", b.internal - a.internal},
          {"hourglass", b.hourglass - a.hourglass},
          {"drilling", b.drilling - a.drilling},
          {"contact", b.contact - a.contact},
          {"stonewall", b.rigidwall - a.rigidwall},
          {"damping", b.damping - a.damping},
          {"external work", b.external_work - a.external_work}};
}

// The contact interface whose energy changed most (id 0 if there is none).
std::pair<int64_t, double> largestContactChange(const EnergySample& a, const EnergySample& b) {
  std::pair<int64_t, double> out{0, 0.0};
  if (a.contact_energy.size() != b.contact_energy.size()) return out;
  for (std::size_t i = 0; i < b.contact_energy.size(); ++i) {
    const double d = b.contact_energy[i] - a.contact_energy[i];
    if (std::abs(d) > std::abs(out.second)) out = {b.contact_id[i], d};
  }
  return out;
}

}  // namespace

std::string EnergyAudit::observe(const EnergySample& sample) {
  const double ratio = sample.energies.ratio;
  ++summary_.samples;
  summary_.min_ratio = std::min(summary_.min_ratio, ratio);
  summary_.max_ratio = std::max(summary_.max_ratio, ratio);
  std::string text;
  if (!(ratio >= kLow && ratio <= kHigh)) {
    if (summary_.samples_outside == 0) summary_.first_outside_time = sample.time;
    ++summary_.samples_outside;
    if (printed_ < kMaxPrinted) {
      text = audit(sample);
      if (++printed_ == kMaxPrinted)
        text += fmt::format(
            "energy audit: {} audits printed; later samples outside [{}, {}] are "
            "counted in summary.json (energy_audit), not listed\n",
            kMaxPrinted, kLow, kHigh);
    }
  }
  previous_ = sample;
  has_previous_ = true;
  return text;
}

std::string EnergyAudit::audit(const EnergySample& now) const {
  const solver::Energies& e = now.energies;
  std::string out =
      fmt::format("energy audit: ratio {:.4f} at time {:.6g} (cycle {}) is outside [{}, {}]",
                  e.ratio, now.time, now.cycle, kLow, kHigh);
  // The first sample (time 0) holds ratio 1 by definition: there is nothing to compare with.
  if (!has_previous_) return out + "\n";
  const solver::Energies& before = previous_.energies;
  out += fmt::format("; since time {:.6g}:", previous_.time);
  const auto terms = changes(before, e);
  // The stored term that moved most: the external work is the reference the others are held
  // against, so it is listed but not named.
  const Term* largest = &terms.front();
  for (const Term& t : terms) {
    out += fmt::format(" {} {:+.4g},", t.name, t.change);
    if (&t != &terms.back() && std::abs(t.change) > std::abs(largest->change)) largest = &t;
  }
  // The imbalance added since the last sample: what the terms gained beyond the work done.
  const double drift = (e.total - e.external_work) - (before.total - before.external_work);
  out += fmt::format(" balance {:+.4g}; largest change of a stored term: {}", drift, largest->name);
  if (std::string_view(largest->name) == "contact") {
    const auto [id, d] = largestContactChange(previous_, now);
    if (id != 0) out += fmt::format(" (interface {} {:+.4g})", id, d);
  }
  return out + "\n";
}

std::string EnergyAudit::verdict() const {
  if (summary_.samples_outside == 0)
    return fmt::format("energy ratio stayed in [{}, {}] (range {:.4f} to {:.4f} over {} samples)\n",
                       kLow, kHigh, summary_.min_ratio, summary_.max_ratio, summary_.samples);
  return fmt::format(
      "warning: energy ratio left [{}, {}]: {} of {} samples outside, first at time {:.6g}, range "
      "{:.4f} to {:.4f} (the energy audit lines above say which term moved)\n",
      kLow, kHigh, summary_.samples_outside, summary_.samples, summary_.first_outside_time,
      summary_.min_ratio, summary_.max_ratio);
}

void EnergyAudit::save(util::ArchiveWriter& w) const {
  visitState(*this, [&](const auto& v) { w.put(v); });
}

void EnergyAudit::load(util::ArchiveReader& r) {
  visitState(*this, [&](auto& v) { r.get(v); });
}

}  // namespace crumple::output
