// Section forces (*DATABASE_CROSS_SECTION_PLANE with *DATABASE_SECFORC): the force and moment
// transmitted through a plane cut, from the element force slots (domain/blocks.hpp).
//
// As LS-DYNA's cross sections (Keyword Manual Vol. I, *DATABASE_CROSS_SECTION_PLANE), the cut
// is fixed at the start from the initial geometry: the elements of the section's parts with
// nodes on both sides of the plane (a node on it counts as the side the normal points to)
// whose centre projects into the LENL x LENM rectangle from the tail XCT.. (everywhere when
// those are 0) or the circle of RADIUS about it, and their nodes on the positive side. The section
// force is the force those elements exert on those nodes, negated: the resultant the material on
// the positive side exerts on the negative side, +sigma A n for a bar in tension sigma along n. The
// moment is taken about the centroid of the cut nodes (their mean current position) and includes
// the shells' and beams' nodal moments. The area is that of the cut through the elements in the
// initial geometry (solids: the polygon the plane cuts from the hexahedron; shells: the cut
// length times the thickness; beams: the section area).
//
// *DATABASE_CROSS_SECTION_SET gives the cut by sets instead: the elements of its element sets
// and, of their nodes, those in NSID; the same sum, negated (the pull of the side the elements
// are not on); the area of the cut nodes' face of each solid, a shell's cut edge times its
// thickness, a beam's section area.
//
// Every element is computed by one rank: each sends its (element, corner) records to rank 0,
// which sums them in ascending (section, global element, corner) order, so the sums are the
// same bits at any rank count.
#pragma once

#include <cstdint>
#include <vector>

#include "comm/communicator.hpp"
#include "domain/subdomain.hpp"
#include "model/model.hpp"
#include "output/ascii.hpp"

namespace crumple::output {

class SectionForces {
 public:
  SectionForces(const model::Model& model, const domain::Subdomain& sd);
  // The force, moment, centroid and area of every section, in deck order (collective; valid
  // on rank 0). `forces_valid` false (before the first cycle, when the slots hold the corner
  // masses) gives zero forces and moments.
  std::vector<ascii::SectionRecord> compute(const domain::Subdomain& sd,
                                            const comm::Communicator& comm,
                                            bool forces_valid) const;
  // Cut elements per section held here (tests and run.log).
  std::size_t localCuts() const { return cuts_.size(); }

 private:
  struct Corner {
    int32_t node = 0;          // local node
    int32_t slot = 0;          // force slot
    int32_t moment_slot = -1;  // moment slot (shells, beams), -1 without
  };
  struct Cut {
    int32_t section = 0;
    int64_t element = 0;  // global element index
    model::Family family = model::Family::Solid;
    std::size_t block = 0, k = 0;  // the element: block of its family, index in the block
    double area = 0.0;
    std::vector<Corner> corners;  // on the positive side
  };
  template <class Block>
  void findCuts(const model::Model& model, const domain::Subdomain& sd,
                const std::vector<Block>& blocks);
  static bool active(const domain::Subdomain& sd, const Cut& c);
  // This rank's corner records (section, element, corner, node id, x, force, moment, area).
  std::vector<double> records(const domain::Subdomain& sd, bool forces_valid) const;
  // Section s from the records order[begin, end) of `all`.
  ascii::SectionRecord sum(std::size_t s, const std::vector<std::size_t>& order, std::size_t begin,
                           std::size_t end, const std::vector<double>& all) const;
  std::vector<model::CrossSection> sections_;
  std::vector<Cut> cuts_;  // ascending (section, element)
};

// The area of the polygon the plane (point c, unit normal n) cuts from a hexahedron with
// corners x (degenerate hexahedra too); 0 when the plane misses it.
double hexCutArea(const std::array<model::Vec3, 8>& x, const model::Vec3& c, const model::Vec3& n);
// The area of the convex polygon with corners p (in any order) in the plane of unit normal n.
double polygonArea(const std::vector<model::Vec3>& p, const model::Vec3& n);

}  // namespace crumple::output
