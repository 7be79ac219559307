#include "output/results.hpp"

#include <fmt/format.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>

namespace crumple::output {

namespace {

// Without a *DATABASE_ request a history is still sampled, this many times per run.
constexpr double kDefaultSamples = 200.0;
constexpr double kDefaultPlotStates = 20.0;

double intervalOr(double requested, double end_time, double samples) {
  if (requested > 0.0) return requested;
  return end_time > 0.0 ? end_time / samples : 0.0;
}

long peakMemoryBytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss * 1024L;  // Linux reports kilobytes
}

}  // namespace

ResultsWriter::ResultsWriter(std::filesystem::path dir, const model::Model& model,
                             const solver::Solver& s)
    : dir_(std::move(dir)), model_(model), pvd_(dir_ / "results.pvd") {
  const auto& ctl = model.controls;
  const double end = s.endTime();
  glstat_.interval = intervalOr(ctl.glstat_dt, end, kDefaultSamples);
  matsum_.interval = intervalOr(ctl.matsum_dt, end, kDefaultSamples);
  plot_.interval = intervalOr(ctl.d3plot_dt, end, kDefaultPlotStates);
  glstat_csv_ = CsvWriter(dir_ / "glstat.csv",
                          {"time", "cycle", "dt", "kinetic", "internal", "hourglass", "contact",
                           "external_work", "total", "energy_ratio", "rigidwall", "added_mass"});
  matsum_csv_ = CsvWriter(dir_ / "matsum.csv", {"time", "part", "kinetic", "internal", "hourglass",
                                                "x_momentum", "y_momentum", "z_momentum"});
  const auto& sd = s.subdomain();
  for (int32_t mn : model.history_nodes) {
    auto it = std::lower_bound(sd.node_model.begin(), sd.node_model.end(), mn);
    if (it != sd.node_model.end() && *it == mn)
      history_local_.push_back(static_cast<int32_t>(it - sd.node_model.begin()));
  }
  if (!history_local_.empty()) {
    nodout_.interval = intervalOr(ctl.nodout_dt, end, kDefaultSamples);
    nodout_csv_ = CsvWriter(dir_ / "nodout.csv", {"time", "node", "x", "y", "z", "dx", "dy", "dz",
                                                  "vx", "vy", "vz", "ax", "ay", "az"});
  }
  if (!model.rigid_walls.empty()) {
    rwforc_.interval = intervalOr(ctl.rwforc_dt, end, kDefaultSamples);
    rwforc_csv_ = CsvWriter(dir_ / "rwforc.csv", {"time", "wall", "fn", "fx", "fy", "fz"});
  }
  std::filesystem::create_directories(dir_ / "states");
}

