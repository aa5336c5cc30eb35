#include "truss/truss_design.h"

#include "core/error.h"
#include "design/solvers.h"

namespace tbridge {

TrussDesign DesignTruss(const Config& config) {
  if (config.design.solver == "direct") {
    throw ConfigError(
        "design.solver", "\"direct\"",
        "a structure is sized by an iterative solver: \"auto\", or one of those built in");
  }
  RequireSolverBuiltIn(config.design.solver);
  TrussDesign d{config, BuildTrussModel(config), {}, {}};
  d.sizing = SizeTruss(d.model, config.design.solver, config.design.tolerance,
                       config.design.max_iterations);
  d.check = CheckTruss(d.model, d.sizing.group_areas);
  return d;
}

}  // namespace tbridge
