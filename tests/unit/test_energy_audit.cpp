// The energy audit (src/output/energy_audit.hpp): silent inside [0.98, 1.02]; outside it, the
// change of every term since the last sample, the imbalance, and the term that moved most
// (with the contact interface when it is contact); its state survives a restart.
#include <gtest/gtest.h>

#include "output/energy_audit.hpp"

namespace crumple::output {
namespace {

// A sample whose ratio follows from its terms as the solver computes it.
EnergySample sample(double time, double kinetic, double internal, double contact,
                    double contact_a = 0.0) {
  EnergySample s;
  s.time = time;
  s.cycle = int64_t(time * 1000);
  s.energies.kinetic = kinetic;
  s.energies.internal = internal;
  s.energies.contact = contact;
  s.energies.initial = 100.0;
  s.energies.total = kinetic + internal + contact;
  s.energies.ratio = s.energies.total / s.energies.initial;
  s.contact_id = {7, 9};
  s.contact_energy = {contact_a, contact - contact_a};
  return s;
}

TEST(EnergyAudit, SilentInsideTheBand) {
  EnergyAudit audit;
  EXPECT_EQ(audit.observe(sample(0.0, 100.0, 0.0, 0.0)), "");
  EXPECT_EQ(audit.observe(sample(1.0, 80.0, 21.5, 0.0)), "");  // ratio 1.015
  EXPECT_EQ(audit.summary().samples, 2);
  EXPECT_EQ(audit.summary().samples_outside, 0);
  EXPECT_LT(audit.summary().first_outside_time, 0.0);
  EXPECT_NE(audit.verdict().find("stayed in [0.98, 1.02]"), std::string::npos);
}

TEST(EnergyAudit, NamesTheTermThatMovedInOneSample) {
  // The car-into-pole event of issue 16 in miniature: kinetic +2, contact +10 in one sample,
  // on interface 9.
  EnergyAudit audit;
  audit.observe(sample(0.0, 100.0, 0.0, 0.0));
  audit.observe(sample(1.0, 90.0, 10.0, 0.0));
  const std::string text = audit.observe(sample(2.0, 92.0, 10.0, 10.0, 0.0));
  EXPECT_NE(text.find("ratio 1.1200 at time 2"), std::string::npos) << text;
  EXPECT_NE(text.find("since time 1:"), std::string::npos) << text;
  EXPECT_NE(text.find("kinetic +2,"), std::string::npos) << text;
  EXPECT_NE(text.find("contact +10,"), std::string::npos) << text;
  EXPECT_NE(text.find("balance +12;"), std::string::npos) << text;
  EXPECT_NE(text.find("largest change of a stored term: contact (interface 9 +10)"),
            std::string::npos)
      << text;
  EXPECT_EQ(audit.summary().samples_outside, 1);
  EXPECT_DOUBLE_EQ(audit.summary().first_outside_time, 2.0);
  EXPECT_DOUBLE_EQ(audit.summary().max_ratio, 1.12);
  EXPECT_NE(audit.verdict().find("1 of 3 samples outside, first at time 2"), std::string::npos)
      << audit.verdict();
}

TEST(EnergyAudit, StopsListingAfterTheLimitButKeepsCounting) {
  EnergyAudit audit;
  audit.observe(sample(0.0, 100.0, 0.0, 0.0));
  int listed = 0;
  const int outside = int(EnergyAudit::kMaxPrinted) + 5;
  for (int k = 1; k <= outside; ++k)
    listed += audit.observe(sample(k, 50.0, 40.0, 0.0)).empty() ? 0 : 1;  // ratio 0.9
  EXPECT_EQ(listed, EnergyAudit::kMaxPrinted);
  EXPECT_EQ(audit.summary().samples_outside, outside);
  EXPECT_DOUBLE_EQ(audit.summary().min_ratio, 0.9);
}

TEST(EnergyAudit, StateSurvivesARestart) {
  EnergyAudit a;
  a.observe(sample(0.0, 100.0, 0.0, 0.0));
  a.observe(sample(1.0, 80.0, 10.0, 0.0));  // ratio 0.9: outside
  util::ArchiveWriter w;
  a.save(w);
  EnergyAudit b;
  util::ArchiveReader r(w.bytes());
  b.load(r);
  EXPECT_TRUE(r.atEnd());
  // The next sample is compared with the dumped one, and the counts go on.
  const std::string text = b.observe(sample(2.0, 70.0, 10.0, 0.0));
  EXPECT_NE(text.find("since time 1: kinetic -10,"), std::string::npos) << text;
  EXPECT_EQ(b.summary().samples, 3);
  EXPECT_EQ(b.summary().samples_outside, 2);
  EXPECT_DOUBLE_EQ(b.summary().first_outside_time, 1.0);
}

}  // namespace
}  // namespace crumple::output
