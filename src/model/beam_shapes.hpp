// Integration points of the standard beam cross-sections of *INTEGRATION_BEAM (LS-DYNA
// Keyword Manual vol. I, ICST > 0) for the Hughes-Liu beam.
//
// A section is cut into rectangles, each halved where it crosses an axis of symmetry, and
// every piece takes 2 x 2 Gauss points with a quarter of its area each. That integrates the
// area and both second moments exactly (2-point Gauss is exact for t^2 over a piece), and, since
// no piece straddles a neutral axis of symmetric bending, also the fully plastic moment
// sigma_y integral |t| dA = sigma_y Z (|t| is linear over each piece).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace crumple::model {

using BeamPoints = std::vector<std::array<double, 3>>;  // (s, t, area)

// ICST 1, the W (wide flange, I) section: D1 flange width (along s), D2 flange thickness,
// D3 overall depth (along t), D4 web thickness. 32 points. Empty with `error` set when the
// dimensions do not make a section.
BeamPoints wSectionPoints(const std::array<double, 6>& d, std::string& error);

}  // namespace crumple::model
