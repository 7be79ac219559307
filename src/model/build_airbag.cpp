// Meaning of *AIRBAG_SIMPLE_PRESSURE_VOLUME (LS-DYNA Keyword Manual Vol. I, *AIRBAG): a closed
// surface of shells (a part set) or segments (a segment set) that encloses a gas whose
// pressure follows the volume; the solver's side is constraints/airbag.hpp.
#include <algorithm>
#include <array>
#include <deque>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "model/build_context.hpp"

namespace crumple::model::build {

namespace {

using deck::Card;
using deck::CardCursor;
using deck::keywordSpec;

// The bag's surface: the shells of the parts of a part set (SIDTYP != 0), or the segments of
// a segment set (SIDTYP = 0), as segments n1..n4 (n3 == n4 for a triangle).
std::vector<std::array<int32_t, 4>> bagSurface(Context& ctx, const Card& c) {
  const int64_t sid = c.integer("SID");
  if (c.integer("SIDTYP") == 0) return ctx.segmentSet(c, "SID", sid);
  const auto& parts = ctx.partSet(c, "SID", sid);
  const Shells& shells = ctx.model.shells;
  std::vector<std::array<int32_t, 4>> segments;
  for (int32_t part : parts) {
    std::size_t found = 0;
    for (std::size_t e = 0; e < shells.size(); ++e)
      if (shells.part[e] == part) {
        segments.push_back(shells.nodes[e]);
        ++found;
      }
    if (found == 0)
      c.fail("SID", "part " + std::to_string(ctx.model.parts[std::size_t(part)].id) +
                        " of part set " + std::to_string(sid) +
                        " has no shells: a bag's parts must be shells");
  }
  return segments;
}

// Turns segments of a surface given with mixed normals (the LSTC sphere of issue 13: half of
// its shells point in, half out) to agree with the first of their connected piece: two
// neighbours must run their shared edge in opposite directions (breadth-first over the edges).
// A quad n1 n2 n3 n4 becomes n1 n4 n3 n2, a triangle n1 n2 n3 n3 becomes n1 n3 n2 n2.
// Returns how many segments were turned.
std::size_t orientConsistently(std::vector<std::array<int32_t, 4>>& segs) {
  auto corners = [&segs](std::size_t i) { return segs[i][2] == segs[i][3] ? 3 : 4; };
  std::map<std::pair<int32_t, int32_t>, std::vector<std::pair<std::size_t, bool>>> edges;
  for (std::size_t i = 0; i < segs.size(); ++i)
    for (int k = 0, n = corners(i); k < n; ++k) {
      const int32_t a = segs[i][std::size_t(k)], b = segs[i][std::size_t((k + 1) % n)];
      edges[{std::min(a, b), std::max(a, b)}].push_back({i, a < b});
    }
  std::vector<int8_t> flip(segs.size(), -1);
  for (std::size_t start = 0; start < segs.size(); ++start) {
    if (flip[start] >= 0) continue;
    flip[start] = 0;
    std::deque<std::size_t> queue{start};
    while (!queue.empty()) {
      const std::size_t i = queue.front();
      queue.pop_front();
      for (int k = 0, n = corners(i); k < n; ++k) {
        const int32_t a = segs[i][std::size_t(k)], b = segs[i][std::size_t((k + 1) % n)];
        const bool runs_up = (a < b) != (flip[i] == 1);
        for (const auto& [j, up] : edges[{std::min(a, b), std::max(a, b)}]) {
          if (flip[j] >= 0) continue;
          flip[j] = up == runs_up ? 1 : 0;  // the same direction as i: turn it
          queue.push_back(j);
        }
      }
    }
  }
  std::size_t turned = 0;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    if (flip[i] != 1) continue;
    auto& q = segs[i];
    q = corners(i) == 3 ? std::array<int32_t, 4>{q[0], q[2], q[1], q[1]}
                        : std::array<int32_t, 4>{q[0], q[3], q[2], q[1]};
    ++turned;
  }
  return turned;
}

// Card 1 fields Crumple has no meaning for: refused when set (they change the answer).
void refuseUnsupportedFields(Context& ctx, const Card& c) {
  if (c.integer("RBID") != 0)
    ctx.reject(c, "RBID", "RBID (activation by a sensor subroutine) is not supported");
  if (c.real("VINI") != 0.0)
    ctx.reject(c, "VINI", "VINI (an initial filled volume) is not supported");
  if (c.real("SPSF") != 0.0) ctx.reject(c, "SPSF", "SPSF (stagnation pressure) is not supported");
}

}  // namespace

