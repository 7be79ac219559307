#include "output/jntforc.hpp"

#include <fmt/format.h>

#include <cmath>

#include "output/ascii.hpp"

namespace crumple::output {

namespace {

double length(const constraints::Vec3& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

}  // namespace

const std::vector<std::string>& jntforcColumns() {
  static const std::vector<std::string> columns = {"time", "joint", "fx", "fy", "fz",    "fr",
                                                   "mx",   "my",    "mz", "mr", "energy"};
  return columns;
}

std::vector<std::vector<double>> jntforcRows(double time,
                                             const std::vector<constraints::JointState>& joints) {
  std::vector<std::vector<double>> rows;
  for (const auto& j : joints)
    rows.push_back({time, double(j.id), j.force[0], j.force[1], j.force[2], length(j.force),
                    j.moment[0], j.moment[1], j.moment[2], length(j.moment), j.energy});
  return rows;
}

namespace ascii {

std::string jntforcBlock(double time, const std::vector<constraints::JointState>& joints) {
  std::string s = fmt::format("\n\n time.........................{}\n", scientific(time, 12, 5));
  for (const auto& j : joints) {
    const auto line = [&](const char* label, double v) {
      return fmt::format(" {:.<36}{}\n", label, scientific(v, 12, 5));
    };
    s += fmt::format("\n joint ID{:.<28}{:12d}\n", "", j.id);
    s += line("x-force", j.force[0]) + line("y-force", j.force[1]) + line("z-force", j.force[2]);
    s += line("x-moment", j.moment[0]) + line("y-moment", j.moment[1]) +
         line("z-moment", j.moment[2]);
    s += line("resultant force", length(j.force)) + line("resultant moment", length(j.moment));
    s += line("joint energy", j.energy);
  }
  return s;
}

}  // namespace ascii

}  // namespace crumple::output
