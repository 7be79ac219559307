// libFuzzer entry for the path `crumple check` takes before the solver: the keyword reader
// (src/deck) and the model builder (src/model), strict and tolerant, on one in-memory file,
// and the serialisation that ships a built model to the other ranks.
//
// The input is the deck "fuzz.k". *INCLUDE resolves against a set of files in memory that holds
// only that deck (deck::MemorySource): an include of "fuzz.k" exercises cycle detection, any
// other name is a missing file, and no fuzzed name can make the reader open a file on disk.
//
// util::InputError is the one way bad input may end: any other exception (std::out_of_range
// from an unchecked index, std::bad_alloc from a size read out of the deck, ...) escapes and
// libFuzzer reports it as a crash, as it does sanitizer reports, timeouts and leaks.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>

#include "deck/deck.hpp"
#include "model/build.hpp"
#include "model/serialize.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  using namespace crumple;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const deck::MemorySource files(std::map<std::string, std::string>{{"fuzz.k", text}});
  deck::Deck deck;
  try {
    deck = deck::readDeck("fuzz.k", files);
  } catch (const util::InputError&) {
    return 0;
  }
  // `crumple check` builds strictly first and tolerantly when the strict build refuses.
  for (const bool tolerant : {false, true}) {
    try {
      const model::Model m =
          model::buildModel(deck, "fuzz.k", model::ReadOptions{.allow_unsupported = tolerant});
      // Under mpirun rank 0 ships the model to the others: the round trip must hold for
      // whatever a deck can build.
      if (model::serialize(model::deserialize(model::serialize(m))) != model::serialize(m))
        __builtin_trap();
      return 0;
    } catch (const util::InputError&) {
    }
  }
  return 0;
}
