// `tbridge design` of a structure (the `structure` section's designable form): its model, its
// sizing and the check of the sized structure, each kept as it was made.
#pragma once

#include "core/config.h"
#include "truss/truss_check.h"
#include "truss/truss_model.h"
#include "truss/truss_sizing.h"

namespace tbridge {

struct TrussDesign {
  Config config;
  TrussModel model;
  TrussSizing sizing;
  TrussCheck check;
};

// Sizes the structure of `config` (design.solver, design.tolerance, design.max_iterations) and
// checks it. Throws ConfigError where the config has no structure to design, ModelError where
// it is a mechanism, and ConfigError (design.solver) for "direct": a structure has no
// equilibrium-only design.
TrussDesign DesignTruss(const Config& config);

}  // namespace tbridge
