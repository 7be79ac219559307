// The consistent unit systems of LS-DYNA decks (Keyword Manual vol. I, "Consistent units") and
// how a deck's system is found: *CONTROL_UNITS names it, else the density and Young's modulus
// of the deck's metals give it away (steel is 7850 kg/m^3 and 210 GPa whatever the system is
// called). The system labels outputs only (run.log, summary.json, `crumple plot`).
#pragma once

#include <span>
#include <string_view>

#include "model/model.hpp"

namespace crumple::model {

struct NamedUnits {
  std::string_view name;  // the key of python/crumple_compare/units.py SYSTEMS
  std::string_view length, time, mass, force, stress;
  double steel_density;  // 7850 kg/m^3 in this system's units
  double steel_young;    // 210 GPa in this system's units
};

std::span<const NamedUnits> unitSystems();

// The system whose length, time and mass units *CONTROL_UNITS names (LENGTH "mm", TIME "ms",
// MASS "kg"); nullptr when no named system has them.
const NamedUnits* unitSystemOf(std::string_view length, std::string_view time,
                               std::string_view mass);

// Sets m.units from the deck's metals when *CONTROL_UNITS has not set it: each metal whose
// Young's modulus and density are within reach of steel's or aluminium's in one system votes
// for it (a density scaled up tenfold for mass scaling still votes right); the most votes win.
void inferUnits(Model& m);

// "t-mm-s (mass t, length mm, time s, force N, stress MPa)", or "not known" when empty.
std::string describeUnits(const UnitSystem& u);

}  // namespace crumple::model
