#include "app/commands.hpp"

#include <fmt/format.h>

#include <optional>

#include <nlohmann/json.hpp>

#include "app/report.hpp"
#include "app/run.hpp"
#include "comm/communicator.hpp"
#include "domain/subdomain.hpp"
#include "model/build.hpp"
#include "solver/solver.hpp"

namespace crumple::app {

namespace {

// `crumple check --json`: the same report as data (docs/compatibility.md is built from it).
nlohmann::json checkJson(const model::Model& m, const std::string& status,
                         const std::optional<std::pair<double, double>>& dt_end) {
  nlohmann::json j;
  j["deck"] = m.deck_path;
  j["status"] = status;
  j["errors"] = nlohmann::json::array();
  for (const auto& e : m.errors) {
    const auto colon = e.message.find(": ");
    j["errors"].push_back({{"where", colon == std::string::npos ? "" : e.message.substr(0, colon)},
                           {"message", e.message},
                           {"feature", nullptr}});
  }
  j["unsupported"] = nlohmann::json::array();
  for (const auto& u : m.unsupported)
    j["unsupported"].push_back({{"keyword", u.keyword},
                                {"count", u.count},
                                {"first", u.first.str()},
                                {"reason", u.reason},
                                {"changes_answer", u.changes_answer},
                                {"feature", u.feature}});
  j["ignored"] = nlohmann::json::array();
  for (const auto& i : m.ignored)
    j["ignored"].push_back({{"where", i.where.str()},
                            {"keyword", i.keyword},
                            {"field", i.field},
                            {"reason", i.reason}});
  j["counts"] = {{"nodes", m.nodes.size()},         {"solids", m.solids.size()},
                 {"shells", m.shells.size()},       {"beams", m.beams.size()},
                 {"discretes", m.discretes.size()}, {"sph_particles", m.sph.size()}};
  j["initial_dt"] = dt_end ? nlohmann::json(dt_end->first) : nlohmann::json(nullptr);
  j["end_time"] = m.controls.end_time;
  return j;
}

// Every input error, as a compiler lists them (the first kMaxShown; --json has all).
void printErrors(const model::Model& m, std::FILE* out) {
  constexpr std::size_t kMaxShown = 200;
  std::fprintf(out, "input errors: %zu\n", m.errors.size());
  for (std::size_t k = 0; k < m.errors.size() && k < kMaxShown; ++k)
    std::fprintf(out, "  %s\n", m.errors[k].message.c_str());
  if (m.errors.size() > kMaxShown)
    std::fprintf(out, "  ... and %zu more (crumple check --json lists them all)\n",
                 m.errors.size() - kMaxShown);
}

}  // namespace

int checkCommand(const CheckOptions& opt, std::FILE* out) {
  // One tolerant read that goes on past every problem, so that a user fixes a deck in one
  // round trip: input errors, then what Crumple lacks, then what it reads and does not use.
  model::Model m;
  try {
    m = model::readModel(opt.deck,
                         model::ReadOptions{.allow_unsupported = true,
                                            .collect_errors = true,
                                            .implicit_as_explicit = opt.implicit_as_explicit});
  } catch (const std::exception& e) {
    std::fprintf(stderr, "crumple: error: %s\n", e.what());
    return 1;
  }
  const auto changing = answerChanging(m);
  std::string status = !m.errors.empty() ? "error" : !changing.empty() ? "refused" : "ok";
  std::string summary;
  std::optional<std::pair<double, double>> dt_end;
  if (status == "ok") {
    try {
      auto sd = domain::buildSerialSubdomain(m);
      solver::Solver s(m, sd, comm::world());
      s.initialize();
      summary = modelSummary(m, s);
      dt_end = std::make_pair(s.initialDt(), m.controls.end_time);
    } catch (const std::exception& e) {
      m.errors.push_back({e.what()});
      status = "error";
    }
  }
  if (opt.json) {
    std::fputs((checkJson(m, status, dt_end).dump(1) + "\n").c_str(), out);
  } else {
    if (summary.empty())
      std::fprintf(out, "deck: %s\nnodes: %zu\nsolid elements: %zu\n", m.deck_path.c_str(),
                   m.nodes.size(), m.solids.size());
    std::fputs(summary.c_str(), out);
    if (!m.errors.empty()) printErrors(m, out);
    if (!changing.empty())
      std::fprintf(out, "not supported, and leaving it out would change the answer:\n%s",
                   answerChangingText(m).c_str());
    const std::string warn = warningsText(m);
    std::fputs(warn.empty() ? "everything in the deck is supported\n" : warn.c_str(), out);
  }
  if (status == "error") {
    // Each error on stderr too, as a compiler lists them (stdout has the whole report).
    for (const auto& e : m.errors) std::fprintf(stderr, "crumple: error: %s\n", e.message.c_str());
    std::fprintf(stderr, "crumple: error: the deck has %zu input error(s)%s\n", m.errors.size(),
                 changing.empty()
                     ? ""
                     : fmt::format(" and uses {} unsupported feature(s)", featureCount(m)).c_str());
    return 1;
  }
  if (status == "refused") {
    std::fprintf(stderr,
                 "crumple: error: this deck cannot run yet: it uses %zu feature(s) Crumple does "
                 "not support, and leaving them out would change the answer\n",
                 featureCount(m));
    return 1;
  }
  if (opt.strict && !m.unsupported.empty()) {
    std::fprintf(stderr, "crumple: error: --strict: the deck uses %zu unsupported keyword(s)\n",
                 m.unsupported.size());
    return 1;
  }
  return 0;
}

int runCommand(const RunOptions& opt) {
  Run run(opt);
  return run.execute();
}

}  // namespace crumple::app
