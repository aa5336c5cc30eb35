#include "dynamics/scenario.h"

#include "core/error.h"

namespace tbridge {

ScenarioResult RunScenario(const Config& config) {
  if (!config.dynamics) {
    throw ConfigError("dynamics", "(missing)", "a dynamic scenario needs a \"dynamics\" section");
  }
  const DynamicsConfig& dc = *config.dynamics;
  ScenarioResult r;
  r.design = RunDesign(config);
  const ModelOptions options = ModelOptionsOf(dc);
  r.model = BuildDynamicModel(r.design, options);
  r.simulation = Simulate(r.model, dc, ReportPrestrain(r.model, r.design, options));
  return r;
}

}  // namespace tbridge
