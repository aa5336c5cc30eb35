// The model `tbridge modes` analyses: a config's custom "structure", or the verified bridge
// the config designs (the bridge tbridge design writes), with ModalModelOptions.
#pragma once

#include <optional>

#include "core/config.h"
#include "core/progress.h"
#include "design/design.h"
#include "dynamics/model.h"

namespace tbridge {

struct ModalScene {
  std::optional<Design> design;  // empty for a "structure" config
  DynamicModel model;
};

// Throws ConfigError for a bad config, ModelError when no design is found.
ModalScene ModalSceneOf(const Config& config, ProgressReporter* progress = nullptr);

}  // namespace tbridge