void readAirbagSimplePressureVolume(Context& ctx, const deck::Keyword& kw,
                                    const KeywordOptions& opts) {
  const auto& spec = keywordSpec("*AIRBAG_SIMPLE_PRESSURE_VOLUME");
  // A number after the name (*AIRBAG_SIMPLE_PRESSURE_VOLUME_1, older decks) is the bag's id.
  int64_t numbered = 0;
  for (const auto& w : opts.words)
    if (w != "ID") numbered = std::stoll(w);
  CardCursor cur(kw, ctx.deck);
  while (nextRecord(cur, opts.has("ID"))) {
    Airbag bag;
    bag.id = numbered != 0 ? numbered : int64_t(ctx.model.airbags.size()) + 1;
    if (opts.has("ID")) {
      const Card& id = cur.read(spec.card("id card"));
      if (!id.blank("ID")) bag.id = id.integer("ID");
    }
    const Card& c = cur.read(spec.card("card 1"));
    const Card& law = cur.read(spec.card("card 2"));
    refuseUnsupportedFields(ctx, c);
    bag.vsca = c.real("VSCA");
    bag.psca = c.real("PSCA");
    if (!(bag.vsca > 0.0)) c.fail("VSCA", "must be positive");
    bag.mwd = c.real("MWD");
    if (bag.mwd < 0.0) c.fail("MWD", "must not be negative");
    const int64_t lcid = law.integer("LCID");
    if (lcid != 0) {
      bag.pv_curve = ctx.curve(law, "LCID", lcid);
    } else {
      bag.cn = law.real("CN");
      bag.beta = law.real("BETA");
      if (bag.cn < 0.0) bag.cn_curve = ctx.curve(law, "CN", int64_t(-bag.cn));
      if (bag.cn == 0.0 || bag.beta == 0.0)
        law.fail(bag.cn == 0.0 ? "CN" : "BETA",
                 "the bag would hold no pressure: give CN and BETA, or LCID");
    }
    // LCIDDR: CN vs time in the dynamic-relaxation phase (without it, CN as in the transient).
    if (const int64_t lciddr = law.integer("LCIDDR"); lciddr != 0) {
      if (lcid != 0)
        ctx.ignore(kw.name, "LCIDDR", "LCID (pressure vs volume) replaces CN in both phases",
                   law.where());
      else
        bag.cn_dr_curve = ctx.curve(law, "LCIDDR", lciddr);
    }
    auto segments = bagSurface(ctx, c);
    if (const std::size_t turned = orientConsistently(segments); turned > 0)
      ctx.ignore(kw.name, "SID",
                 std::to_string(turned) + " of " + std::to_string(segments.size()) +
                     " segments turned to agree with their neighbours' orientation (the bag's "
                     "surface had mixed normals)",
                 c.where());
    if (segments.size() < 4) c.fail("SID", "a closed surface needs at least 4 segments");
    bag.first = ctx.model.pressure_loads.size();
    bag.count = segments.size();
    const int32_t index = int32_t(ctx.model.airbags.size());
    for (const auto& s : segments) {
      PressureLoad p;
      p.nodes = s;
      p.airbag = index;
      ctx.model.pressure_loads.push_back(p);
    }
    ctx.model.airbags.push_back(bag);
    ctx.collect(cur);
  }
}

}  // namespace crumple::model::build
