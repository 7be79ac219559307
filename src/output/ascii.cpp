#include "output/ascii.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

namespace crumple::output::ascii {

namespace {

std::string padded(std::string_view text, std::size_t width) {
  std::string s(text.substr(0, width));
  s.resize(width, ' ');
  return s;
}

// " label.......... value": the label filled with dots to 31 characters, then 1PE14.5.
void dotted(std::string& out, std::string_view label, double value) {
  out += fmt::format(" {:.<31}{}\n", label, scientific(value, 14, 5));
}

// Three values, each "name=" and E13.4, as matsum's continuation lines.
std::string triple(const char* a, const char* b, const char* c, const Vec3& v) {
  return fmt::format(" {}={}     {}={}     {}={}\n", a, scientific(v[0], 13, 4), b,
                     scientific(v[1], 13, 4), c, scientific(v[2], 13, 4));
}

}  // namespace

std::string scientific(double value, int width, int digits) {
  // + 0.0 prints a negative zero as 0 (Fortran drops its sign).
  return fmt::format("{:>{}.{}E}", value + 0.0, width, digits);
}

std::string fractional(double value, int width, int digits) {
  if (value == 0.0 || !std::isfinite(value))
    return fmt::format(
        "{:>{}}",
        value == 0.0 ? fmt::format("0.{:0>{}}E+00", "", digits) : fmt::format("{}", value), width);
  // d significant digits as d.ddd E k, rewritten 0.dddd E k+1.
  const std::string s = fmt::format("{:.{}E}", value, digits - 1);
  const std::size_t e = s.find('E');
  std::string mantissa;
  for (char ch : s.substr(0, e))
    if (ch >= '0' && ch <= '9') mantissa += ch;
  const int exponent = std::atoi(s.c_str() + e + 1) + 1;
  const std::string text = fmt::format("{}0.{}E{}{:02d}", value < 0 ? "-" : "", mantissa,
                                       exponent < 0 ? '-' : '+', std::abs(exponent));
  return fmt::format("{:>{}}", text, width);
}

std::string banner(std::string_view title) {
  return fmt::format(" {}\n{:20}ls-dyna layout (R13 ASCII files), written by crumple {}\n",
                     padded(title, 72), "", CRUMPLE_VERSION);
}

std::string legend(const std::vector<LegendEntry>& entries, int gap, int title_width) {
  std::string s = "{BEGIN LEGEND}\n Entity #        Title\n";
  for (const auto& e : entries)
    s += fmt::format("{:9d}{:{}}{}\n", e.id, "", gap,
                     padded(e.title, static_cast<std::size_t>(title_width)));
  return s + "{END LEGEND}\n";
}

std::string glstatBlock(const GlstatSample& g) {
  std::string s =
      fmt::format("\n\n dt of cycle{:8d} is controlled by {:<10}{:10d} of part{:10d}\n\n", g.cycle,
                  g.dt_family, g.dt_element, g.dt_part);
  dotted(s, "time", g.time);
  dotted(s, "time step", g.dt);
  dotted(s, "kinetic energy", g.kinetic);
  dotted(s, "internal energy", g.internal);
  dotted(s, "spring and damper energy", g.spring_damper);
  dotted(s, "hourglass energy ", g.hourglass);
  dotted(s, "system damping energy", g.damping);
  dotted(s, "sliding interface energy", g.contact);
  dotted(s, "external work", g.external_work);
  if (g.stonewall) dotted(s, "stonewall energy", g.stonewall_energy);
  dotted(s, "eroded kinetic energy", g.eroded_kinetic);
  dotted(s, "eroded internal energy", g.eroded_internal);
  dotted(s, "eroded hourglass energy", g.eroded_hourglass);
  dotted(s, "total energy", g.total);
  dotted(s, "total energy / initial energy", g.ratio);
  dotted(s, "energy ratio w/o eroded energy", g.ratio_without_eroded);
  dotted(s, "global x velocity", g.velocity[0]);
  dotted(s, "global y velocity", g.velocity[1]);
  dotted(s, "global z velocity", g.velocity[2]);
  // Wall-clock figures would make the file differ between runs of the same deck.
  s += fmt::format(" {:.<31}{:14d}\n", "time per zone cycle.(nanosec)", 0);
  if (g.mass_scaled) {
    dotted(s, "added mass", g.added_mass);
    dotted(s, "percentage increase", g.percent_increase);
  }
  return s;
}

std::string matsumHeader(std::string_view title, const std::vector<LegendEntry>& parts) {
  return banner(title) + "\n" + legend(parts, 5, 72) + "\n\n\n";
}

std::string matsumBlock(double time, const std::vector<MatsumPart>& parts) {
  std::string s = fmt::format(" time ={}\n", scientific(time, 13, 4));
  for (const auto& p : parts) {
    s += fmt::format(
        " mat.#={:5d}             inten={}     kinen={}     eroded_ie={}     eroded_ke={}\n", p.id,
        scientific(p.internal, 13, 4), scientific(p.kinetic, 13, 4),
        scientific(p.eroded_internal, 13, 4), scientific(p.eroded_kinetic, 13, 4));
    s += triple("x-mom", "y-mom", "z-mom", p.momentum);
    s += triple("x-rbv", "y-rbv", "z-rbv", p.rigid_velocity);
    s += fmt::format("{:25}hgeng={}\n\n\n", "", scientific(p.hourglass, 13, 4));
  }
  return s + "\n\n";
}

std::string nodoutHeader(std::string_view title, const std::vector<LegendEntry>& nodes) {
  return banner(title) + "\n" + legend(nodes, 5, 80) + "\n";
}

namespace {
std::string nodoutTitle(int64_t cycle, double time) {
  return fmt::format(
      "\n\n\n n o d a l   p r i n t   o u t   f o r   t i m e  s t e p{:8d}{:30}( at time {} )\n\n",
      cycle, "", scientific(time, 13, 7));
}
std::string nodoutRow(int64_t id, std::initializer_list<const Vec3*> groups) {
  std::string s = fmt::format("{:9d} ", id);
  for (const Vec3* v : groups)
    for (double x : *v) s += scientific(x, 12, 5);
  return s + "\n";
}
}  // namespace

std::string nodoutBlock(int64_t cycle, double time, const std::vector<NodoutRow>& rows,
                        bool rotations) {
  std::string s = nodoutTitle(cycle, time);
  s += " nodal point  x-disp     y-disp      z-disp      x-vel       y-vel       z-vel      "
       "x-accl      y-accl      z-accl      x-coor      y-coor      z-coor\n";
  for (const auto& r : rows) s += nodoutRow(r.id, {&r.disp, &r.vel, &r.acc, &r.coor});
  if (!rotations) return s;
  s += nodoutTitle(cycle, time);
  s += " nodal point  x-rot      y-rot       z-rot       x-rot vel   y-rot vel   z-rot vel   "
       "x-rot acc   y-rot acc   z-rot acc\n";
  for (const auto& r : rows) s += nodoutRow(r.id, {&r.rot, &r.rot_vel, &r.rot_acc});
  return s;
}

std::string entityHeader(std::string_view title, const std::vector<LegendEntry>& entities) {
  return banner(title) + "\n" + legend(entities, 6, 68) + "\n";
}

std::string rcforcBlock(double time, const std::vector<ContactRecord>& contacts) {
  std::string s;
  for (const auto& c : contacts) {
    if (c.single_surface) {
      const std::string note = fmt::format(
          " interface number,{:10d},is single surface-resultants are undefined\n", c.id);
      s += note + note;
      continue;
    }
    for (const auto& [side, f] : {std::pair{"slave", &c.slave}, std::pair{"master", &c.master}}) {
      s += fmt::format("  {:<6}{:11d} time{}  x{}  y{}  z{} mass{}", side, c.id,
                       scientific(time, 12, 5), scientific((*f)[0], 13, 5),
                       scientific((*f)[1], 13, 5), scientific((*f)[2], 13, 5),
                       scientific(0.0, 13, 5));
      // Contact moments are not computed: written as LS-DYNA writes an absent quantity.
      s += fmt::format("  mx{}  my{}  mz{}\n", scientific(0.0, 13, 5), scientific(0.0, 13, 5),
                       scientific(0.0, 13, 5));
    }
  }
  return s;
}

std::string sleoutBlock(int64_t cycle, double time, const std::vector<ContactRecord>& contacts) {
  std::string s =
      fmt::format("\n\n\n contact interface energy file, time={}\n", fractional(time, 14, 7));
  s += fmt::format("    #             slave       master       cycle={:14d}    frictional\n\n",
                   cycle);
  double slave = 0, master = 0, friction = 0;
  for (const auto& c : contacts) {
    s += fmt::format("{:10d}   {}   {}{:31}{}\n", c.id, fractional(c.slave_energy, 10, 4),
                     fractional(c.master_energy, 10, 4), "", fractional(c.friction_energy, 10, 4));
    slave += c.slave_energy;
    master += c.master_energy;
    friction += c.friction_energy;
  }
  s += fmt::format("\n summary   total slave side={}\n", fractional(slave, 14, 7));
  s += fmt::format("{:11}total mastr side={}\n", "", fractional(master, 14, 7));
  s += fmt::format("{:11}total energy    ={}\n", "", fractional(slave + master, 14, 7));
  s += fmt::format("{:11}friction energy ={}\n\n\n\n", "", fractional(friction, 14, 7));
  return s;
}

std::string rwforcHeader(std::string_view title) {
  return banner(title) + "\n r i g i d   w a l l   f o r c e s\n\n" +
         "       time       wall#  normal-force      x-force      y-force      z-force\n";
}

std::string rwforcBlock(double time, const std::vector<WallRecord>& walls) {
  std::string s;
  for (const auto& w : walls)
    s += fmt::format("{}{:8d}{}{}{}{}\n", scientific(time, 12, 5), w.id,
                     scientific(w.normal, 14, 5), scientific(w.force[0], 13, 5),
                     scientific(w.force[1], 13, 5), scientific(w.force[2], 13, 5));
  return s;
}

std::string secforcBlock(double time, const std::vector<SectionRecord>& sections) {
  std::string s;
  for (const auto& c : sections) {
    const double f =
        std::sqrt(c.force[0] * c.force[0] + c.force[1] * c.force[1] + c.force[2] * c.force[2]);
    s += fmt::format(" section#{:8d} time{}\n", c.id, scientific(time, 12, 5));
    s += fmt::format("{:7}x-force={}  y-force={}  z-force={}  resultant={}\n", "",
                     scientific(c.force[0], 12, 4), scientific(c.force[1], 12, 4),
                     scientific(c.force[2], 12, 4), scientific(f, 12, 4));
    s +=
        fmt::format("{:6}x-moment={} y-moment={} z-moment={}\n", "", scientific(c.moment[0], 12, 4),
                    scientific(c.moment[1], 12, 4), scientific(c.moment[2], 12, 4));
    s += fmt::format("{:6}x-center={} y-center={} z-center={}       area={}\n", "",
                     scientific(c.centroid[0], 12, 4), scientific(c.centroid[1], 12, 4),
                     scientific(c.centroid[2], 12, 4), scientific(c.area, 12, 4));
  }
  return s;
}

}  // namespace crumple::output::ascii
