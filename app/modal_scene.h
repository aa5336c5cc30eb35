// The model `tbridge modes` analyses: a config's custom "structure", or the verified bridge
// the config designs (the bridge tbridge design writes), with ModalModelOptions.
#pragma once

#include <optional>
#include <string>

#include "core/config.h"
#include "core/progress.h"
#include "design/design.h"
#include "dynamics/model.h"

namespace tbridge {

struct ModalScene {
  std::optional<Design> design;  // empty for a "structure" config
  DynamicModel model;
};

// `mass_model`: "design" (the deck and payload as the runs have them), or the comfort check's
// "crowd" or "empty" deck (verify/comfort_check.h), for a bridge config. Throws ConfigError
// for a bad config, ModelError when no design is found.
ModalScene ModalSceneOf(const Config& config, ProgressReporter* progress = nullptr,
                        const std::string& mass_model = "design");

}  // namespace tbridge
