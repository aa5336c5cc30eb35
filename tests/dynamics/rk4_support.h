// Fixed-step RK4 runs for the engine tests.
#pragma once

#include <Eigen/Core>

#include "dynamics/class1.h"
#include "dynamics/integrators.h"
#include "dynamics/workspace.h"

namespace tbridge::test {

// Fixed-step RK4 on `ode` from y for `steps` steps of dt, calling `each(step, t, y)` after
// every step.
template <class Each>
Eigen::VectorXd RunRk4(OdeSystem& ode, Eigen::VectorXd y, double dt, long steps, Each each) {
  Rk4Workspace ws(ode.size());
  for (long k = 0; k < steps; ++k) {
    Rk4Step(ode, k * dt, dt, y, ws);
    each(k + 1, (k + 1) * dt, y);
  }
  return y;
}

// The same on a class-1 system, final state only.
inline Eigen::VectorXd RunRk4(const Class1System& system, Eigen::VectorXd y, double dt,
                              long steps) {
  Class1Ode ode(system);
  return RunRk4(ode, std::move(y), dt, steps, [](long, double, const Eigen::VectorXd&) {});
}

}  // namespace tbridge::test
