// The nodal-pressure tetrahedron (*SECTION_SOLID ELFORM 13): the one-point tetrahedron of
// ELFORM 10 whose volumetric strain, and so its pressure, is the mean of its four nodes'
// volumetric strains (Bonet & Burton 1998, "A simple average nodal pressure tetrahedral element
// for incompressible and nearly incompressible dynamic explicit applications", Commun. Numer.
// Meth. Engng 14:437-449; LS-DYNA Theory Manual, solid element formulation 13).
//
// Each node carries the volume V_a = sum_e V_e / 4 and V0_a = sum_e V0_e / 4 over the ELFORM 13
// tetrahedra around it, and the logarithmic volumetric strain e_a = ln(V_a / V0_a). An element's
// volumetric strain is e_e = (e_1 + e_2 + e_3 + e_4) / 4: with p = -K e, the mean of the
// nodal pressures, Bonet & Burton's element pressure. The nodal sums are a gather over
// elements: each element writes its corners' shares to its own slots, the slots of elements on
// other ranks travel as forces do (Subdomain::nodal_volume_peers), and every node sums them in
// ascending global element order (Subdomain::nodal_volume): the same bits at any rank and
// thread count. The kernel (hex8.cpp) then gives the element's law the strain increment whose
// volumetric part is the step's change of e_e.
#pragma once

#include <vector>

#include "domain/subdomain.hpp"

namespace crumple::elements {

// Writes, for every element of an ELFORM 13 block, (V0 / 4, V / 4, 0) into the slots of its
// corners N1..N4 (V0 at x0, V at x) and zeros into corners 5-8 (which repeat N4); an eroded
// element writes zeros everywhere.
void writeNodalVolumes(const domain::SolidBlock& blk, const domain::NodeVector& x0,
                       const domain::NodeVector& x, double* slots);

// The nodal volumetric strains e_a = ln(V_a / V0_a) from the gathered volumes (V0_a, V_a per
// node, two values a node); 0 at a node with no nodal-pressure tetrahedron.
void nodalVolumetricStrain(const std::vector<double>& volumes, std::vector<double>& strain);

}  // namespace crumple::elements
