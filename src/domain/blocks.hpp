// Element blocks other than solids: shells, beams and discrete elements. Like SolidBlock, a
// block is the elements of one part on one rank, with its state as structure of arrays, and
// writes its corner forces (and moments) to per-element slots that the nodes gather in global
// element order (ARCHITECTURE.md, Determinism).
//
// Slot layout (3 doubles per slot, slots[3 * slot + c]):
//   shell element e:    force corner a (0..3) at slot_offset + 8 e + a,
//                       moment corner a      at slot_offset + 8 e + 4 + a
//   beam element e:     force at node a (0..1) at slot_offset + 4 e + a,
//                       moment at node a      at slot_offset + 4 e + 2 + a
//   discrete element e: force at node a (0..1) at slot_offset + 2 e + a
// Initialisation writes each corner's lumped mass into the x component of its force slot and
// its rotational inertia into the x component of its moment slot, so that masses and inertias
// are assembled by the same ordered gather as forces and moments.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "materials/materials.hpp"
#include "model/model.hpp"

namespace crumple::domain {

// What every block has: the part, the elements (model indices within their family) and
// where their slots start.
struct BlockBase {
  int32_t part = model::kNone;  // model part index
  int64_t part_id = 0;
  // Model element index within the element family (solids, shells, beams or discretes).
  // Elements with a node shared with another rank come first (ascending), then the others.
  std::vector<int32_t> elem;
  std::size_t shared_count = 0;  // elements in the first group
  std::size_t shared_end = 0;    // shared_count rounded up to whole batches (kernel range)
  std::vector<int64_t> elem_id;  // user element id
  std::size_t slot_offset = 0;   // first slot of the block
  // *MAT_RIGID part: the elements give the rigid body their mass and inertia and compute no
  // force; their kernels run only at initialisation (the state arrays are allocated by the
  // solver, which calls the kernels' resize functions).
  bool rigid = false;
  std::size_t size() const { return elem.size(); }
};

// Elements per batch for shells (state arrays padded to whole batches).
inline constexpr int kShellBatch = 16;

// Belytschko-Tsay shells (ELFORM 2; ELFORM 4 / degenerate quads as C0 triangles).
struct ShellBlock : BlockBase {
  materials::Law law;
  double rho0 = 0.0;
  int elform = 2;
  int nip = 2;             // integration points through the thickness
  bool lobatto = false;    // QR/IRID: Gauss (default) or Lobatto
  double shear_factor = 5.0 / 6.0;
  int ihq = 1;             // hourglass type (viscous 1-3, stiffness 4-5)
  double qm = 0.1;         // hourglass coefficient
  bool bwc = false;        // Belytschko-Wong-Chiang warping correction (*CONTROL_SHELL BWC=1)
  bool thickness_update = false;  // *CONTROL_SHELL ISTUPD
  std::vector<std::array<int32_t, 4>> conn;  // local node indices; n3 == n4: triangle
  std::vector<std::array<double, 4>> corner_thickness;  // initial thickness at the 4 corners
  // Per-element state: defined by the kernel (src/elements/shell.cpp), padded to batches.
  std::vector<double> thick;       // current thickness
  std::vector<double> area0;       // initial area
  std::vector<double> e_int, e_hg;
  std::vector<uint8_t> active, failed;
  std::vector<double> mass_scale;  // empty if none
  // Stress at each integration point in the corotational element frame:
  // sig[(k * nip + i) * padded + e] for component k in (xx, yy, xy, yz, zx), point i.
  std::vector<double> sig;
  std::vector<double> eps_p;       // [i * padded + e]
  std::vector<double> alpha;       // back stress, like sig (kinematic laws), else empty
  std::vector<double> hgq;         // hourglass resistance (stiffness forms), else empty
  std::size_t paddedSize() const {
    return (elem.size() + kShellBatch - 1) / kShellBatch * kShellBatch;
  }
};

// Beam cross-section (*SECTION_BEAM).
struct BeamSection {
  int elform = 2;        // 1 Hughes-Liu, 2 Belytschko-Schwer resultant, 3 truss
  int cst = 0;           // Hughes-Liu cross-section: 0 rectangular, 1 tubular
  double ts1 = 0, ts2 = 0, tt1 = 0, tt2 = 0;  // Hughes-Liu thicknesses at nodes 1, 2
  double a = 0, iss = 0, itt = 0, j = 0, sa = 0;  // resultant / truss properties
  double shear_factor = 1.0;
};

struct BeamBlock : BlockBase {
  materials::Law law;
  double rho0 = 0.0;
  BeamSection section;
  std::vector<std::array<int32_t, 3>> conn;  // local nodes 1, 2 and orientation node 3
                                             // (model::kNone: default orientation)
  // Orientation node coordinates (the third node may be held by no element; its position is
  // fixed): one entry per element.
  std::vector<std::array<double, 3>> orientation;
  // Per-element state: defined by the kernel (src/elements/beam.cpp).
  std::vector<double> length0;
  std::vector<double> e_int;
  std::vector<uint8_t> active;
  std::vector<double> state;  // kernel-defined layout
};

// Discrete springs and dampers (*ELEMENT_DISCRETE, *SECTION_DISCRETE).
struct DiscreteBlock : BlockBase {
  enum class Kind : uint8_t { SpringElastic, DamperViscous, SpringNonlinear };
  Kind kind = Kind::SpringElastic;
  double k = 0.0;  // stiffness (SpringElastic) or damping constant (DamperViscous)
  std::vector<double> curve_x, curve_y;  // SpringNonlinear: force vs elongation
  std::vector<std::array<int32_t, 2>> conn;
  std::vector<double> scale;    // *ELEMENT_DISCRETE S (force scale factor)
  std::vector<double> offset;   // *ELEMENT_DISCRETE OFFSET (initial elongation)
  std::vector<double> length0;  // initial length
  std::vector<double> e_int;
  std::vector<double> force;    // axial force (output)
};

}  // namespace crumple::domain
