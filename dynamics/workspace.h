// Scratch buffers of the dynamics engines and integrators. Each is sized once from the
// system it serves; stepping only reads and writes them, so a step allocates nothing.
#pragma once

#include <Eigen/Core>

#include "dynamics/node_forces.h"

namespace tbridge {

// The class-1 right-hand side: non-bar node forces, dim x n_n packed node-major [N]; what the
// last evaluation found: the bar force densities per model bar [N/m] and the dampers' power [W].
// When record_strings is set, the next evaluation writes each string's geometry there (one per
// model string) and clears it.
struct Class1Workspace {
  Eigen::VectorXd force;
  Eigen::VectorXd lambda;
  double damper_power = 0;
  const StringGeometry* record_strings = nullptr;
  explicit Class1Workspace(int coordinates = 0, int bars = 0)
      : force(Eigen::VectorXd::Zero(coordinates)), lambda(Eigen::VectorXd::Zero(bars)) {}
};

// Classical RK4: the four stage slopes and the stage state (each of the state's size), and the
// dampers' power at the first stage [W].
struct Rk4Workspace {
  Eigen::VectorXd k1, k2, k3, k4, stage;
  double first_power = 0;
  explicit Rk4Workspace(int size = 0)
      : k1(Eigen::VectorXd::Zero(size)),
        k2(Eigen::VectorXd::Zero(size)),
        k3(Eigen::VectorXd::Zero(size)),
        k4(Eigen::VectorXd::Zero(size)),
        stage(Eigen::VectorXd::Zero(size)) {}
};

// Dormand-Prince 5(4): seven stage slopes (k1 and k7 swap roles under FSAL), the stage state,
// the candidate solution, and the five coefficient vectors of the dense output.
struct Dopri5Workspace {
  Eigen::VectorXd k[7];
  Eigen::VectorXd stage, y_new;
  Eigen::VectorXd dense[5];
  explicit Dopri5Workspace(int size = 0) {
    for (Eigen::VectorXd& v : k) v = Eigen::VectorXd::Zero(size);
    for (Eigen::VectorXd& v : dense) v = Eigen::VectorXd::Zero(size);
    stage = Eigen::VectorXd::Zero(size);
    y_new = Eigen::VectorXd::Zero(size);
  }
};

}  // namespace tbridge
