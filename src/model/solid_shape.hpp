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
    bool seen = false;
    for (int i = 0; i < k; ++i) seen = seen || out[i] == v;
    if (!seen) out[k++] = v;
  }
  return k;
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
