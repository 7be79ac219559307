// Joint forces (*DATABASE_JNTFORC): jntforc.csv and LS-DYNA's ASCII jntforc, one record per
// joint of *CONSTRAINED_JOINT_ at each output time, from the resultants the rigid-body module
// keeps (constraints::JointState: the force of the joint's springs on body B, the N2 side,
// their moment about N2, in global components, and the joint's energy).
#pragma once

#include <string>
#include <vector>

#include "constraints/rigid.hpp"

namespace crumple::output {

// time, joint, fx, fy, fz, fr, mx, my, mz, mr, energy
const std::vector<std::string>& jntforcColumns();
std::vector<std::vector<double>> jntforcRows(double time,
                                             const std::vector<constraints::JointState>& joints);

namespace ascii {
// One output time: per joint its id, force and moment components and resultants, energy
// (the layout of LS-DYNA's jntforc is not checked against a sample: docs/theory.md).
std::string jntforcBlock(double time, const std::vector<constraints::JointState>& joints);
}  // namespace ascii

}  // namespace crumple::output
