// Deck -> Model: gives each keyword its meaning, validates references and values, and
// records every keyword or option that is read but not acted on.
#pragma once

#include <filesystem>
#include <string>

#include "deck/deck.hpp"
#include "model/model.hpp"

namespace crumple::model {

struct ReadOptions {
  // false (crumple run): util::InputError for anything the solution would need that Crumple
  // does not support (a solid element whose part uses *MAT_RIGID, an unsupported option of a
  // supported keyword, a *DEFINE_TABLE hardening curve, ...).
  // true (crumple check): those are recorded in Model::unsupported instead and reading goes
  // on, so that everything can be listed. Such a Model may hold parts without a material or
  // section (kNone) and must not be run.
  bool allow_unsupported = false;
  // true (crumple check): an input error in one keyword or record is recorded in
  // Model::errors and reading goes on with the next, so that one pass lists every problem.
  // Such a Model must not be run either.
  bool collect_errors = false;
  // An implicit deck (*CONTROL_IMPLICIT_GENERAL IMFLAG != 0) is run explicitly, and said so,
  // instead of refused (crumple run --implicit-as-explicit).
  bool implicit_as_explicit = false;
};

// Reads the deck at `path` (following *INCLUDE) and builds the validated Model.
// Throws util::InputError whose message names file:line, keyword, card and field.
Model readModel(const std::filesystem::path& path);
Model readModel(const std::filesystem::path& path, const ReadOptions& options);
// The same from a deck already read (`path` names it in messages): the fuzzer's entry, which
// reads from memory.
Model buildModel(const deck::Deck& deck, const std::filesystem::path& path,
                 const ReadOptions& options);

// Reads a restart deck (crumple run --restart-deck): *CONTROL_TERMINATION and the
// *DATABASE_ output intervals change `controls`; any other keyword is a util::InputError naming
// file:line, as a continued run cannot take it into account.
void readRestartDeck(const std::filesystem::path& path, Controls& controls);

// Model::unsupported as a table, one line per keyword: keyword, count, first file:line,
// reason. Empty string when there is nothing to report.
std::string formatUnsupported(const Model& model);

// Model::ignored as a list, one line per field: file:line, keyword, field, reason.
std::string formatIgnored(const Model& model);

}  // namespace crumple::model
