// The element families as one list: each block type's kernel behind one signature, so that the
// solver visits every block with one loop (domain::Subdomain::forEachBlock). A block type
// carries its model family and slots per element (kFamily, kSlotsPerElement); adding a family
// means its kernel, its block, its traits here and its deck reader.
#pragma once

#include <cstddef>

#include "domain/blocks.hpp"
#include "domain/subdomain.hpp"
#include "elements/beam.hpp"
#include "elements/discrete.hpp"
#include "elements/hex8.hpp"
#include "elements/shell.hpp"
#include "elements/solid2d.hpp"
#include "elements/tet10.hpp"
#include "elements/tshell.hpp"
#include "model/model.hpp"

namespace crumple::elements {

// What one element pass reads: x(n), v(n-1/2), w(n-1/2) (angular velocities), dt(n-1/2).
struct KernelInputs {
  const domain::NodeVector& x;
  const domain::NodeVector& v;
  const domain::NodeVector& w;
  double dt = 0.0;
  const BulkViscosity& bv;
  double* slots = nullptr;
  const double* nodal_ev = nullptr;  // nodal volumetric strains (ELFORM 13; tet_nodal.hpp)
};

template <class Block>
struct FamilyTraits;

template <>
struct FamilyTraits<domain::SolidBlock> {
  static BlockStatus forces(domain::SolidBlock& b, const KernelInputs& in, std::size_t first,
                            std::size_t last) {
    if (b.thickShell()) return computeThickShellForces(b, in.x, in.v, in.dt, in.slots, first, last);
    return model::isFullyIntegratedHex(b.elform) || b.elform == 15
               ? computeFullSolidForces(b, in.x, in.v, in.dt, in.bv, in.slots, first, last)
               : computeSolidForces(b, in.x, in.v, in.dt, in.bv, in.slots, first, last,
                                    in.nodal_ev);
  }
};

template <>
struct FamilyTraits<domain::Tet10Block> {
  static BlockStatus forces(domain::Tet10Block& b, const KernelInputs& in, std::size_t first,
                            std::size_t last) {
    return computeTet10Forces(b, in.x, in.v, in.dt, in.bv, in.slots, first, last);
  }
};

template <>
struct FamilyTraits<domain::ShellBlock> {
  static BlockStatus forces(domain::ShellBlock& b, const KernelInputs& in, std::size_t first,
                            std::size_t last) {
    if (b.planar()) return computeSolid2DForces(b, in.x, in.v, in.dt, in.bv, in.slots, first, last);
    return b.elform == 16
               ? computeFullShellForces(b, in.x, in.v, in.w, in.dt, in.slots, first, last)
               : computeShellForces(b, in.x, in.v, in.w, in.dt, in.slots, first, last);
  }
};

template <>
struct FamilyTraits<domain::BeamBlock> {
  static BlockStatus forces(domain::BeamBlock& b, const KernelInputs& in, std::size_t first,
                            std::size_t last) {
    return computeBeamForces(b, in.x, in.v, in.w, in.dt, in.slots, first, last);
  }
};

template <>
struct FamilyTraits<domain::DiscreteBlock> {
  static BlockStatus forces(domain::DiscreteBlock& b, const KernelInputs& in, std::size_t first,
                            std::size_t last) {
    return computeDiscreteForces(b, in.x, in.v, in.dt, in.slots, first, last);
  }
};

template <class Block>
using TraitsOf = FamilyTraits<std::decay_t<Block>>;

}  // namespace crumple::elements
