// Deck -> Model: gives each keyword its meaning, validates references and values, and
// records every keyword or option that is read but not acted on.
#pragma once

#include <filesystem>

#include "model/model.hpp"

namespace crumple::model {

// Reads the deck at `path` (following *INCLUDE) and builds the validated Model.
// Throws util::InputError whose message names file:line, keyword, card and field.
Model readModel(const std::filesystem::path& path);

}  // namespace crumple::model
