// Contact interfaces as the deck defines them (*CONTACT_..., LS-DYNA Keyword Manual Vol. I,
// "*CONTACT"), resolved to segments and nodes with model indices. The penalty method and the
// search live in src/contact; this is only the data they start from.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "util/source_loc.hpp"

namespace crumple::model {

// One side of an interface: the nodes that are checked against the other side's segments,
// and the segments the other side's nodes are checked against. A segment is four model node
// indices (n3 == n4 for a triangle), oriented so that its normal (x3-x1) x (x4-x2) points
// out of the solid it bounds; shell segments follow the shell's node order.
struct ContactSurface {
  std::vector<int32_t> nodes;  // ascending model node indices
  std::vector<std::array<int32_t, 4>> segments;
  // Per segment: the global element it bounds, its shell thickness (0 for a solid face: the
  // surface has one side) and its penalty stiffness before the scale factors,
  // K A^2 / V for a solid face and K A / (longest diagonal) for a shell (Hallquist, LS-DYNA
  // Theory Manual, "Contact-Impact Algorithm", penalty method; DYNA3D User Manual sec. 6).
  std::vector<int64_t> segment_element;
  std::vector<double> segment_thickness;
  std::vector<double> segment_stiffness;
  // Per segment: the depth of its element under it (V / A of a solid, the thickness of a
  // shell). A node deeper than half of it inside a solid is on the far side of the element,
  // not in contact with this face.
  std::vector<double> segment_depth;
  // Per segment: the solid across the face (global element index), or -1. Only the surfaces of
  // *CONTACT_ERODING_ interfaces with EROSOP 1 hold faces with a solid across them: such a
  // face is in contact once that solid has eroded and its own element lives (the surface
  // follows the erosion; src/contact/erosion.hpp).
  std::vector<int64_t> segment_neighbour;
  // Per node: half the largest shell thickness at it (0 where only solids meet it), the
  // offset of a node of this side from the mid-surface of the other.
  std::vector<double> node_half_thickness;
  // *CONTACT_AUTOMATIC_GENERAL: the side's beams as capsules (their axis and a radius;
  // docs/theory.md, "Beam edges"), checked edge against edge. Per edge: its two model nodes,
  // radius, penalty stiffness before the scale factors (K d, d the contact diameter) and part.
  std::vector<std::array<int32_t, 2>> edges;
  std::vector<double> edge_radius;
  std::vector<double> edge_stiffness;
  std::vector<int32_t> edge_part;
};

enum class ContactKind : uint8_t {
  NodesToSurface,    // one way: nodes of side A against segments of side B
  SurfaceToSurface,  // two way (symmetric): both of the above
  SingleSurface,     // the nodes of one surface against its own segments
  Tied,              // nodes of side A held to the points of side B's segments they start on
  // *CONTACT_FORCE_TRANSDUCER_PENALTY: adds no force; measures the forces of the other
  // interfaces between side A and side B (on side A from all of them when B is empty).
  Transducer,
};

struct ContactInterface {
  int64_t id = 0;  // CID of _ID/_TITLE, else the 1-based order of definition
  std::string title;
  std::string keyword;  // as written, for messages
  ContactKind kind = ContactKind::NodesToSurface;
  bool automatic = false;  // _AUTOMATIC_: segment orientation found from the approach side
  bool offset = false;     // tied _OFFSET: keep the initial gap (else nodes move onto B)
  // Tied shell edge (*CONTACT_TIED_SHELL_EDGE_TO_SURFACE...) and *CONTACT_SPOTWELD: the node's
  // rotation is tied to the segment's too, so that the tie carries moments (docs/theory.md,
  // "Tied shell edges").
  bool tie_rotations = false;
  // *CONTACT_..._TIEBREAK (Keyword Manual, *CONTACT, tiebreak card; OPTION 1): SURFA nodes
  // touching SURFB are tied until (f_n / N)^nen + (f_s / S)^mes >= 1, f_n the tensile normal
  // and f_s the shear force of the tie, N and S the failure forces (NFLS and SFLS times the
  // node's area for AUTOMATIC_SURFACE_TO_SURFACE_TIEBREAK, NFLF and SFLF for
  // TIEBREAK_NODES_TO_SURFACE); then ordinary penalty contact (docs/theory.md, "Tiebreak").
  struct Tiebreak {
    bool on = false;
    bool stress = false;  // normal and shear are stresses (times the node's area)
    double normal = 0.0, shear = 0.0;
    double nen = 2.0, mes = 2.0;
  };
  Tiebreak tiebreak;
  ContactSurface a, b;            // SURFA (slave) and SURFB (master); b empty for single surface
  double fs = 0, fd = 0, dc = 0;  // Coulomb friction: mu = FD + (FS - FD) exp(-DC |v_rel|)
  double vdc = 0;                 // viscous damping, % of critical
  double birth = 0, death = 1e20;
  double sfs = 1, sfm = 1;  // penalty scale factors of the A and B segments (SFSA, SFSB)
  double sst = 0, mst = 0;  // contact thickness overrides of A and B (0 = shell thickness)
  // Tied interfaces: the largest distance from a node to the segment it is tied to, when SST
  // or MST is negative (Keyword Manual, *CONTACT card 3: a tie then depends only on the
  // separation, against their absolute value); 0: the thickness-based tolerance.
  double tie_distance = 0;
  // 1: stiffness also from the nodal masses and the time step; 2: segment-based contact,
  // segment pairs with a stiffness from their masses and the time step (docs/theory.md,
  // "Segment-based contact").
  int soft = 0;
  double sofscl = 0.1;
  int sbopt = 2;  // SOFT = 2: segment pair options (2: planar segments; 3: warped, as 2 here)
  int depth = 2;  // SOFT = 2: 2 surface and edge-to-edge penetration
  int bsort = 0;  // at most this many cycles between bucket sorts (0: by travel alone)
  // Optional card C (or MPP card 1) IGNORE, the interface's own: 1 and 2 track initial
  // penetrations; 0 takes *CONTROL_CONTACT's (ignoreOf below).
  int ignore = 0;
  // Optional card C DTSTIF: the step SOFT = 1's mass-based stiffness is taken at (0: the
  // stiffness step, Contact::dt_stiff_).
  double dtstif = 0.0;
  // MPP card 1 CPARM8 of AUTOMATIC_GENERAL: 1 and 2 leave out beam pairs of one part.
  bool skip_same_part_edges = false;
  // *CONTACT_ERODING_...: the surfaces take the faces that erosion exposes (EROSOP 1; the
  // surfaces then hold interior faces, ContactSurface::segment_neighbour). Every interface
  // drops the segments and nodes of eroded elements.
  bool eroding = false;
  util::SourceLoc where;
};

// *CONTROL_CONTACT
struct ContactControls {
  double slsfac = 0.1;  // global penalty scale factor
  // IGNORE (card 4): 0 moves initially penetrating nodes back to the surface (DYNA3D), 1 and
  // 2 keep the initial penetration and push back only what goes beyond it.
  int ignore = 0;
  // SSTHK (card 2): 0 (default) limits a shell's contact thickness in single surface contacts
  // to 40% of its shortest edge where no thickness is given for contact (OPTT, SST); 1 takes
  // the shell's thickness as it is (docs/theory.md, "Contact thickness").
  int ssthk = 0;
  // ENMASS (card 1): the nodes whose elements have all eroded leave contact (0), or stay in
  // it with their mass when one of their elements was a solid (1) or a solid or a shell (2).
  int enmass = 0;
  // Re-partition the contact work when the busiest rank carries this many times the mean.
  double rebalance_threshold = 1.25;
};

// The IGNORE an interface runs with: its own, else *CONTROL_CONTACT's (Keyword Manual,
// *CONTACT optional card C: "EQ.0: take the value of *CONTROL_CONTACT").
inline int ignoreOf(const ContactInterface& ci, const ContactControls& controls) {
  return ci.ignore != 0 ? ci.ignore : controls.ignore;
}

}  // namespace crumple::model
