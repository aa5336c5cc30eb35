// One dynamic scenario end to end: config -> design -> dynamic model -> simulation, or, for a
// custom scene, config -> structure model -> simulation.
#pragma once

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
ScenarioResult RunScenario(const Config& config, const RunHooks& hooks = {});

}  // namespace tbridge
