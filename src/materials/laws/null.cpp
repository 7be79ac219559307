#include "materials/laws/null.hpp"

#include <cmath>

#include "deck/card.hpp"
#include "deck/layout.hpp"
#include "util/error.hpp"

namespace crumple::materials {

const deck::KeywordSpec& MatNull::cards() {
  using deck::I;
  using deck::R;
  static const deck::KeywordSpec spec{
      kKeywords[0],
      {deck::titleCard(),
       {"card 1",
        {I("MID"), R("RO"), R("PC"), R("MU"), R("TEROD"), R("CEROD"), R("YM"), R("PR")}}}};
  return spec;
}

MatNull::Params MatNull::read(LawInput& in) {
  const deck::Card& c = in.card("card 1");
  Params p;
  p.rho = c.real("RO");
  p.pc = c.real("PC");
  p.mu = c.real("MU");
  p.terod = c.real("TEROD");
  p.cerod = c.real("CEROD");
  p.E = c.real("YM");
  p.nu = c.real("PR");
  if (p.pc > 0.0) c.fail("PC", "the pressure cutoff is a tension limit: zero or negative");
  if (p.mu < 0.0) c.fail("MU", "the viscosity must not be negative");
  if (p.terod < 0.0) c.fail("TEROD", "a relative volume: zero (no erosion) or positive");
  if (p.cerod < 0.0) c.fail("CEROD", "a relative volume: zero (no erosion) or positive");
  if (p.terod > 0.0 && p.cerod > 0.0 && p.cerod >= p.terod)
    c.fail("CEROD", "erosion in compression must be at a smaller relative volume than TEROD");
  // YM 0 (the default) leaves null shells and beams without contact stiffness.
  if (p.E < 0.0) c.fail("YM", "Young's modulus must not be negative");
  if (p.E > 0.0 && !(p.nu > -1.0 && p.nu < 0.5))
    c.fail("PR", "Poisson's ratio must lie in (-1, 0.5)");
  return p;
}

MatNull MatNull::make(const Params& p, const CurveAt&, const std::string& at, const Eos* eos) {
  if (!(p.rho > 0.0)) throw util::InputError(at + "RO must be positive");
  if (p.pc > 0.0) throw util::InputError(at + "PC must be zero or negative");
  MatNull law;
  law.rho0 = p.rho;
  law.pc = p.pc;
  law.mu = p.mu;
  law.terod = p.terod;
  law.cerod = p.cerod;
  if (eos) {
    checkEos(at, *eos, p.rho);
    law.eos = *eos;
    law.moduli = Moduli{eosBulkModulus(*eos, p.rho), 0.0};
  } else if (p.E > 0.0) {
    checkModuli(at, p.E, p.nu);
    law.moduli = moduliFromYoung(p.E, p.nu);
  }
  return law;
}

void MatNull::update(PointBatch& b) const {
  // s' = 2 MU e_dot' = (2 MU / dt) de' (no viscous stress before the first step has a dt).
  const double visc = b.dt > 0.0 ? 2.0 * mu / b.dt : 0.0;
  for (int i = 0; i < b.n; ++i) {
    double d[6], s_old[6];
    for (int k = 0; k < 6; ++k) {
      d[k] = b.de[k][i];
      s_old[k] = b.s[k][i];
    }
    const double tr = d[0] + d[1] + d[2];
    const double p_old = -(s_old[0] + s_old[1] + s_old[2]) / 3.0;
    double dev[6];
    double w_dev = 0.0;  // (s'_old + s'_new) / 2 : de, tensor shear components counted twice
    for (int k = 0; k < 6; ++k) {
      dev[k] = visc * (k < 3 ? d[k] - tr / 3.0 : d[k]);
      const double dev_old = k < 3 ? s_old[k] + p_old : s_old[k];
      w_dev += (k < 3 ? 0.5 : 1.0) * (dev_old + dev[k]) * d[k];
    }
    const double p = eosPointStep(eos, rho0, pc, b.h[0][i], b.h[1][i], b.h[2][i], w_dev, p_old, tr);
    for (int k = 0; k < 6; ++k) b.s[k][i] = k < 3 ? dev[k] - p : dev[k];
    const double v_new = eos.v0 * std::exp(b.h[0][i]);
    b.failed[i] =
        static_cast<uint8_t>((terod > 0.0 && v_new > terod) || (cerod > 0.0 && v_new < cerod));
  }
}

}  // namespace crumple::materials
