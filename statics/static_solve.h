// Nonlinear static analysis of a prestressed tensegrity: rigid bars, elastic strings that go
// slack, large displacements.
//
// Unknowns: the free node positions x and one multiplier per bar. Equilibrium at every free
// node, f_ext + f_strings(x) + C(x)^T lambda = 0, with C the gradient of the bar constraints
// g_b = |x_j - x_i|^2 - l_b^2 = 0 (bar compression = 2 lambda_b l_b). A string pulls with
// T = k (s - L0) while s > L0, else nothing. Newton's method on the saddle-point system
//   [K_t - sum lambda_b H_b   -C^T] [dx]   [R]
//   [C                         0  ] [dl] = [-g]
// (K_t the strings' tangent stiffness, H_b the Hessian of g_b), with the load applied in
// steps from a state in equilibrium, halving a step that does not converge.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/structure.h"

namespace tbridge {

// The constant data of the analysis. Bar lengths are those of `structure.nodes`.
struct StaticModel {
  Structure structure;
  std::vector<double> string_stiffness;    // k = E A / L0 [N/m]
  std::vector<double> string_rest_length;  // L0 [m]
};

struct StaticState {
  Eigen::Matrix3Xd nodes;             // positions [m]
  Eigen::VectorXd bar_compression;    // [N], per bar (negative: tension)
  Eigen::VectorXd string_tension;     // [N], per string (0 when slack)
  Eigen::Matrix3Xd reactions;         // [N], zero at free nodes; balance the applied loads
};

struct StaticResult {
  StaticState state;
  bool converged = false;
  int newton_iterations = 0;
  int load_steps = 0;
  double residual = 0;  // largest |force imbalance| at a free node [N]
  int slack_strings = 0;
  std::string message;  // why it did not converge
};

// Equilibrium under `loads` (3 x n_n [N]), starting from `start`, a state in equilibrium under
// `start_loads` (its bar forces seed the multipliers). Planar structures move in x-y only.
StaticResult SolveStatic(const StaticModel& model, const StaticState& start, const Eigen::Matrix3Xd& start_loads,
                         const Eigen::Matrix3Xd& loads);

// The force every member exerts on the nodes of `nodes` with the given bar compressions,
// string tensions from the model (slack = 0), and the reactions that balance `loads`.
StaticState StateAt(const StaticModel& model, const Eigen::Matrix3Xd& nodes, const Eigen::VectorXd& bar_compression,
                    const Eigen::Matrix3Xd& loads);

}  // namespace tbridge
