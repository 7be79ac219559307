#include "materials/laws/spotweld.hpp"

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "util/error.hpp"

namespace crumple::materials {

const deck::KeywordSpec& Spotweld::cards() {
  using deck::I;
  using deck::R;
  static const deck::KeywordSpec spec{
      kKeywords[0],
      {deck::titleCard(),
       {"card 1", {I("MID"), R("RO"), R("E"), R("PR"), R("SIGY"), R("EH"), R("DT"), R("TFAIL")}},
       {"card 2",
        {R("EFAIL"), R("NRR"), R("NRS"), R("NRT"), R("MRR"), R("MSS"), R("MTT"), I("NF")}},
       {"card 3", {R("RS"), I("OPT"), R("FVAL"), R("TRUE_T"), R("ASFF"), R("BETA"), I("DMGOPT")}}}};
  return spec;
}

namespace {

// A failure limit of card 2: blank or positive (LS-DYNA reads negative values as curve ids of
// rate-dependent limits, not supported here).
double limit(LawInput& in, const deck::Card& c, std::string_view field) {
  const double v = c.real(field);
  if (v < 0) in.reject(c, field, "a negative value (a curve of the limit) is not supported");
  return v > 0 ? v : 0.0;
}

}  // namespace

Spotweld::Params Spotweld::read(LawInput& in) {
  const deck::Card& c = in.card("card 1");
  const deck::Card& c2 = in.optionalCard("card 2");
  const deck::Card& c3 = in.optionalCard("card 3");
  Params p;
  readElastic(c, p.E, p.nu);
  p.sigy = c.real("SIGY");
  p.eh = c.real("EH");
  if (p.sigy <= 0) c.fail("SIGY", "the yield stress must be positive");
  if (p.eh < 0) c.fail("EH", "the plastic hardening modulus must not be negative");
  if (c.real("DT") != 0) in.reject(c, "DT", "the mass-scaling step of spot welds is not supported");
  p.tfail = limit(in, c, "TFAIL");
  p.efail = limit(in, c2, "EFAIL");
  p.nrr = limit(in, c2, "NRR");
  p.nrs = limit(in, c2, "NRS");
  p.nrt = limit(in, c2, "NRT");
  p.mrr = limit(in, c2, "MRR");
  p.mss = limit(in, c2, "MSS");
  p.mtt = limit(in, c2, "MTT");
  if (c2.integer("NF") > 1)
    in.reject(c2, "NF", "filtering the resultants over NF steps is not supported");
  for (auto f : {"RS", "OPT", "FVAL", "TRUE_T", "ASFF", "BETA", "DMGOPT"})
    if (c3.real(f) != 0)
      in.reject(c3, f, "card 3 (failure models of solid spot welds) is not supported");
  return p;
}

Spotweld Spotweld::make(const Params& p, const CurveAt&, const std::string& at) {
  checkModuli(at, p.E, p.nu);
  if (!(p.sigy > 0.0)) throw util::InputError(at + "SIGY must be positive");
  Spotweld law;
  law.moduli = moduliFromYoung(p.E, p.nu);
  law.sigy = p.sigy;
  law.eh = p.eh;
  law.efail = p.efail;
  law.weld = {p.nrr, p.nrs, p.nrt, p.mrr, p.mss, p.mtt, p.tfail};
  return law;
}

std::string Spotweld::solidRefusal(const Params& p) {
  if (p.tfail > 0) return "TFAIL (failure by time) is applied to spot-weld beams only";
  if (p.nrr > 0 || p.nrs > 0 || p.nrt > 0 || p.mrr > 0 || p.mss > 0 || p.mtt > 0)
    return "the resultant failure NRR .. MTT is applied to spot-weld beams only (the resultants "
           "of a hexahedral weld are not computed)";
  return {};
}

// Solid welds: von Mises plasticity with the isotropic hardening EH (no rate effect), failing
// at EFAIL.
void Spotweld::update(PointBatch& b) const {
  LinearHardening h;
  h.sigy = sigy;
  h.Hi = eh;
  linearHardeningReturn(b, moduli, h, false);
  markFailed(b, efail);
}

FibreLaw Spotweld::fibre() const {
  FibreLaw f;
  f.E = youngOf(moduli);
  f.G = moduli.shear;
  f.plastic = true;
  f.sigy = sigy;
  f.Hi = eh;  // EH is the slope of the yield stress against the plastic strain
  f.fail = efail;
  f.weld = weld;
  return f;
}

}  // namespace crumple::materials
