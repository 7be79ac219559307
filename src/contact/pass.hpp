// One side's nodes checked against the other side's segments, as the model gives them: the
// unit the search, the partition and the force kernel share. Fixed for the run.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace crumple::contact {

// Contact nodes are numbered over every interface, in ascending model index ("cn" numbering);
// a check is one node of a pass against that pass's segments, numbered over every pass.
struct Pass {
  int32_t iface = 0;           // index into Model::contacts
  bool self = false;           // single surface: skip segments next to the node
  bool tied = false;           // nodes held to the point of the segment they start on
  bool tie_rotations = false;  // tied: the node's rotation held to the segment's too (moments)
  // Tied until the bond fails, then ordinary contact (ContactInterface::tiebreak): the faces of
  // the checks' own surface (as local check indices; -1 a corner not among them) and the area
  // of each check's node on the bond, a quarter of each quadrilateral (a third of each
  // triangle) whose corners are all tied, for failure stresses.
  bool tiebreak = false;
  // (Also the faces of an eroding pass's own surface: its checks are the nodes on the faces in
  // contact; `exposure` below.)
  std::vector<std::array<int32_t, 4>> own_faces;
  std::vector<double> node_area;
  int32_t first_check = 0;                  // global index of the first check
  std::vector<int32_t> node;                // contact node of each check
  std::vector<double> node_half;            // half shell thickness at the node
  std::vector<std::array<int32_t, 4>> seg;  // contact nodes
  std::vector<double> seg_half;             // half thickness (0: one-sided solid face)
  std::vector<double> seg_k;                // penalty stiffness with the scale factors
  std::vector<double> seg_depth;            // ContactSurface::segment_depth
  // The element each segment bounds and the solid across it (-1 none; ContactSurface::
  // segment_element, segment_neighbour), for the surfaces that follow erosion (erosion.hpp).
  std::vector<int64_t> seg_elem, seg_across;
  // *CONTACT_ERODING_ node passes: a check is in contact while its node is on a face of its own
  // surface (own_faces) that is in contact (own_elem, own_across as seg_elem, seg_across).
  bool exposure = false;
  std::vector<int64_t> own_elem, own_across;
  // The segment across each edge (seg[k], seg[k + 1 mod 4]) of each segment; -1 for a free
  // edge, an edge shared by more than two segments, and a triangle's collapsed edge.
  std::vector<std::array<int32_t, 4>> seg_nbr;
  // Single surface: the nodes sharing a segment with each node (CSR over contact nodes).
  std::vector<int32_t> near_ptr, near_node;
  double reach_extra = 0.0;  // largest node + segment half thickness
  double max_node_half = 0.0;
  // Beam edges (*CONTACT_AUTOMATIC_GENERAL; docs/theory.md, "Beam edges"): a check is an edge
  // (its first node in `node`, its second in `node2`, its radius in `node_half`) against the
  // other edges, stored as segments {m0, m1, m0, m1} with their radius in `seg_half`. Each
  // pair is checked once, by the check of the lower edge index (the same list on both sides).
  bool edges = false;
  std::vector<int32_t> node2;
  std::vector<int32_t> edge_part;  // part of each edge (CPARM8: pairs of one part left out)
  bool skip_same_part = false;
  // Segment pairs (SOFT = 2; docs/theory.md, "Segment-based contact"): a check is a segment
  // of the first side (its corners in `check_seg`, its half thickness in `node_half`, its
  // depth in `check_depth`, its scale factor in `check_k`) against the segments of the other
  // side (`seg`, `seg_k` holding their scale factors SLSFAC x SFS or SFM). Single surface
  // (`self`): both lists are the surface's, each pair checked once, by the lower index.
  bool segpairs = false;
  std::vector<std::array<int32_t, 4>> check_seg;
  std::vector<double> check_depth, check_k;
  std::vector<int64_t> check_elem, check_across;  // as seg_elem, seg_across
};

}  // namespace crumple::contact
