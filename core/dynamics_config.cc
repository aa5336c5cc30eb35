#include "core/dynamics_config.h"

#include <nlohmann/json.hpp>
#include <string>

#include "core/dynamics_fields.h"
#include "core/error.h"
#include "core/json_reader.h"

namespace tbridge {

void CheckDynamicsRules(const DynamicsConfig& d) {
  if (d.dt > d.duration) {
    throw ConfigError("dynamics.dt", std::to_string(d.dt),
                      "must not exceed duration = " + std::to_string(d.duration));
  }
  for (size_t a = 0; a < d.prestrain.size(); ++a) {
    for (size_t b = 0; b < a; ++b) {
      if (d.prestrain[a].group == d.prestrain[b].group) {
        throw ConfigError("dynamics.prestrain[" + std::to_string(a) + "].group",
                          std::string("\"") + NameOf(d.prestrain[a].group) + "\"",
                          "each group at most once");
      }
    }
  }
  for (size_t k = 0; k < d.loads.size(); ++k) {
    if (d.loads[k].t_end <= d.loads[k].t_start) {
      throw ConfigError("dynamics.loads[" + std::to_string(k) + "].t_end",
                        std::to_string(d.loads[k].t_end),
                        "must be greater than t_start = " + std::to_string(d.loads[k].t_start));
    }
    const LoadStepConfig& l = d.loads[k];
    if (l.rise_s + l.fall_s > l.t_end - l.t_start) {
      throw ConfigError(
          "dynamics.loads[" + std::to_string(k) + "].rise_s", std::to_string(l.rise_s),
          "rise_s + fall_s (" + std::to_string(l.rise_s + l.fall_s) +
              ") must fit in t_end - t_start = " + std::to_string(l.t_end - l.t_start));
    }
  }
}

DynamicsConfig ParseDynamicsConfig(JsonSection section) {
  return ParseSection<DynamicsConfig>(section, CheckDynamicsRules);
}

nlohmann::json ToJson(const DynamicsConfig& d) { return EchoFields(d); }

}  // namespace tbridge
