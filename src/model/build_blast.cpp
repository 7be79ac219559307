// *LOAD_BLAST_ENHANCED and *LOAD_BLAST_SEGMENT_SET (LS-DYNA Keyword Manual Vol. I, *LOAD):
// the charges and the segments they load (src/constraints/blast.hpp for the pressure).
#include <string>

#include "model/build_context.hpp"

namespace crumple::model::build {

namespace {

using deck::Card;
using deck::CardCursor;
using deck::keywordSpec;

// UNIT (Keyword Manual, *LOAD_BLAST_ENHANCED): the pounds, feet, milliseconds and psi in one
// deck unit of mass, length, time and pressure. 1 pounds, feet, seconds, psi; 2 kilograms,
// meters, seconds, pascals (the default); 3 pounds, inches, seconds, psi; 4 grams,
// centimeters, microseconds, megabars; 5 the user's CFM, CFL, CFT, CFP.
constexpr double kLbPerKg = 2.20462262185, kFtPerM = 3.28083989501;
constexpr double kPsiPerPa = 1.0 / 6894.75729317;

bool setUnits(BlastCharge& b, int64_t unit) {
  switch (unit) {
    case 1:
      b.cfm = 1.0, b.cfl = 1.0, b.cft = 1e3, b.cfp = 1.0;
      return true;
    case 2:
      b.cfm = kLbPerKg, b.cfl = kFtPerM, b.cft = 1e3, b.cfp = kPsiPerPa;
      return true;
    case 3:
      b.cfm = 1.0, b.cfl = 1.0 / 12.0, b.cft = 1e3, b.cfp = 1.0;
      return true;
    case 4:
      b.cfm = 1e-3 * kLbPerKg, b.cfl = 1e-2 * kFtPerM, b.cft = 1e-3, b.cfp = 1e11 * kPsiPerPa;
      return true;
    default:
      return false;
  }
}

}  // namespace

void readLoadBlastEnhanced(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*LOAD_BLAST_ENHANCED");
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec.card("card 1"));
    const Card& c2 = cur.readOptional(spec.card("card 2"));
    BlastCharge b;
    b.id = c.integer("BID");
    b.mass = c.real("M");
    if (!(b.mass > 0)) c.fail("M", "the TNT equivalent mass must be positive");
    b.origin = {c.real("XBO"), c.real("YBO"), c.real("ZBO")};
    b.tbo = c.real("TBO");
    const int64_t unit = c.integer("UNIT");
    if (unit == 5) {
      b.cfm = c2.real("CFM"), b.cfl = c2.real("CFL"), b.cft = c2.real("CFT");
      b.cfp = c2.real("CFP");
      for (auto f : {"CFM", "CFL", "CFT", "CFP"})
        if (!(c2.real(f) > 0)) c2.fail(f, "UNIT 5 needs a positive conversion factor");
    } else if (!setUnits(b, unit)) {
      ctx.reject(c, "UNIT", "unit systems 1 to 5 are supported");
    }
    const int64_t blast = c.integer("BLAST");
    if (blast != 2)
      ctx.reject(c, "BLAST",
                 "only the hemispherical surface burst (BLAST 2) is supported: the free-air "
                 "and air-burst fits are not implemented");
    if (const int64_t nid = c2.integer("NIDBO"); nid != 0) {
      b.origin_node = ctx.node(c2, "NIDBO", nid);
      const auto& x = ctx.model.nodes.x[static_cast<std::size_t>(b.origin_node)];
      b.origin = {x[0], x[1], x[2]};
    }
    b.death = c2.real("DEATH");
    const int64_t negphs = c2.integer("NEGPHS");
    if (negphs != 0 && negphs != 1) c2.fail("NEGPHS", "must be 0 or 1");
    b.negative_phase = negphs == 0;
    ctx.model.blasts.push_back(b);
    ctx.collect(cur);
  }
}

void readLoadBlastSegmentSet(Context& ctx, const deck::Keyword& kw, const KeywordOptions&) {
  const auto& spec = keywordSpec("*LOAD_BLAST_SEGMENT_SET").card("card 1");
  CardCursor cur(kw, ctx.deck);
  for (cur.skipBlankLines(); !cur.atEnd(); cur.skipBlankLines()) {
    const Card& c = cur.read(spec);
    const int64_t bid = c.integer("BID");
    int32_t charge = kNone;
    for (std::size_t k = 0; k < ctx.model.blasts.size(); ++k)
      if (ctx.model.blasts[k].id == bid) charge = static_cast<int32_t>(k);
    if (charge == kNone) c.fail("BID", "no *LOAD_BLAST_ENHANCED with BID " + std::to_string(bid));
    if (c.integer("ALEPID") != 0)
      ctx.reject(c, "ALEPID", "coupling the blast to an ALE domain is not supported");
    c.real("SFNRB");  // the ALE coupling's non-reflecting boundary: no ALE, no use
    PressureLoad p;
    p.blast = charge;
    p.sf = c.real("SCALEP");
    for (const auto& s : ctx.segmentSet(c, "SSID", c.integer("SSID"))) {
      p.nodes = s;
      ctx.model.pressure_loads.push_back(p);
    }
    ctx.collect(cur);
  }
}

}  // namespace crumple::model::build
