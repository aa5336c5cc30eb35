// The lowest linearised natural frequency of a dynamic model, for the outer loop's frequency
// constraint, without the full dense eigen-decomposition of dynamics/modal.h.
//
// Small models (at most `dense_max_dofs` free DOFs) use ComputeModes. Larger ones use
// shift-invert Lanczos on the constrained problem: each step solves the sparse saddle-point
// system
//   [K - sigma M   C^T] [y ]   [M v]
//   [C             0  ] [mu] = [ 0 ]
// (K, M, C from Linearise: tangent stiffness, mass and bar-length constraint Jacobian), whose
// y is (Z^T (K - sigma M) Z)^-1 Z^T M v in full coordinates, Z a null-space basis of C. The
// Lanczos basis is M-orthonormal with full re-orthogonalisation; its largest Ritz value theta
// gives omega^2 = sigma + 1/theta. One sparse LU of size n_dof + n_b replaces the O(n_dof^3)
// dense solve: planar n = 8 (1020 DOFs) drops from about 1 s to a few ms.
#pragma once

#include <string>

#include "dynamics/model.h"

namespace tbridge {

struct FirstFrequencyOptions {
  int dense_max_dofs = 300;      // at or below: ComputeModes (exact, cheap enough)
  int max_lanczos_steps = 120;   // Krylov dimension limit
  double tolerance = 1e-10;      // relative Ritz residual for convergence
};

struct FirstFrequency {
  double omega_rad_s = 0;  // lowest omega; negative (-sqrt(-omega^2)) for an unstable mode
  std::string method;      // "dense" | "lanczos"
  int lanczos_steps = 0;   // 0 for dense
};

// Throws ModelError when the model is inconsistent (see Linearise), the saddle-point system is
// singular (a mechanism the bar constraints do not remove) or Lanczos does not converge.
FirstFrequency LowestFrequency(const DynamicModel& model, const FirstFrequencyOptions& options = {});

}  // namespace tbridge
