// The penalty force of one node against one segment (docs/theory.md, "Force"; Hallquist,
// Goudreau & Benson 1985, CMAME 51; LS-DYNA Theory Manual, "Contact-Impact Algorithm" and
// "Friction"), and the record of it that every rank receives. Pure functions of their
// arguments: the search (contact.cpp) decides which segment and how deep, these say what force.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "contact/geometry.hpp"
#include "model/contact.hpp"

namespace crumple::contact {

// One node in contact with one segment over the last step. The node takes `force`, the
// segment's nodes -N_a force (segmentReaction).
struct Record {
  int32_t check = 0;          // global check index
  int32_t segment = 0;        // segment of the check's pass
  std::array<double, 4> N{};  // weights of the segment nodes at the contact point
  Vec3 force{};               // on the node: normal + friction
  Vec3 friction{};            // the friction part alone: the stick history of the next cycle
  double penetration = 0.0;   // beyond the entry and initial offsets (tied: the distance)
  double energy = 0.0;        // of the penalty spring now, k p^2 / 2
  double dissipated = 0.0;    // by friction and damping over the last step
  int8_t side = 0;            // shells: the side of the segment the node is on (0: none)
  double entry = 0.0;         // penetration the node already had when the contact began
  // Beam edges: the contact point's parameter on the check's edge; its nodes take (1 - s) and
  // s of `force`, the other edge's nodes -N_a force (N = {1 - t, t, 0, 0}).
  double edge_s = 0.0;
  // Segment pairs: the weights of the check's segment nodes at its contact point; they take
  // M_a `force`, the other segment's nodes -N_a force.
  std::array<double, 4> M{};
  // Rotational ties (tied shell edges, spot welds): the moment on the node, its history for
  // the next cycle; the segment's nodes take -N_a (moment + arm), arm the moment of `force`
  // about the tied point (x_node - sum N_a x_a) x force, so that the pair's moments sum to zero.
  Vec3 moment{};
  Vec3 arm{};
  int8_t released = 0;  // tiebreak: the bond failed this cycle (ordinary contact from the next)
};

// The fields of a record in wire order (records travel between ranks as doubles, one per
// field): the one list pack and unpack follow.
template <class R, class F>
requires std::is_same_v<std::remove_const_t<R>, Record>
constexpr void forEachField(R& r, F&& f) {
  f(r.check);
  f(r.segment);
  for (auto& n : r.N) f(n);
  for (auto& c : r.force) f(c);
  for (auto& c : r.friction) f(c);
  f(r.penetration);
  f(r.energy);
  f(r.dissipated);
  f(r.side);
  f(r.entry);
  f(r.edge_s);
  for (auto& m : r.M) f(m);
  for (auto& c : r.moment) f(c);
  for (auto& c : r.arm) f(c);
  f(r.released);
}

constexpr std::size_t recordDoubles() {
  Record r;
  std::size_t n = 0;
  forEachField(r, [&](auto&) { ++n; });
  return n;
}
constexpr std::size_t kRecordDoubles = recordDoubles();

void pack(const Record& r, std::vector<double>& out);
Record unpack(const double* in);

// The reaction on node a of the record's segment: -N_a f, so that the forces on node and
// segment sum to zero and, the node being on the normal through the contact point, so do
// their moments.
inline Vec3 segmentReaction(const Record& r, std::size_t a) {
  return scale(r.force, -r.N[a]);
}

// Positions, velocities and nodal masses (with mass scaling) of a node and of the four nodes
// of a segment (a triangle repeats its third node).
struct NodeAndSegment {
  Vec3 x_node{}, v_node{};
  double m_node = 0.0;
  std::array<Vec3, 4> x_seg{}, v_seg{};
  std::array<double, 4> m_seg{};
  bool triangle = false;
  // Rotational ties only: angular velocities and rotary inertias (0 where a node has no
  // rotational freedom).
  Vec3 w_node{};
  double i_node = 0.0;
  std::array<Vec3, 4> w_seg{};
  std::array<double, 4> i_seg{};
};

// A node the search found penetrating a segment.
struct Penetration {
  int32_t check = 0, segment = 0;
  std::array<double, 4> N{};  // weights of the segment nodes at the contact point
  Vec3 push{};                // unit direction the node is pushed out
  double depth = 0.0;         // penetration beyond the entry and initial offsets, > 0
  int8_t side = 0;            // for the record
  double entry = 0.0;         // for the record
};

// f_n = k p - c v_n, at least 0, c = VDC/100 x 2 sqrt(k m*); Coulomb friction with an elastic
// stick, capped at mu f_n, mu = FD + (FS - FD) exp(-DC |v_t|). k is the segment's stiffness
// (`stiffness`, with the scale factors), raised by SOFT = 1 and capped for stability.
// `friction`: the tangential force of the last cycle (zero for a new contact). dt_stiff: the
// step the stiffness is taken at (SOFT = 1 and the stability cap; Contact::stiffnessStep);
// dt_prev: the last step, over which velocities and slip are taken.
Record penaltyForce(const Penetration& p, const NodeAndSegment& m, double stiffness,
                    const Vec3& friction, const model::ContactInterface& ci, double dt_stiff,
                    double dt_prev);

// A node tied to the point sum N_a x_a + offset n of a segment (the point moves and turns with
// the segment): a penalty spring of `stiffness` (capped for stability), with VDC damping of
// the relative velocity. dt_stiff and dt_prev as for penaltyForce.
Record tiedForce(int32_t check, int32_t segment, const std::array<double, 4>& N, double offset,
                 const NodeAndSegment& m, double stiffness, const model::ContactInterface& ci,
                 double dt_stiff, double dt_prev);

// Whether the tie of record r (tiedForce) breaks: (f_n / N)^nen + (f_s / S)^mes >= 1, f_n the
// tensile part of the force along the segment normal (the node on side `side` of it), f_s the
// rest, N and S the interface's failure forces (times `area` when they are stresses).
bool tieBreaks(const Record& r, const NodeAndSegment& m, int side,
               const model::ContactInterface::Tiebreak& tb, double area);

// Adds to a tied record (tiedForce) the rotational tie of a shell edge or spot weld node
// (docs/theory.md, "Tied shell edges"): a rotational penalty spring between the node's
// angular velocity and the segment's at the tied point, sum N_a w_a, in rate form
// M(n) = M(n-1) + k_r (w_seg - w_node) dt, the history turned with the pair's mean spin;
// k_r = 2 I* / dt_stiff^2 (I* the pair's rotary inertia, scaled so that rotations never set
// the step; VDC damps the translation only); and the moment of the tie force about
// the tied point, for the segment. `moment`: the history of the last cycle. No rotational
// spring where the node or the segment has no rotary inertia (a solid).
void addTiedMoment(Record& r, const NodeAndSegment& m, const Vec3& moment, double dt_stiff,
                   double dt_prev);

}  // namespace crumple::contact
