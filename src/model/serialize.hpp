// The Model as bytes, so that rank 0 alone reads and validates a deck and the other ranks
// receive the result (src/app distributes it through comm::Communicator::broadcast).
#pragma once

#include <vector>

#include "model/model.hpp"

namespace crumple::model {

std::vector<char> serialize(const Model& model);
Model deserialize(const std::vector<char>& bytes);

}  // namespace crumple::model
