// What `crumple check` and `crumple run` say about a model: its summary, the keywords read but
// not acted on, and the unsupported features that change the answer.
#pragma once

#include <string>
#include <vector>

#include "model/model.hpp"
#include "solver/solver.hpp"

namespace crumple::app {

// Counts by element type and part, mass, initial time step and its element, contacts and
// initial penetrations (check's report, the head of run.log).
std::string modelSummary(const model::Model& m, const solver::Solver& s);

// Keywords read but not acted on, fields read but not honoured; empty when there are none.
std::string warningsText(const model::Model& m);

// The unsupported entries whose absence changes the answer: a run refuses the deck for them.
std::vector<const model::UnsupportedKeyword*> answerChanging(const model::Model& m);

// How many distinct features answerChanging lists.
std::size_t featureCount(const model::Model& m);

// One line per feature (every element of every part of a missing material is one feature),
// in order of first appearance.
std::string answerChangingText(const model::Model& m);

}  // namespace crumple::app
