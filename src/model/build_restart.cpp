// The restart deck (docs/reliability.md, "Restart"): the few keywords a continued run may
// change. Everything else the continued run needs comes from the original deck and the dump,
// so any other keyword is refused by name rather than silently dropped.
#include <string>
#include <string_view>

#include "model/build_context.hpp"
#include "util/error.hpp"

namespace crumple::model {

void readRestartDeck(const std::filesystem::path& path, Controls& controls) {
  using namespace build;  // Context, KeywordOptions, Handler and the keyword readers
  static const std::pair<std::string_view, Handler> kAllowed[] = {
      {"*CONTROL_TERMINATION", readControlTermination},
      {"*DATABASE_BINARY_D3PLOT", readDatabaseD3plot},
      {"*DATABASE_BINARY_D3DUMP", readDatabaseD3dump},
      {"*DATABASE_GLSTAT", readDatabaseAscii},
      {"*DATABASE_MATSUM", readDatabaseAscii},
      {"*DATABASE_NODOUT", readDatabaseAscii},
      {"*DATABASE_RWFORC", readDatabaseAscii},
      {"*DATABASE_RCFORC", readDatabaseAscii},
      {"*DATABASE_SLEOUT", readDatabaseAscii},
      {"*DATABASE_SECFORC", readDatabaseAscii},
      {"*TITLE", nullptr},  // a label for the reader of the deck, nothing to change
  };
  const deck::Deck deck = deck::readDeck(path);
  // The readers write into a scratch model that starts from the current controls, so a
  // keyword changes only the fields it gives.
  Model scratch;
  scratch.controls = controls;
  Context ctx(deck, scratch, ReadOptions{});
  for (const auto& kw : deck.keywords) {
    Handler handler = nullptr;
    bool allowed = false;
    for (const auto& [name, h] : kAllowed)
      if (kw.name == name) {
        handler = h;
        allowed = true;
      }
    if (!allowed)
      throw util::InputError(
          deck.loc(kw).str() + ": " + kw.name +
          " is not supported in a restart deck (it may change *CONTROL_TERMINATION, "
          "*DATABASE_BINARY_D3PLOT, *DATABASE_BINARY_D3DUMP and the *DATABASE_GLSTAT, _MATSUM, "
          "_NODOUT, _RWFORC, _RCFORC, _SLEOUT and _SECFORC intervals)");
    if (handler) handler(ctx, kw, KeywordOptions{});
  }
  // NPLTC without DT: the plot interval follows the (possibly new) end time.
  if (ctx.d3plot_npltc > 0 && scratch.controls.d3plot_dt == 0.0 && scratch.controls.end_time > 0)
    scratch.controls.d3plot_dt = scratch.controls.end_time / double(ctx.d3plot_npltc);
  // Which LS-DYNA ASCII files are written is the original deck's: a restart continues them
  // (only their intervals change).
  scratch.controls.ascii = controls.ascii;
  controls = scratch.controls;
}

}  // namespace crumple::model