void ResultsWriter::write(const solver::Solver& s, bool last) {
  const auto t0 = std::chrono::steady_clock::now();
  const double t = s.time();
  const auto& sd = s.subdomain();
  if (glstat_.due(t, last)) {
    const auto e = s.energies();
    glstat_csv_.row({t, double(s.cycle()), s.dt(), e.kinetic, e.internal, e.hourglass, e.contact,
                     e.external_work, e.total, e.ratio, e.rigidwall, s.addedMass()});
    glstat_csv_.flush();
    glstat_.advance(t);
  }
  if (matsum_.due(t, last)) {
    for (const auto& p : s.partSums())
      matsum_csv_.row({t, double(p.part_id), p.kinetic, p.internal, p.hourglass, p.momentum[0],
                       p.momentum[1], p.momentum[2]});
    matsum_csv_.flush();
    matsum_.advance(t);
  }
  if (nodout_.due(t, last)) {
    for (int32_t n : history_local_) {
      const std::size_t i = 3 * static_cast<std::size_t>(n);
      nodout_csv_.row({t, double(sd.node_id[static_cast<std::size_t>(n)]), sd.x[i], sd.x[i + 1],
                       sd.x[i + 2], sd.x[i] - sd.x0[i], sd.x[i + 1] - sd.x0[i + 1],
                       sd.x[i + 2] - sd.x0[i + 2], sd.v[i], sd.v[i + 1], sd.v[i + 2], sd.a[i],
                       sd.a[i + 1], sd.a[i + 2]});
    }
    nodout_csv_.flush();
    nodout_.advance(t);
  }
  if (rwforc_.due(t, last)) {
    for (const auto& w : s.boundary().walls())
      rwforc_csv_.row({t, double(w.def->id), w.normal_force, w.force[0], w.force[1], w.force[2]});
    rwforc_csv_.flush();
    rwforc_.advance(t);
  }
  if ((s.cycle() == 0 || plot_.due(t, last)) && t != last_plot_time_) {
    writePlotState(s);
    plot_.advance(t);
    last_plot_time_ = t;
  }
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void ResultsWriter::writePlotState(const solver::Solver& s) {
  const auto& sd = s.subdomain();
  const std::size_t nn = sd.numNodes();
  std::vector<double> disp(3 * nn);
  for (std::size_t i = 0; i < 3 * nn; ++i) disp[i] = sd.x[i] - sd.x0[i];

  // Cells: active elements in global element order across blocks.
  struct Cell {
    int32_t elem;
    const domain::SolidBlock* blk;
    std::size_t k;
  };
  std::vector<Cell> cells;
  for (const auto& blk : sd.solid_blocks)
    for (std::size_t k = 0; k < blk.size(); ++k)
      if (blk.active[k]) cells.push_back({blk.elem[k], &blk, k});
  std::sort(cells.begin(), cells.end(),
            [](const Cell& a, const Cell& b) { return a.elem < b.elem; });
  const std::size_t nc = cells.size();
  std::vector<int32_t> conn(8 * nc);
  std::vector<double> stress(6 * nc), eps(nc), von_mises(nc);
  std::vector<int64_t> part(nc), rank(nc, sd.rank), elem_id(nc);
  for (std::size_t i = 0; i < nc; ++i) {
    const auto& c = cells[i];
    for (int a = 0; a < 8; ++a) conn[8 * i + a] = c.blk->conn[c.k][a];
    double sg[6];
    for (int k = 0; k < 6; ++k) stress[6 * i + k] = sg[k] = c.blk->sig[k][c.k];
    eps[i] = c.blk->eps_p.empty() ? 0.0 : c.blk->eps_p[c.k];
    const double p = (sg[0] + sg[1] + sg[2]) / 3.0;
    const double j2 =
        0.5 * ((sg[0] - p) * (sg[0] - p) + (sg[1] - p) * (sg[1] - p) + (sg[2] - p) * (sg[2] - p)) +
        sg[3] * sg[3] + sg[4] * sg[4] + sg[5] * sg[5];
    von_mises[i] = std::sqrt(3.0 * j2);
    part[i] = c.blk->part_id;
    elem_id[i] = model_.solids.id[static_cast<std::size_t>(c.elem)];
  }
  MeshView mesh{nn, sd.x.data(), nc, conn.data()};
  std::vector<FieldView> fields = {
      {"node_id", Association::Point, 1, nullptr, sd.node_id.data()},
      {"displacement", Association::Point, 3, disp.data(), nullptr},
      {"velocity", Association::Point, 3, sd.v.data(), nullptr},
      {"acceleration", Association::Point, 3, sd.a.data(), nullptr},
      {"element_id", Association::Cell, 1, nullptr, elem_id.data()},
      {"part", Association::Cell, 1, nullptr, part.data()},
      {"rank", Association::Cell, 1, nullptr, rank.data()},
      {"stress", Association::Cell, 6, stress.data(), nullptr},
      {"von_mises", Association::Cell, 1, von_mises.data(), nullptr},
      {"effective_plastic_strain", Association::Cell, 1, eps.data(), nullptr},
  };
  const std::string name = fmt::format("states/state_{:05d}.vtu", plot_count_++);
  writeVtu(dir_ / name, mesh, fields);
  pvd_.addState(s.time(), name);
}

void ResultsWriter::writeSummary(const solver::Solver& s, const RunInfo& info) const {
  const auto e = s.energies();
  const auto& t = s.timing();
  const auto& sd = s.subdomain();
  nlohmann::json j;
  j["version"] = CRUMPLE_VERSION;
  j["deck"] = info.deck;
  j["ranks"] = info.ranks;
  j["threads"] = info.threads;
  j["termination"] = info.termination;
  if (!info.message.empty()) j["message"] = info.message;
  j["end_time"] = s.time();
  j["cycles"] = s.cycle();
  j["wall_s"] = info.wall_s;
  const double element_cycles = double(model_.solids.size()) * double(s.cycle());
  j["element_cycles_per_s"] = info.wall_s > 0.0 ? element_cycles / info.wall_s : 0.0;
  const double accounted = t.elements + t.contact + t.constraints + t.communication + seconds_;
  j["timing"] = {{"elements", t.elements},       {"contact", t.contact},
                 {"constraints", t.constraints}, {"communication", t.communication},
                 {"output", seconds_},           {"other", std::max(0.0, info.wall_s - accounted)}};
  j["counts"] = {{"nodes", model_.nodes.size()},
                 {"solids", model_.solids.size()},
                 {"shells", 0},
                 {"beams", 0}};
  j["energy"] = {{"kinetic", e.kinetic},
                 {"internal", e.internal},
                 {"hourglass", e.hourglass},
                 {"contact", e.contact},
                 {"external_work", e.external_work},
                 {"rigidwall", e.rigidwall},
                 {"total", e.total},
                 {"ratio", e.ratio}};
  j["mass"] = {{"physical", s.totalMass()}, {"added", s.addedMass()}};
  j["eroded_elements"] = s.erodedElements();
  j["initial_dt"] = s.initialDt();
  j["peak_memory_bytes"] = peakMemoryBytes();
  j["state_digest"] = stateDigest(sd.x, sd.v);
  std::ofstream out(dir_ / "summary.json");
  out << j.dump(2) << '\n';
}

}  // namespace crumple::output
