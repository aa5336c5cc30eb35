#include "app/modal_scene.h"

#include "bridge/design_model.h"
#include "checks/comfort_check.h"
#include "dynamics/structure_model.h"
#include "sizing/verified_design.h"

namespace tbridge {

ModalScene ModalSceneOf(const Config& config, ProgressReporter* progress,
                        ModalMassModel mass_model) {
  const ModelOptions options = ModalModelOptions(config);
  ModalScene scene;
  if (config.structure) {
    scene.model = BuildStructureModel(*config.structure, options);
    return scene;
  }
  scene.design = DesignAndVerify(config, progress);
  scene.model = mass_model == ModalMassModel::kDesign
                    ? BuildDynamicModel(*scene.design, options)
                    : ComfortModel(*scene.design, mass_model == ModalMassModel::kCrowd);
  return scene;
}

}  // namespace tbridge
