// The model `tbridge modes` analyses: a config's custom "structure", or the verified bridge
// the config designs (the bridge tbridge design writes), with ModalModelOptions.
#pragma once

#include <optional>
#include <string>

#include "core/config.h"
#include "core/named_choice.h"
#include "core/progress.h"
#include "design/design.h"
#include "dynamics/model.h"

namespace tbridge {

// A bridge's mass model for its modes (tbridge modes --mass): the deck and payload as the runs
// have them, or the comfort check's deck with the traffic class's pedestrians or with none
// (checks/comfort_check.h).
enum class ModalMassModel { kDesign, kCrowd, kEmpty };
inline constexpr std::array<Named<ModalMassModel>, 3> kModalMassModelNames{
    {{ModalMassModel::kDesign, "design"},
     {ModalMassModel::kCrowd, "crowd"},
     {ModalMassModel::kEmpty, "empty"}}};
inline const char* NameOf(ModalMassModel k) { return NameIn(kModalMassModelNames, k); }

struct ModalScene {
  std::optional<Design> design;  // empty for a "structure" config
  DynamicModel model;
};

// `mass_model`: see ModalMassModel; a structure config gives its own masses. Throws ConfigError
// for a bad config, ModelError when no design is found.
ModalScene ModalSceneOf(const Config& config, ProgressReporter* progress = nullptr,
                        ModalMassModel mass_model = ModalMassModel::kDesign);

}  // namespace tbridge
