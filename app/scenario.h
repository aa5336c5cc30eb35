// One dynamic scenario end to end: config -> design -> dynamic model -> simulation, or, for a
// custom scene, config -> structure model -> simulation.
#pragma once

#include <functional>
#include <vector>

#include "core/config.h"
#include "design/design.h"
#include "dynamics/model.h"
#include "dynamics/simulation.h"

namespace tbridge {

struct ScenarioResult {
  Design design;  // empty for a "structure" config
  DynamicModel model;
  SimulationResult simulation;
};

// Throws ConfigError when `config` has no "dynamics" section (or a bad one), ModelError when
// the design or the run fails (see RunDesign and Simulate). A "structure" config skips the
// design and builds its model with BuildStructureModel. `hooks` go to Simulate (progress,
// the caller's bytes per record for the output limit); the progress stages are "design" and
// "simulate".
// `on_design` (optional: empty) sees the design before the run starts, and may throw to stop it.
// `make_design` designs a bridge config: the verified design for tbridge simulate
// (RunSimulateScenario), the design as written for a design file (RunDesignScenario). It has no
// default, so that no caller runs the unverified equilibrium design by leaving it out.
ScenarioResult RunScenario(const Config& config, const RunHooks& hooks,
                           const std::function<void(const Design&)>& on_design,
                           const std::function<Design(const Config&)>& make_design);

// `tbridge simulate`'s scenario, and the paper's tables': RunScenario on the bridge tbridge
// design writes, verified and resized (a config with the paper's switches keeps the paper's
// design, RunDesign, which needs no check to be simulated), or on the config's custom structure.
ScenarioResult RunSimulateScenario(const Config& config, const RunHooks& hooks = {},
                                   const std::function<void(const Design&)>& on_design = {});

// `tbridge simulate DESIGN.json`: the scenario of the "dynamics" section of a written design's
// own config (its `config`), run on the design as written, or as built where its members were
// edited (io/design_reader.h). Throws ConfigError naming "config.dynamics" when the design's
// config has none.
ScenarioResult RunDesignScenario(const Design& design, const RunHooks& hooks = {},
                                 const std::function<void(const Design&)>& on_design = {});

}  // namespace tbridge
