#include "dynamics/scenario.h"

#include "core/error.h"
#include "dynamics/structure_model.h"

namespace tbridge {

ScenarioResult RunScenario(const Config& config) {
  if (!config.dynamics) {
    throw ConfigError("dynamics", "(missing)", "a dynamic scenario needs a \"dynamics\" section");
  }
  const DynamicsConfig& dc = *config.dynamics;
  ScenarioResult r;
  const ModelOptions options = ModelOptionsOf(dc);
  if (config.structure) {
    r.model = BuildStructureModel(*config.structure, options);
    r.simulation = Simulate(r.model, dc);
    return r;
  }
  r.design = RunDesign(config);
  r.model = BuildDynamicModel(r.design, options);
  r.simulation = Simulate(r.model, dc, ReportPrestrain(r.model, r.design, options));
  return r;
}

}  // namespace tbridge
