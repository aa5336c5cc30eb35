#include "app/modal_scene.h"

#include "bridge/design_model.h"
#include "dynamics/structure_model.h"
#include "verify/verified_design.h"

namespace tbridge {

ModalScene ModalSceneOf(const Config& config, ProgressReporter* progress) {
  const ModelOptions options = ModalModelOptions(config);
  ModalScene scene;
  if (config.structure) {
    scene.model = BuildStructureModel(*config.structure, options);
    return scene;
  }
  scene.design = DesignAndVerify(config, progress);
  scene.model = BuildDynamicModel(*scene.design, options);
  return scene;
}

}  // namespace tbridge
