#include "output/reactions.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "constraints/rigid.hpp"

namespace crumple::output {

namespace {

// Without a DT on the keyword a history is sampled this many times per run (as results.cpp).
constexpr double kDefaultSamples = 200.0;

const std::vector<std::string> kSpcforcColumns = {"time", "node", "fx", "fy",
                                                  "fz",   "mx",   "my", "mz"};
// energy: the work the prescribed motion has done on the node since t = 0.
const std::vector<std::string> kBndoutColumns = {"time", "node", "fx", "fy", "fz", "energy"};
// The centre of mass (x, y, z), its displacement, velocity and acceleration; the rotation
// accumulated about the global axes, the angular velocity and acceleration.
const std::vector<std::string> kRbdoutColumns = {
    "time", "body", "x",  "y",  "z",  "dx", "dy", "dz", "vx",     "vy",     "vz",    "ax",
    "ay",   "az",   "rx", "ry", "rz", "wx", "wy", "wz", "alphax", "alphay", "alphaz"};
// force: axial, tension positive; fx, fy, fz: that force on the second node along the element.
const std::vector<std::string> kDeforcColumns = {"time", "element", "force", "elongation",
                                                 "fx",   "fy",      "fz"};

// The reactions of the owned nodes as (id, fx, fy, fz, mx, my, mz, work, rotations) records.
std::vector<double> reactionRecords(const std::vector<constraints::NodeReaction>& reactions,
                                    const domain::Subdomain& sd) {
  std::vector<double> out;
  for (const auto& r : reactions) {
    const auto n = std::size_t(r.node);
    if (!sd.node_owned[n]) continue;
    const bool rotations = sd.rotations && sd.inertia[n] > 0.0;
    out.insert(out.end(), {double(sd.node_id[n]), r.force[0], r.force[1], r.force[2], r.moment[0],
                           r.moment[1], r.moment[2], r.work, rotations ? 1.0 : 0.0});
  }
  return out;
}
constexpr std::size_t kReaction = 9;

}  // namespace

double historyInterval(double requested, double end_time) {
  if (requested > 0.0) return requested;
  return end_time > 0.0 ? end_time / kDefaultSamples : 0.0;
}

std::vector<std::vector<double>> gatherById(const comm::Communicator& comm,
                                            const std::vector<double>& local, std::size_t width) {
  const auto all = comm.allGather(local);
  std::vector<std::vector<double>> rows;
  if (!comm.isRoot()) return rows;
  for (std::size_t k = 0; k + width <= all.size(); k += width)
    rows.emplace_back(all.begin() + std::ptrdiff_t(k), all.begin() + std::ptrdiff_t(k + width));
  std::stable_sort(rows.begin(), rows.end(),
                   [](const auto& a, const auto& b) { return a[0] < b[0]; });
  return rows;
}

ReactionHistories::ReactionHistories(const model::Model& model, const solver::Solver& s,
                                     const comm::Communicator& comm)
    : model_(model), comm_(comm) {
  const auto& ctl = model.controls;
  const double end = s.endTime();
  spc_ = ctl.ascii.spcforc && !model.spcs.empty();
  motion_ = ctl.ascii.bndout && !model.prescribed.empty();
  if (ctl.ascii.rbdout && s.rigidBodies())
    for (const auto& b : s.rigidBodies()->states())
      rigid_ = rigid_ || b.kind != constraints::RigidBodyState::Kind::Weld;
  discrete_ = ctl.ascii.deforc && model.discretes.size() > 0;
  if (spc_) spcforc_.interval = historyInterval(ctl.spcforc_dt, end);
  if (motion_) bndout_.interval = historyInterval(ctl.bndout_dt, end);
  if (rigid_) rbdout_.interval = historyInterval(ctl.rbdout_dt, end);
  if (discrete_) deforc_.interval = historyInterval(ctl.deforc_dt, end);
}

std::vector<ReactionHistories::File> ReactionHistories::files() {
  return {{"spcforc.csv", &spcforc_csv_, &kSpcforcColumns, spc_},
          {"bndout.csv", &bndout_csv_, &kBndoutColumns, motion_},
          {"rbdout.csv", &rbdout_csv_, &kRbdoutColumns, rigid_},
          {"deforc.csv", &deforc_csv_, &kDeforcColumns, discrete_},
          {"spcforc", &spcforc_txt_, nullptr, spc_},
          {"bndout", &bndout_txt_, nullptr, motion_},
          {"rbdout", &rbdout_txt_, nullptr, rigid_},
          {"deforc", &deforc_txt_, nullptr, discrete_}};
}

std::string ReactionHistories::header(std::string_view name) const {
  if (name == "spcforc") return ascii::spcforcHeader(model_.title);
  if (name == "deforc") {
    std::vector<ascii::LegendEntry> elements;
    for (int64_t id : model_.discretes.id) elements.push_back({id, {}});
    return ascii::deforcHeader(model_.title, elements);
  }
  return ascii::banner(model_.title);  // bndout, rbdout: the banner, then the blocks
}

void ReactionHistories::write(const solver::Solver& s, bool last) {
  const double t = s.time();
  const std::pair<HistorySchedule*, void (ReactionHistories::*)(const solver::Solver&)> all[] = {
      {&spcforc_, &ReactionHistories::writeSpcforc},
      {&bndout_, &ReactionHistories::writeBndout},
      {&rbdout_, &ReactionHistories::writeRbdout},
      {&deforc_, &ReactionHistories::writeDeforc}};
  for (const auto& [schedule, writer] : all)
    if (schedule->due(t, last)) {
      (this->*writer)(s);
      schedule->advance(t);
    }
}

void ReactionHistories::writeSpcforc(const solver::Solver& s) {
  const auto& sd = s.subdomain();
  const auto rows = gatherById(comm_, reactionRecords(s.boundary().spcReactions(), sd), kReaction);
  if (!comm_.isRoot()) return;
  std::vector<ascii::SpcRecord> records;
  for (const auto& r : rows) {
    // The SPCs of a node are merged when the deck is read: the set is not known (setid 0).
    records.push_back({int64_t(r[0]), 0, {r[1], r[2], r[3]}, {r[4], r[5], r[6]}, r[8] != 0.0});
    spcforc_csv_.row({s.time(), r[0], r[1], r[2], r[3], r[4], r[5], r[6]});
  }
  spcforc_csv_.flush();
  spcforc_txt_.write(ascii::spcforcBlock(s.time(), records));
  spcforc_txt_.flush();
}

void ReactionHistories::writeBndout(const solver::Solver& s) {
  const auto& sd = s.subdomain();
  const auto rows =
      gatherById(comm_, reactionRecords(s.boundary().motionReactions(), sd), kReaction);
  if (!comm_.isRoot()) return;
  std::vector<ascii::BndoutRecord> records;
  for (const auto& r : rows) {
    // LS-DYNA R13 prints the node id in the setid field (bolted_joint's bndout).
    records.push_back({int64_t(r[0]), int64_t(r[0]), {r[1], r[2], r[3]}, {}, r[7]});
    bndout_csv_.row({s.time(), r[0], r[1], r[2], r[3], r[7]});
  }
  bndout_csv_.flush();
  bndout_txt_.write(ascii::bndoutBlock(s.time(), records));
  bndout_txt_.flush();
}

void ReactionHistories::writeRbdout(const solver::Solver& s) {
  if (!comm_.isRoot()) return;
  using Kind = constraints::RigidBodyState::Kind;
  std::vector<ascii::RigidBodyRecord> records;
  for (const auto& b : s.rigidBodies()->states()) {
    if (b.kind == Kind::Weld) continue;
    records.push_back({b.id, b.kind == Kind::Nodal, b.cm, b.displacement, b.rotation, b.velocity,
                       b.angular_velocity, b.acceleration, b.angular_acceleration, b.axes});
    std::vector<double> row = {s.time(), double(b.id)};
    for (const auto* v : {&b.cm, &b.displacement, &b.velocity, &b.acceleration, &b.rotation,
                          &b.angular_velocity, &b.angular_acceleration})
      row.insert(row.end(), v->begin(), v->end());
    rbdout_csv_.row(row);
  }
  rbdout_csv_.flush();
  rbdout_txt_.write(ascii::rbdoutBlock(s.cycle() + 1, s.time(), records));
  rbdout_txt_.flush();
}

void ReactionHistories::writeDeforc(const solver::Solver& s) {
  const auto& sd = s.subdomain();
  std::vector<double> local;  // (id, axial force, elongation, fx, fy, fz) per element held here
  for (const auto& b : sd.discrete_blocks)
    for (std::size_t k = 0; k < b.size(); ++k) {
      const auto n1 = std::size_t(b.conn[k][0]), n2 = std::size_t(b.conn[k][1]);
      model::Vec3 d{};
      for (std::size_t c = 0; c < 3; ++c) d[c] = sd.x[3 * n2 + c] - sd.x[3 * n1 + c];
      const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      // The axial force pulls the second node back towards the first in tension.
      const double f = b.force[k], scale = len > 0.0 ? -f / len : 0.0;
      // + 0.0: no negative zeros in the files.
      local.insert(local.end(), {double(b.elem_id[k]), f, b.elongation[k], scale * d[0] + 0.0,
                                 scale * d[1] + 0.0, scale * d[2] + 0.0});
    }
  const auto rows = gatherById(comm_, local, 6);
  if (!comm_.isRoot()) return;
  std::vector<ascii::DiscreteRecord> records;
  for (const auto& r : rows) {
    records.push_back({int64_t(r[0]), {r[3], r[4], r[5]}, r[1], r[2]});
    deforc_csv_.row({s.time(), r[0], r[1], r[2], r[3], r[4], r[5]});
  }
  deforc_csv_.flush();
  deforc_txt_.write(ascii::deforcBlock(s.time(), records));
  deforc_txt_.flush();
}

void ReactionHistories::saveState(util::ArchiveWriter& out) const {
  const auto& ctl = model_.controls;
  const double requested[] = {ctl.spcforc_dt, ctl.bndout_dt, ctl.rbdout_dt, ctl.deforc_dt};
  const HistorySchedule* schedules[] = {&spcforc_, &bndout_, &rbdout_, &deforc_};
  for (std::size_t k = 0; k < 4; ++k) {
    out.put(requested[k]);
    out.put(schedules[k]->next);
  }
}

void ReactionHistories::loadState(util::ArchiveReader& in, double time) {
  const auto& ctl = model_.controls;
  const double requested[] = {ctl.spcforc_dt, ctl.bndout_dt, ctl.rbdout_dt, ctl.deforc_dt};
  HistorySchedule* schedules[] = {&spcforc_, &bndout_, &rbdout_, &deforc_};
  for (std::size_t k = 0; k < 4; ++k) {
    double dumped_dt = 0.0, next = 0.0;
    in.get(dumped_dt);
    in.get(next);
    schedules[k]->next = dumped_dt == requested[k] ? next : time + schedules[k]->interval;
  }
}

}  // namespace crumple::output
