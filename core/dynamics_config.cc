#include "core/dynamics_config.h"

#include <nlohmann/json.hpp>

#include "core/json_reader.h"

namespace tbridge {

DynamicsConfig ParseDynamicsConfig(JsonSection s) {
  DynamicsConfig d;
  d.duration = s.Number("duration", d.duration, Range::Positive());
  d.dt = s.Number("dt", d.dt, Range::Positive());
  s.Finish();
  return d;
}

nlohmann::json ToJson(const DynamicsConfig& d) {
  return {{"duration", d.duration}, {"dt", d.dt}};
}

}  // namespace tbridge
