// What an FE program needs of a design to analyse it as tbridge does: the drawn geometry and
// its supports, each member's axial stiffness and reference force, the masses of the modal
// model, and the node loads of every load case and travelling station. The writers for each
// program (export/calculix.h, export/opensees.h) only format it.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "design/design.h"
#include "dynamics/model.h"
#include "statics/static_solve.h"

namespace tbridge {

// One static analysis: node loads [N] (3 x n_n) and what tbridge calls it ("uls_travelling at
// node 5", "reference").
struct FeLoadStep {
  std::string label;
  Eigen::Matrix3Xd loads;
};

struct FeModel {
  StaticModel statics;  // drawn geometry, supports, each string's k = E A / L0 and L0
  StaticState
      reference;  // the drawn geometry in equilibrium: bar compressions, string tensions [N]
  double youngs_modulus = 0;  // the bars' E [Pa] (the strings' is in their stiffness)
  std::vector<double> bar_area, string_area;  // [m^2]
  Eigen::Matrix3Xd reference_loads;           // 3 x n_n [N], the reference state's
  std::vector<FeLoadStep> cases;              // every case, a travelling one at every station
  // The model `tbridge modes` analyses (bridge/design_model.h, ModalModelOptions): its bar
  // masses (string shares included, spread uniformly along the bar), node masses, and the
  // loads whose equilibrium the modes are linearised about.
  DynamicModel modal;
};

// Throws ModelError when the reference state does not stand (the static model's forces).
FeModel FeModelOf(const Design& design);

}  // namespace tbridge
