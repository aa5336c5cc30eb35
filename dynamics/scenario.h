// One dynamic scenario end to end: config -> design -> dynamic model -> simulation.
#pragma once

#include <vector>

#include "core/config.h"
#include "design/design.h"
#include "dynamics/model.h"
#include "dynamics/simulation.h"

namespace tbridge {

struct ScenarioResult {
  Design design;
  DynamicModel model;
  SimulationResult simulation;
};

// Throws ConfigError when `config` has no "dynamics" section (or a bad one), ModelError when
// the design or the run fails (see RunDesign and Simulate).
ScenarioResult RunScenario(const Config& config);

}  // namespace tbridge
