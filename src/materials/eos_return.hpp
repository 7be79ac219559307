// The return of the deviatoric laws whose pressure comes from the part's equation of state
// (*MAT_ELASTIC_PLASTIC_HYDRO, *MAT_JOHNSON_COOK): one point's elastic predictor, radial
// return and EOS step, shared by their updates.
#pragma once

#include "materials/eos.hpp"
#include "materials/law.hpp"
#include "materials/return_mapping.hpp"

namespace crumple::materials {

// One point of a deviatoric law whose pressure comes from an equation of state (*MAT_010,
// *MAT_015): the elastic predictor of the deviator (shear modulus G), the radial return by
// the effective plastic strain increment x = increment(q, de) of the trial von Mises stress q
// (0 inside the surface), the pressure and energy of the EOS (eosPointStep, with the
// deviatoric work (s'_old + s'_new) / 2 : de as *MAT_NULL; history h[0..2] the EOS's state,
// eos.hpp, kEosHistory) held at pc, and the new stress. eps_p is left to the caller. Returns x and
// p.
struct EosReturn {
  double x = 0.0, p = 0.0;
};
template <class Increment>
EosReturn eosRadialReturn(PointBatch& b, int i, double G, const Eos& eos, double rho0, double pc,
                          const Increment& increment) {
  double d[6], s_old[6], dev_old[6], dev[6];
  for (int k = 0; k < 6; ++k) {
    d[k] = b.de[k][i];
    s_old[k] = b.s[k][i];
  }
  const double tr = d[0] + d[1] + d[2];
  const double p_old = deviator(s_old, dev_old);
  for (int k = 0; k < 6; ++k) dev[k] = dev_old[k] + 2.0 * G * (k < 3 ? d[k] - tr / 3.0 : d[k]);
  const double q = vonMises(dev);
  EosReturn r;
  r.x = increment(q, static_cast<const double*>(d));
  const double shrink = r.x > 0.0 ? 3.0 * G * r.x / q : 0.0;
  double w_dev = 0.0;
  for (int k = 0; k < 6; ++k) {
    dev[k] -= shrink * dev[k];
    w_dev += (k < 3 ? 0.5 : 1.0) * (dev_old[k] + dev[k]) * d[k];
  }
  r.p = eosPointStep(eos, rho0, pc, b.h[0][i], b.h[1][i], b.h[2][i], w_dev, p_old, tr);
  for (int k = 0; k < 6; ++k) b.s[k][i] = k < 3 ? dev[k] - r.p : dev[k];
  return r;
}

}  // namespace crumple::materials
