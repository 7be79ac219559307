// Meaning of the *MAT_ keywords: one generic reader per law unit of materials/registry.hpp.
// The unit reads its own cards through materials::LawInput, which this file implements on
// the builder's Context (card order, verdicts on fields, curves); MID, RO and the title are
// read here for every law.
#include <string>
#include <utility>

#include "deck/card.hpp"
#include "model/build_context.hpp"

namespace crumple::model::build {

using deck::Card;
using deck::CardCursor;

namespace {

class LawCards final : public materials::LawInput {
 public:
  LawCards(Context& ctx, const deck::Keyword& kw, CardCursor& cur, const deck::KeywordSpec& spec)
      : ctx_(ctx), kw_(kw), cur_(cur), spec_(spec) {}

  const Card& card(std::string_view label) override { return read(label, false); }
  const Card& optionalCard(std::string_view label) override { return read(label, true); }
  void reject(const Card& c, std::string_view field, const std::string& why) override {
    ctx_.reject(c, field, why);
  }
  void ignore(const Card& c, std::string_view field, const std::string& why) override {
    ctx_.ignore(kw_.name, field, why, c.where());
  }
  int32_t curve(const Card& c, std::string_view field, int64_t id) override {
    return ctx_.curve(c, field, id);
  }
  int32_t curveOrReject(const Card& c, std::string_view field, int64_t id) override {
    if (ctx_.model.curveIndex(id) == kNone && ctx_.isUnsupported(Kind::Curve, id)) {
      ctx_.reject(c, field, ctx_.undefinedMessage(Kind::Curve, id));
      return kNone;
    }
    return ctx_.curve(c, field, id);
  }
  int32_t table(const Card&, std::string_view, int64_t id) override {
    return ctx_.model.tableIndex(id);
  }
  int32_t addCurve(int64_t id, std::vector<double> x, std::vector<double> y) override {
    Curve curve;
    curve.id = id;
    curve.x = std::move(x);
    curve.y = std::move(y);
    ctx_.model.curves.push_back(std::move(curve));
    return static_cast<int32_t>(ctx_.model.curves.size() - 1);
  }
  int64_t materialId() const override { return id_; }
  void setMaterialId(int64_t id) { id_ = id; }

 private:
  // Each card once, in the order the unit asks for them (a cursor only moves forward).
  const Card& read(std::string_view label, bool optional) {
    for (const auto& [l, c] : read_)
      if (l == label) return *c;
    const auto& spec = spec_.card(label);
    const Card& c = optional ? cur_.readOptional(spec) : cur_.read(spec);
    read_.emplace_back(label, &c);
    return c;
  }

  Context& ctx_;
  const deck::Keyword& kw_;
  CardCursor& cur_;
  const deck::KeywordSpec& spec_;
  std::vector<std::pair<std::string_view, const Card*>> read_;
  int64_t id_ = 0;
};

template <class U>
void readLaw(Context& ctx, const deck::Keyword& kw, const KeywordOptions& opts) {
  const deck::KeywordSpec& spec = U::cards();
  CardCursor cur(kw, ctx.deck);
  std::string title = readTitleCard(cur, spec, opts);
  LawCards in(ctx, kw, cur, spec);
  Material m = readMaterialBase(ctx, in.card("card 1"), std::move(title), U::kDensity);
  in.setMaterialId(m.id);
  const auto params = U::read(in);
  if constexpr (requires { U::addErosion(params, m.erosion); }) U::addErosion(params, m.erosion);
  m.law = params;
  ctx.model.materials.push_back(std::move(m));
  ctx.collect(cur);
}

template <class... U>
std::vector<LawReader> readersOf(materials::LawList<U...>) {
  std::vector<LawReader> r;
  (
      [&] {
        for (std::string_view name : U::kKeywords) r.push_back({name, readLaw<U>});
      }(),
      ...);
  return r;
}

}  // namespace

const std::vector<LawReader>& lawReaders() {
  static const std::vector<LawReader> r = readersOf(materials::AllLaws{});
  return r;
}

}  // namespace crumple::model::build
