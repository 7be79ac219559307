#include "output/elout.hpp"

#include <algorithm>
#include <cmath>

#include "elements/beam.hpp"
#include "elements/shell.hpp"
#include "materials/materials.hpp"
#include "output/reactions.hpp"

namespace crumple::output {

namespace {

// One record sent to rank 0: element id, point, then kValues values (see the record functions).
constexpr std::size_t kValues = 11;
constexpr std::size_t kWidth = 2 + kValues;

template <class Block>
bool alive(const Block& b, std::size_t k) {
  return b.active.empty() || b.active[k] != 0;
}

const char* stateOf(bool failed, double eps_p) {
  if (failed) return "failed";
  return eps_p > 0.0 ? "plastic" : "elastic";
}

double vonMises(const ascii::Stress& s) {
  const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

void push(std::vector<double>& out, double id, double point, std::initializer_list<double> v) {
  out.push_back(id);
  out.push_back(point);
  std::size_t n = 0;
  for (double x : v) {
    out.push_back(x);
    ++n;
  }
  out.insert(out.end(), kValues - n, 0.0);
}

template <class Blocks>
void findHeld(const Blocks& blocks, const std::vector<int32_t>& wanted,
              std::vector<std::pair<std::size_t, std::size_t>>& held) {
  for (std::size_t bi = 0; bi < blocks.size(); ++bi)
    for (std::size_t k = 0; k < blocks[bi].size(); ++k)
      if (std::binary_search(wanted.begin(), wanted.end(), blocks[bi].elem[k]))
        held.emplace_back(bi, k);
}

}  // namespace

const std::vector<std::string>& ElementHistories::columns() {
  static const std::vector<std::string> c = {
      "time", "element", "family", "point",   "sxx",     "syy",      "szz",      "sxy",    "syz",
      "szx",  "eps_p",   "axial",  "shear_s", "shear_t", "moment_s", "moment_t", "torsion"};
  return c;
}

ElementHistories::ElementHistories(const model::Model& model, const solver::Solver& s,
                                   const comm::Communicator& comm)
    : model_(model), comm_(comm) {
  const auto& h = model.history_elements;
  wanted_ = model.controls.ascii.elout &&
            std::any_of(h.begin(), h.end(), [](const auto& v) { return !v.empty(); });
  if (!wanted_) return;
  schedule_.interval = historyInterval(model.controls.elout_dt, s.endTime());
  const auto& sd = s.subdomain();
  std::vector<std::pair<std::size_t, std::size_t>> held[3];
  findHeld(sd.solid_blocks, h[0], held[0]);
  findHeld(sd.shell_blocks, h[1], held[1]);
  findHeld(sd.beam_blocks, h[2], held[2]);
  for (int f = 0; f < 3; ++f)
    for (const auto& [b, k] : held[f]) held_[std::size_t(f)].push_back({b, k});
}

std::string ElementHistories::header() const {
  return ascii::banner(model_.title);
}

int64_t ElementHistories::materialType(int32_t part) const {
  const auto& p = model_.parts[std::size_t(part)];
  return materials::typeNumberOf(model_.materials[std::size_t(p.material)].law);
}

// (id, 1, sxx..szx, eps_p, failed, material type)
std::vector<double> ElementHistories::solidRecords(const solver::Solver& s) const {
  std::vector<double> out;
  for (const Held& h : held_[0]) {
    const auto& b = s.subdomain().solid_blocks[h.block];
    const double eps = b.eps_p.empty() ? 0.0 : b.eps_p[h.k];
    push(out, double(b.elem_id[h.k]), 1,
         {b.sigAt(0, h.k), b.sigAt(1, h.k), b.sigAt(2, h.k), b.sigAt(3, h.k), b.sigAt(4, h.k),
          b.sigAt(5, h.k), eps, alive(b, h.k) ? 0.0 : 1.0, double(materialType(b.part))});
  }
  return out;
}

// Per point through the thickness: (id, point, sxx..szx, eps_p, failed, material type)
std::vector<double> ElementHistories::shellRecords(const solver::Solver& s) const {
  std::vector<double> out;
  for (const Held& h : held_[1]) {
    const auto& b = s.subdomain().shell_blocks[h.block];
    std::vector<double> sig(6 * std::size_t(b.nip)), eps(std::size_t(b.nip));
    elements::shellPointStress(b, s.subdomain().x, h.k, reinterpret_cast<double(*)[6]>(sig.data()),
                               eps.data());
    const int points = b.planar() ? 1 : b.nip;
    for (int p = 0; p < points; ++p) {
      const double* q = sig.data() + 6 * p;
      push(out, double(b.elem_id[h.k]), p + 1,
           {q[0], q[1], q[2], q[3], q[4], q[5], eps[std::size_t(p)], alive(b, h.k) ? 0.0 : 1.0,
            double(materialType(b.part))});
    }
  }
  return out;
}

// (id, 0, six resultants, mean eps_p, failed, material type, part id), then per section point
// (id, point, sigma 11, 12, 31, eps_p).
std::vector<double> ElementHistories::beamRecords(const solver::Solver& s) const {
  std::vector<double> out;
  for (const Held& h : held_[2]) {
    const auto& b = s.subdomain().beam_blocks[h.block];
    double r[6] = {};
    elements::beamSectionResultants(b, h.k, r);
    const std::size_t n = b.point.empty() ? 0 : std::size_t(b.points);
    const auto* pts = n ? &b.point[h.k * n] : nullptr;
    double eps = 0.0;
    for (std::size_t p = 0; p < n; ++p) eps += pts[p].eps_p / double(n);
    const double id = double(b.elem_id[h.k]);
    push(out, id, 0,
         {r[0], r[1], r[2], r[3], r[4], r[5], eps, alive(b, h.k) ? 0.0 : 1.0,
          double(materialType(b.part)), double(model_.parts[std::size_t(b.part)].id)});
    for (std::size_t p = 0; p < n; ++p)
      push(out, id, double(p + 1), {pts[p].sig, pts[p].tau_s, pts[p].tau_t, pts[p].eps_p});
  }
  return out;
}

void ElementHistories::write(const solver::Solver& s, bool last) {
  if (!wanted_ || !schedule_.due(s.time(), last)) return;
  schedule_.advance(s.time());
  const auto solids = gatherById(comm_, solidRecords(s), kWidth);
  const auto beams = gatherById(comm_, beamRecords(s), kWidth);
  const auto shells = gatherById(comm_, shellRecords(s), kWidth);
  if (!comm_.isRoot()) return;
  const double t = s.time();
  const int64_t cycle = s.cycle() + 1;
  auto csv = [&](const std::vector<double>& r, int family, std::initializer_list<double> v) {
    std::vector<double> row = {t, r[0], double(family), r[1]};
    row.insert(row.end(), v);
    row.resize(columns().size(), 0.0);
    for (double& x : row) x += 0.0;  // no negative zeros in the file
    csv_.row(row);
  };
  std::vector<ascii::EloutSolid> es;
  for (const auto& r : solids) {
    const ascii::Stress sig{r[2], r[3], r[4], r[5], r[6], r[7]};
    es.push_back(
        {int64_t(r[0]), int64_t(r[10]), stateOf(r[9] != 0.0, r[8]), sig, r[8], vonMises(sig)});
    csv(r, 0, {r[2], r[3], r[4], r[5], r[6], r[7], r[8]});
  }
  std::vector<ascii::EloutBeam> eb;
  for (const auto& r : beams) {
    if (r[1] == 0.0) {
      eb.push_back({int64_t(r[0]),
                    int64_t(r[11]),
                    int64_t(r[10]),
                    {r[2], r[3], r[4], r[5], r[6], r[7]},
                    r[8],
                    {}});
      csv(r, 2, {0, 0, 0, 0, 0, 0, r[8], r[2], r[3], r[4], r[5], r[6], r[7]});
    } else {
      eb.back().points.push_back({r[2], r[3], r[4], r[5]});
      csv(r, 2, {r[2], 0, 0, r[3], 0, r[4], r[5]});
    }
  }
  std::vector<ascii::EloutShell> esh;
  for (const auto& r : shells) {
    if (r[1] == 1.0) esh.push_back({int64_t(r[0]), int64_t(r[10]), {}});
    esh.back().points.push_back(
        {stateOf(r[9] != 0.0, r[8]), {r[2], r[3], r[4], r[5], r[6], r[7]}, r[8]});
    csv(r, 1, {r[2], r[3], r[4], r[5], r[6], r[7], r[8]});
  }
  csv_.flush();
  if (!es.empty()) txt_.write(ascii::eloutSolidBlock(cycle, t, es));
  if (!eb.empty()) txt_.write(ascii::eloutBeamBlock(cycle, t, eb));
  if (!esh.empty()) txt_.write(ascii::eloutShellBlock(cycle, t, esh));
  txt_.flush();
}

void ElementHistories::saveState(util::ArchiveWriter& out) const {
  out.put(model_.controls.elout_dt);
  out.put(schedule_.next);
}

void ElementHistories::loadState(util::ArchiveReader& in, double time) {
  double dumped_dt = 0.0, next = 0.0;
  in.get(dumped_dt);
  in.get(next);
  schedule_.next = dumped_dt == model_.controls.elout_dt ? next : time + schedule_.interval;
}

}  // namespace crumple::output
