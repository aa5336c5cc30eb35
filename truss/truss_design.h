// `tbridge design` of a structure (the `structure` section's designable form): its model, its
// sizing and the check of the sized structure, each kept as it was made.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <vector>

#include "core/config.h"
#include "truss/truss_check.h"
#include "truss/truss_model.h"
#include "truss/truss_sizing.h"

namespace tbridge {

struct TrussDesign {
  Config config;
  TrussModel model;
  TrussSizing sizing;       // as sized; read back from the file by `check`
  TrussCheck check;         // at each member's area: its group's, or its own where edited
  std::vector<int> edited;  // members whose area in the file is not their group's (check)
};

// Sizes the structure of `config` (design.solver, design.tolerance, design.max_iterations) and
// checks it. Throws ConfigError where the config has no structure to design, ModelError where
// it is a mechanism, and ConfigError (design.solver) for "direct": a structure has no
// equilibrium-only design.
TrussDesign DesignTruss(const Config& config);

// A structure's design file (`kind` "structure") read and checked as written: each member at the
// area its file gives, which may differ from its group's after an engineer's edit (listed in
// `edited`). Throws ConfigError naming the key where the file is not a structure's design or an
// area is not a positive number.
TrussDesign CheckTrussDesignFile(const nlohmann::json& file);

}  // namespace tbridge
