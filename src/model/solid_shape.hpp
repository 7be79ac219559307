// The shape of an 8-node solid as LS-DYNA writes it: hexahedra, and tetrahedra, pentahedra and
// pyramids as degenerate hexahedra with repeated node indices (Keyword Manual, *ELEMENT_SOLID:
// tetrahedron N1 N2 N3 N4 N4 N4 N4 N4, pentahedron N1 N2 N3 N4 N5 N5 N6 N6). Shared by the
// reader (*SECTION_SOLID ELFORM 10, *CONTROL_SOLID ESORT), the dual graph and the contact
// surfaces, so that every module sees the same faces.
#pragma once

#include <array>
#include <cstdint>

namespace crumple::model {

// Distinct node indices of an 8-node (possibly degenerate) hex, in order of first appearance.
// Returns how many there are (<= 8).
inline int distinctNodes(const std::array<int32_t, 8>& n, int32_t out[8]) {
  int k = 0;
  for (int32_t v : n) {
    int i = 0;
    while (i < k && out[i] != v) ++i;
    if (i == k) out[k++] = v;
  }
  return k;
}

// True when no two of the nodes are the same (the usual hexahedron): each node against the
// ones one to four places after it, cyclically (every pair once or twice), without a branch,
// which the compiler does four at a time; distinctNodes' search was three times as much.
inline bool allDistinct(const std::array<int32_t, 8>& n) {
  std::array<int32_t, 16> twice{};
  for (std::size_t i = 0; i < 8; ++i) twice[i] = twice[i + 8] = n[i];
  int same = 0;
  for (std::size_t r = 1; r <= 4; ++r)
    for (std::size_t i = 0; i < 8; ++i) same |= twice[i] == twice[i + r];
  return same == 0;
}

// A tetrahedron in the canonical form the ELFORM 10 kernel reads: four distinct nodes, then
// the fourth repeated (N1 N2 N3 N4 N4 N4 N4 N4).
inline bool isCanonicalTet(const std::array<int32_t, 8>& n) {
  int32_t d[8];
  if (distinctNodes(n, d) != 4) return false;
  for (int a = 0; a < 4; ++a)
    if (n[std::size_t(a)] != d[a]) return false;
  return true;
}

// The tetrahedron of an element with exactly four distinct nodes, as N1 N2 N3 N4 N4 N4 N4 N4
// with the nodes in order of first appearance. Both conventions in use (N4 repeated, and N3 =
// N4 with N5 repeated) keep the base triangle first and its right-hand normal towards the apex
// (the hexahedron's bottom face points at its top face), so a positive hexahedron gives a
// positive tetrahedron.
inline std::array<int32_t, 8> canonicalTet(const std::array<int32_t, 8>& n) {
  int32_t d[8];
  distinctNodes(n, d);
  return {d[0], d[1], d[2], d[3], d[3], d[3], d[3], d[3]};
}

// The pentahedron with bottom triangle (b0 b1 b2), its right-hand normal towards the top
// triangle (t0 t1 t2), t_i across the axial edge from b_i, in the Keyword Manual's form
// N1 N2 N3 N4 N5 N5 N6 N6 (*ELEMENT_SOLID): triangles (N1 N5 N2) and (N4 N6 N3), axial edges
// N1-N4, N5-N6, N2-N3; for a positive hexahedron (N1 N5 N2) points at the other triangle.
inline std::array<int32_t, 8> prismAsHex(const int32_t b[3], const int32_t t[3]) {
  return {b[0], b[2], t[2], t[0], b[1], b[1], t[1], t[1]};
}

// Of the six ways to write one prism (either triangle first, three turns each, all with the
// same orientation), the one with the lexicographically smallest node indices: every input
// convention of the same element gives the same canonical nodes, hence the same bits.
inline std::array<int32_t, 8> smallestPrism(const int32_t b[3], const int32_t t[3]) {
  std::array<int32_t, 8> best{};
  bool first = true;
  for (int end = 0; end < 2; ++end)
    for (int turn = 0; turn < 3; ++turn) {
      int32_t lo[3], hi[3];
      for (int i = 0; i < 3; ++i) {
        // Seen from the other end the triangle runs the other way round.
        const int k = end == 0 ? (i + turn) % 3 : (3 - i + turn) % 3;
        lo[i] = end == 0 ? b[k] : t[k];
        hi[i] = end == 0 ? t[k] : b[k];
      }
      const auto cand = prismAsHex(lo, hi);
      if (first || cand < best) best = cand;
      first = false;
    }
  return best;
}

// The prism of an element with six distinct nodes whose repeats collapse two opposite faces of
// the hexahedron into triangles (both conventions in use: N5 = N6 and N7 = N8, the Keyword
// Manual's; N3 = N4 and N7 = N8), in canonical form (smallestPrism); false for any other
// collapse. For each hexahedron axis the lower face is listed with its right-hand normal
// towards the upper one and upper[i] is the node across the edge from lower[i]; a positive
// hexahedron so gives a positive prism whichever faces collapse.
inline bool canonicalPrism(const std::array<int32_t, 8>& n, std::array<int32_t, 8>& out) {
  int32_t d[8];
  if (distinctNodes(n, d) != 6) return false;
  constexpr int kAxes[3][2][4] = {{{0, 1, 2, 3}, {4, 5, 6, 7}},   // zeta: bottom to top
                                  {{0, 4, 5, 1}, {3, 7, 6, 2}},   // eta
                                  {{0, 3, 7, 4}, {1, 2, 6, 5}}};  // xi
  for (const auto& axis : kAxes) {
    for (int i = 0; i < 4; ++i) {
      const int j = (i + 1) % 4;  // the collapsed edge of both faces: lower[i] = lower[j]
      const auto at = [&](int face, int k) { return n[std::size_t(axis[face][k])]; };
      if (at(0, i) != at(0, j) || at(1, i) != at(1, j)) continue;
      const int k1 = (j + 1) % 4, k2 = (j + 2) % 4;
      const int32_t b[3] = {at(0, j), at(0, k1), at(0, k2)};
      const int32_t t[3] = {at(1, j), at(1, k1), at(1, k2)};
      const auto prism = prismAsHex(b, t);
      int32_t c[8];
      if (distinctNodes(prism, c) != 6) continue;
      out = smallestPrism(b, t);
      return true;
    }
  }
  return false;
}

// A pentahedron in the canonical form the ELFORM 15 kernel reads.
inline bool isCanonicalPrism(const std::array<int32_t, 8>& n) {
  std::array<int32_t, 8> c{};
  return canonicalPrism(n, c) && c == n;
}

// The faces of a solid as lists of 3 or 4 distinct node indices (sizes[f]); returns their
// count. Collapsing nodes turns a hex face into a triangle (kept), an edge or a point
// (dropped); this gives the right faces for the LS-DYNA pentahedron (n5=n6, n7=n8) and
// pyramid (n5=...=n8) and for the tetrahedron written n3=n4, n5=...=n8. The other tetrahedron
// convention (n4=...=n8) would keep the bottom "face" n1..n4, which is the whole element, and
// lose the triangle n1 n2 n3, so any element with 4 distinct nodes is given its 4 triangles
// directly (outward for a positive tetrahedron in canonical order). Faces are listed in
// LS-DYNA node order, outward by the right-hand rule for a positive element.
inline int solidFaces(const std::array<int32_t, 8>& n, int32_t faces[6][4], int sizes[6]) {
  constexpr int kHexFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                   {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  int32_t d[8];
  const int k = distinctNodes(n, d);
  if (k < 4) return 0;  // not a solid; the model validation reports it
  if (k == 4) {
    constexpr int kTet[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
    for (int f = 0; f < 4; ++f) {
      for (int i = 0; i < 3; ++i) faces[f][i] = d[kTet[f][i]];
      sizes[f] = 3;
    }
    return 4;
  }
  int nf = 0;
  for (const auto& hf : kHexFaces) {
    int m = 0;
    for (int i = 0; i < 4; ++i) {
      const int32_t v = n[std::size_t(hf[i])];
      bool seen = false;
      for (int j = 0; j < m; ++j) seen = seen || faces[nf][j] == v;
      if (!seen) faces[nf][m++] = v;
    }
    if (m >= 3) sizes[nf++] = m;
  }
  return nf;
}

}  // namespace crumple::model
