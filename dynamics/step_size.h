// Step sizes from the highest linearised frequency, found without a modal analysis.
//
// omega_max^2 is the spectral radius of da/dx, the position Jacobian of the accelerations
// (for a linearised undamped structure a = -M^-1 K x on the constraint manifold). Power
// iteration on forward-difference products da/dx w costs one right-hand-side evaluation per
// iteration, so this is linear in the number of members, where ComputeModes (dynamics/modal.h)
// is a dense O(n_dof^3) solve (about 7 s at planar n = 9 and 8x that per level after).
#pragma once

#include <Eigen/Core>

#include "dynamics/integrators.h"

namespace tbridge {

struct FrequencyBoundOptions {
  int max_iterations = 1000;
  // Stop when the estimate changes by less than this per iteration (relative). Close top
  // frequencies converge slowly from below, so this is tight.
  double tolerance = 1e-6;
  double increment = 1e-7;  // forward-difference step, relative to the largest |x| (>= 1 m)
};

struct FrequencyBound {
  double omega_max = 0;  // [rad/s]
  int iterations = 0;
  bool converged = false;
};

// omega_max of `system` (second order, state (x, v) as in dynamics/class1.h) linearised at
// the positions of `y` with zero velocity. Deterministic (fixed start vector). Throws
// ModelError when an evaluation is not finite.
FrequencyBound HighestFrequency(OdeSystem& system, const Eigen::VectorXd& y,
                                const FrequencyBoundOptions& options = {});

// RK4's stability limit on the imaginary axis for frequency omega: 2 sqrt(2) / omega [s].
double Rk4StepLimit(double omega_max);

}  // namespace tbridge
