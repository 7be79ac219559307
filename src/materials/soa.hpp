// Internal to src/materials: restrict-qualified views of a PointBatch for the kernels.
//
// GCC honours `restrict` on function parameters and on members of structs passed by value,
// but not on local copies; without it the 19 independent arrays of a batch need more runtime
// alias checks than the vectoriser is willing to emit, and the loops stay scalar. The arrays
// of one batch never overlap (PointBatch contract), which is what restrict promises.
#pragma once

#include "materials/law.hpp"

namespace crumple::materials::detail {

struct Soa {
  double* __restrict s0;
  double* __restrict s1;
  double* __restrict s2;
  double* __restrict s3;
  double* __restrict s4;
  double* __restrict s5;
  const double* __restrict d0;
  const double* __restrict d1;
  const double* __restrict d2;
  const double* __restrict d3;
  const double* __restrict d4;
  const double* __restrict d5;
  double* __restrict a0;  // back stress; null for laws without kinematic hardening
  double* __restrict a1;
  double* __restrict a2;
  double* __restrict a3;
  double* __restrict a4;
  double* __restrict a5;
  double* __restrict ep;  // effective plastic strain; null for elastic laws
};

inline Soa soaOf(const PointBatch& b) {
  return Soa{b.s[0],     b.s[1],     b.s[2],     b.s[3],     b.s[4],  b.s[5],     b.de[0],
             b.de[1],    b.de[2],    b.de[3],    b.de[4],    b.de[5], b.alpha[0], b.alpha[1],
             b.alpha[2], b.alpha[3], b.alpha[4], b.alpha[5], b.eps_p};
}

}  // namespace crumple::materials::detail
