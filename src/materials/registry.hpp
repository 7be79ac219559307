// Every material law Crumple knows, one line each. The deck reader's keyword table, the
// Model's parameter variant (and so its serialisation), the partitioner's weights and the
// element kernels' dispatch are all generated from this list: adding a law is its unit in
// src/materials/laws/ (law.hpp says what a unit declares) plus its line here.
#pragma once

#include "materials/laws/blatz_ko.hpp"
#include "materials/laws/crushable_foam.hpp"
#include "materials/laws/elastic.hpp"
#include "materials/laws/elastic_plastic_hydro.hpp"
#include "materials/laws/enhanced_composite.hpp"
#include "materials/laws/frazer_nash.hpp"
#include "materials/laws/honeycomb.hpp"
#include "materials/laws/johnson_cook.hpp"
#include "materials/laws/low_density_foam.hpp"
#include "materials/laws/modified_piecewise_linear.hpp"
#include "materials/laws/mooney_rivlin.hpp"
#include "materials/laws/muscle.hpp"
#include "materials/laws/null.hpp"
#include "materials/laws/ogden.hpp"
#include "materials/laws/piecewise_linear.hpp"
#include "materials/laws/plastic_kinematic.hpp"
#include "materials/laws/power_law.hpp"
#include "materials/laws/rigid.hpp"
#include "materials/laws/soil_foam.hpp"
#include "materials/laws/spotweld.hpp"
#include "materials/laws/springs.hpp"
#include "materials/laws/strain_rate_plasticity.hpp"
#include "materials/laws/viscoelastic.hpp"

namespace crumple::materials {

template <class... L>
struct LawList {};

// The order is the index of a law in archives (restart dumps, the model sent to other ranks):
// append new laws at the end.
using AllLaws = LawList<Elastic, PlasticKinematic, PiecewiseLinear, Rigid, SpringElastic,
                        DamperViscous, SpringNonlinear, SoilAndFoam, MatNull, CrushableFoam,
                        JohnsonCook, PowerLaw, StrainRatePlasticity, ModifiedPiecewiseLinear,
                        Spotweld, ElasticPlasticHydro, MooneyRivlin, FrazerNash, Muscle,
                        Viscoelastic, LowDensityFoam, BlatzKo, Ogden, Honeycomb, EnhancedComposite>;

}  // namespace crumple::materials
