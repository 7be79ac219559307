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

namespace crumple::output::ascii {

namespace {
std::string e134(const Vec3& v) {
  return scientific(v[0], 13, 4) + scientific(v[1], 13, 4) + scientific(v[2], 13, 4);
}
}  // namespace

std::string spcforcHeader(std::string_view title) {
  return banner(title) + "\n s i n g l e   p o i n t   c o n s t r a i n t   f o r c e s\n";
}

std::string spcforcBlock(double time, const std::vector<SpcRecord>& nodes) {
  std::string s = fmt::format("\n output at time ={}\n", scientific(time, 13, 5));
  Vec3 force{}, moment{};
  bool rotations = false;
  for (const auto& n : nodes) {
    s += fmt::format(" node={:10d} local x,y,z forces ={}   setid {:8d}\n", n.id, e134(n.force),
                     n.set);
    if (n.rotations)
      s += fmt::format(" node={:10d} local x,y,z moments={}   setid {:8d}\n", n.id, e134(n.moment),
                       n.set);
    for (int c = 0; c < 3; ++c) {
      force[std::size_t(c)] += n.force[std::size_t(c)];
      moment[std::size_t(c)] += n.moment[std::size_t(c)];
    }
    rotations = rotations || n.rotations;
  }
  if (rotations) s += fmt::format("{:12}moment resultants={}\n", "", e134(moment));
  return s + fmt::format("{:12}force resultants ={}\n", "", e134(force));
}

std::string bndoutBlock(double time, const std::vector<BndoutRecord>& nodes) {
  std::string s = fmt::format(
      "\n n o d a l   f o r c e/e n e r g y    o u t p u t  t={}\n\n"
      " velocity boundary condition forces/rigid body moments \n\n",
      scientific(time, 14, 5));
  Vec3 total{};
  double energy = 0;
  for (const auto& n : nodes) {
    s += fmt::format(
        " nd#{:8d}  xforce={}   yforce={}  zforce={}   energy={}   setid ={:8d} xmoment={} "
        "ymoment={} zmoment={}\n",
        n.id, scientific(n.force[0], 13, 4), scientific(n.force[1], 13, 4),
        scientific(n.force[2], 13, 4), scientific(n.energy, 13, 4), n.set,
        scientific(n.moment[0], 13, 4), scientific(n.moment[1], 13, 4),
        scientific(n.moment[2], 13, 4));
    for (int c = 0; c < 3; ++c) total[std::size_t(c)] += n.force[std::size_t(c)];
    energy += n.energy;
  }
  return s + fmt::format("{:14}xtotal={}   ytotal={}  ztotal={}   etotal={}\n", "",
                         scientific(total[0], 13, 4), scientific(total[1], 13, 4),
                         scientific(total[2], 13, 4), scientific(energy, 13, 4));
}

namespace {
// Three rows "label" + translation and rotation triples (E12.4), as rbdout's global and local
// blocks.
std::string motionRows(const Vec3* d, const Vec3* dr, const Vec3* v, const Vec3* vr, const Vec3* a,
                       const Vec3* ar) {
  auto six = [](const Vec3& x, const Vec3& y) {
    std::string s;
    for (double q : x) s += scientific(q, 12, 4);
    for (double q : y) s += scientific(q, 12, 4);
    return s;
  };
  return " displacements:" + six(*d, *dr) + "\n    velocities:" + six(*v, *vr) +
         "\n accelerations:" + six(*a, *ar) + "\n";
}
Vec3 toLocal(const std::array<Vec3, 3>& axes, const Vec3& g) {
  Vec3 out{};
  for (std::size_t k = 0; k < 3; ++k)
    out[k] = axes[k][0] * g[0] + axes[k][1] * g[1] + axes[k][2] * g[2];
  return out;
}
}  // namespace

std::string rbdoutBlock(int64_t cycle, double time, const std::vector<RigidBodyRecord>& bodies) {
  std::string s =
      fmt::format("\n  r i g i d   b o d y   m o t i o n   a t  cycle={:8d}   time= {}\n", cycle,
                  scientific(time, 12, 5));
  for (const auto& b : bodies) {
    s += fmt::format("\n {}rigid body{:8d}\n", b.nodal ? "nodal " : "", b.id);
    s +=
        "   global             x           y           z           x-rot       y-rot       z-rot\n";
    s += "   coordinates:";
    for (double q : b.coordinates) s += scientific(q, 12, 4);
    s += "\n" + motionRows(&b.displacement, &b.rotation, &b.velocity, &b.angular_velocity,
                           &b.acceleration, &b.angular_acceleration);
    s += " principal or user defined local coordinate direction vectors\n";
    s += "     a           b           c\n";
    for (std::size_t r = 0; r < 3; ++r) {
      s += fmt::format("   row {}", r + 1);
      for (std::size_t c = 0; c < 3; ++c) s += scientific(b.axes[c][r], 12, 4);
      s += "\n";
    }
    s += " output in principal or user defined local coordinate directions\n";
    s += "     a           b           c    a-rot  b-rot  c-rot\n";
    const Vec3 d = toLocal(b.axes, b.displacement), dr = toLocal(b.axes, b.rotation);
    const Vec3 v = toLocal(b.axes, b.velocity), vr = toLocal(b.axes, b.angular_velocity);
    const Vec3 a = toLocal(b.axes, b.acceleration), ar = toLocal(b.axes, b.angular_acceleration);
    s += motionRows(&d, &dr, &v, &vr, &a, &ar);
  }
  return s;
}

std::string deforcHeader(std::string_view title, const std::vector<LegendEntry>& elements) {
  return banner(title) + "\n" + legend(elements, 6, 68) + "\n";
}

std::string deforcBlock(double time, const std::vector<DiscreteRecord>& elements) {
  std::string s =
      fmt::format("\n d i s c r e t e   e l e m e n t   f o r c e s   a t   t i m e {}\n",
                  scientific(time, 13, 5));
  for (const auto& e : elements) {
    s += fmt::format(" element#{:9d}  x-force={}  y-force={}  z-force={}\n", e.id,
                     scientific(e.force[0], 12, 4), scientific(e.force[1], 12, 4),
                     scientific(e.force[2], 12, 4));
    s += fmt::format("{:18}resultant={}  change in length={}\n", "", scientific(e.resultant, 12, 4),
                     scientific(e.elongation, 12, 4));
  }
  return s;
}

namespace {
// The title line of a stress block: "\n\n <spaced title>   f o r   t i m e  s t e p   N   ( at
// time T )", as R13's elout.
std::string eloutTitle(std::string_view what, int64_t cycle, double time) {
  return fmt::format("\n\n {}   f o r   t i m e  s t e p{:9d}   ( at time{} )\n", what, cycle,
                     scientific(time, 12, 5));
}
std::string stresses(const Stress& s) {
  std::string out;
  for (double v : s) out += scientific(v, 12, 4);
  return out;
}
}  // namespace

namespace {
// The head of a solid or shell stress block: the title, " element  materl<system>", the
// column names ("<ipt>  stress  sig-xx ... sig-zx<last>") and the second header line.
std::string stressHead(int64_t cycle, double time, std::string_view system, std::string_view ipt,
                       std::string_view last, std::string_view second) {
  std::string s = eloutTitle("e l e m e n t   s t r e s s   c a l c u l a t i o n s", cycle, time);
  s += fmt::format(
      "\n element  materl{}\n{}  stress       sig-xx      sig-yy      sig-zz"
      "      sig-xy      sig-yz      sig-zx{}\n{:11}state{}\n",
      system, ipt, last, "", second);
  return s;
}
}  // namespace

std::string eloutSolidBlock(int64_t cycle, double time, const std::vector<EloutSolid>& solids) {
  std::string s = stressHead(cycle, time, "", "     ipt", fmt::format("{:23}yield", ""),
                             fmt::format("{:82}effsg      function", ""));
  for (const auto& e : solids) {
    s += fmt::format("{:8d}-{:7d}\n", e.id, e.material_type);
    s += fmt::format("       1 {:<7} {}{}{}\n", e.state, stresses(e.sig),
                     scientific(e.eps_p, 14, 4), scientific(e.effective, 14, 4));
  }
  return s;
}

std::string eloutShellBlock(int64_t cycle, double time, const std::vector<EloutShell>& shells) {
  std::string s = stressHead(cycle, time, "(global)", " ipt-shl", "       plastic",
                             fmt::format("{:81}strain ", ""));
  for (const auto& e : shells) {
    s += fmt::format("{:8d}-{:7d}\n", e.id, e.material_type);
    for (std::size_t p = 0; p < e.points.size(); ++p)
      s += fmt::format("{:4d}-{:3d} {:<7} {}{}\n", p + 1, 1, e.points[p].state,
                       stresses(e.points[p].sig), scientific(e.points[p].eps_p, 14, 4));
  }
  return s;
}

std::string eloutBeamBlock(int64_t cycle, double time, const std::vector<EloutBeam>& beams) {
  std::string s = eloutTitle("r e s u l t a n t s   a n d   s t r e s s e s", cycle, time);
  for (const auto& b : beams) {
    s += fmt::format("\n\n beam/truss # ={:8d}      part ID  ={:10d}      material type={:8d}\n\n",
                     b.id, b.part, b.material_type);
    s += " resultants      axial    shear-s    shear-t    moment-s   moment-t   torsion     pl "
         "eps\n";
    s += fmt::format("{:11}", "");
    for (double v : b.resultants) s += scientific(v, 11, 3);
    s += scientific(b.eps_p, 11, 3) + "\n";
    if (b.points.empty()) continue;
    s += "\n\n integration point stresses\n";
    s += "                       sigma 11       sigma 12       sigma 31   plastic  eps\n";
    for (std::size_t p = 0; p < b.points.size(); ++p) {
      const auto& q = b.points[p];
      s += fmt::format("{:5d}{:11}{}{}{}{}\n", p + 1, "", scientific(q.sigma11, 15, 6),
                       scientific(q.sigma12, 15, 6), scientific(q.sigma31, 15, 6),
                       scientific(q.eps_p, 15, 6));
    }
  }
  return s;
}

}  // namespace crumple::output::ascii
