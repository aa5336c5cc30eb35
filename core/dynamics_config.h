// Config of a dynamic scenario (the "dynamics" section). Plain data with defaults (SI units).
#pragma once

#include <nlohmann/json_fwd.hpp>

namespace tbridge {

class JsonSection;

struct DynamicsConfig {
  double duration = 1.0;  // simulated time [s]
  double dt = 1e-5;       // fixed time step [s]
};

DynamicsConfig ParseDynamicsConfig(JsonSection section);
nlohmann::json ToJson(const DynamicsConfig& config);

}  // namespace tbridge
