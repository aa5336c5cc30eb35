#include "app/scenario.h"

#include "bridge/design_model.h"
#include "core/error.h"
#include "core/progress.h"
#include "dynamics/structure_model.h"
#include "sizing/verified_design.h"

namespace tbridge {

ScenarioResult RunScenario(const Config& config, const RunHooks& hooks,
                           const std::function<void(const Design&)>& on_design,
                           const std::function<Design(const Config&)>& make_design) {
  if (!config.dynamics) {
    throw ConfigError("dynamics", "(missing)", "a dynamic scenario needs a \"dynamics\" section");
  }
  const DynamicsConfig& dc = *config.dynamics;
  CheckStepLimit(dc);  // before the design, which may take a while itself
  ScenarioResult r;
  const ModelOptions options = ModelOptionsOf(dc);
  if (config.structure) {
    r.model = BuildStructureModel(*config.structure, options);
    if (hooks.progress != nullptr) hooks.progress->Stage(hooks.stage_prefix + "simulate");
    r.simulation = Simulate(r.model, dc, {}, hooks);
    return r;
  }
  if (hooks.progress != nullptr) hooks.progress->Stage(hooks.stage_prefix + "design");
  r.design = make_design(config);
  if (on_design) on_design(r.design);
  r.model = BuildDynamicModel(r.design, options);
  if (hooks.progress != nullptr) hooks.progress->Stage(hooks.stage_prefix + "simulate");
  r.simulation = Simulate(r.model, dc, ReportPrestrain(r.model, r.design, options), hooks);
  return r;
}

ScenarioResult RunSimulateScenario(const Config& config, const RunHooks& hooks,
                                   const std::function<void(const Design&)>& on_design) {
  const auto paper = [](const Config& c) { return RunDesign(c); };
  const auto verified = [](const Config& c) { return DesignAndVerify(c); };
  return RunScenario(
      config, hooks, on_design,
      KeepsPaperSwitches(config) ? std::function<Design(const Config&)>{paper} : verified);
}

ScenarioResult RunDesignScenario(const Design& design, const RunHooks& hooks,
                                 const std::function<void(const Design&)>& on_design) {
  if (!design.config.dynamics) {
    throw ConfigError(
        "config.dynamics", "(missing)",
        "a design file simulated needs a \"dynamics\" section in its config (configs/README.md): "
        "add one there, or to the config it was designed from");
  }
  return RunScenario(design.config, hooks, on_design, [&design](const Config&) { return design; });
}

}  // namespace tbridge
