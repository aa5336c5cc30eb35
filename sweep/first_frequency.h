// The lowest linearised natural frequency of a dynamic model, for the outer loop's frequency
// constraint, without the full dense eigen-decomposition of dynamics/modal.h.
//
// Small models (at most `dense_max_dofs` free DOFs) take every mode densely; larger ones the
// lowest mode alone from ComputeModes' sparse solver (shift-invert Lanczos by Spectra on the
// sparse null-space-reduced pencil; dynamics/modal.h says why and what it costs).
#pragma once

#include <string>

#include "dynamics/model.h"

namespace tbridge {

struct FirstFrequencyOptions {
  int dense_max_dofs = 300;  // at or below: every mode densely (exact, cheap enough)
  double tolerance = 1e-10;  // relative Ritz residual for convergence of the sparse solver
};

struct FirstFrequency {
  double omega_rad_s = 0;  // lowest omega; negative (-sqrt(-omega^2)) for an unstable mode
  std::string method;      // "dense" | "sparse"
  int iterations = 0;      // Lanczos restarts of the sparse solver; 0 for dense
};

// Throws ModelError when the model is inconsistent (see Linearise), has no free degree of
// freedom, its shifted constrained stiffness is singular (a mechanism the bar constraints do
// not remove) or the eigensolver does not converge.
FirstFrequency LowestFrequency(const DynamicModel& model,
                               const FirstFrequencyOptions& options = {});

}  // namespace tbridge
