// The summary of a dynamic run, as `tbridge simulate` writes it (summary.json): the resolved
// config, the model's geometry, frequency, stresses, slack events, bar-length error and energy
// balance.
#pragma once

#include <nlohmann/json.hpp>

#include "core/config.h"
#include "dynamics/model.h"
#include "dynamics/simulation.h"

namespace tbridge {

nlohmann::json SummaryJson(const Config& config, const DynamicModel& model,
                           const SimulationResult& result);

}  // namespace tbridge
