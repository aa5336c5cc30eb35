#include "sweep/first_frequency.h"

#include "core/error.h"
#include "dynamics/modal.h"

namespace tbridge {

FirstFrequency LowestFrequency(const DynamicModel& model, const FirstFrequencyOptions& options) {
  ModalOptions modal;
  modal.count = 1;
  modal.dense_max_dofs = options.dense_max_dofs;
  modal.tolerance = options.tolerance;
  modal.highest = false;  // the frequency constraint needs only the lowest mode
  const ModalResult modes = ComputeModes(model, modal);
  if (modes.modes.empty())
    throw ModelError("first frequency: the model has no free degree of freedom");
  FirstFrequency out;
  out.omega_rad_s = modes.modes.front().omega_rad_s;
  out.method = modes.solver;
  out.iterations = modes.iterations;
  return out;
}

}  // namespace tbridge
