// The reciprocal (CONLIN) curvature of a sizing program's Lagrangian in one positive variable
// (Fleury and Braibant 1986). A row g_r that rises with x_j is expanded in 1 / x_j,
//   g_r ~ g_r0 + (dg_r/dx_j) x_j0 (1 - x_j0 / x_j),
// as a member's stress, its buckling margin and a deflection behave in its area; the expansion's
// second derivative at x_j0 is -2 (dg_r/dx_j) / x_j0. For L = f - sum_r lambda_r g_r with
// lambda_r >= 0 on a binding row g_r >= lo_r, each row that rises with x_j adds
// 2 lambda_r (dg_r/dx_j) / x_j, and the objective, where it falls with x_j, its own
// 2 (-df/dx_j) / x_j; a row that falls with x_j is linear in it (conservative). The sum is
// never negative, so the diagonal it forms is a convex model.
//
// The one statement of it: the SQP's Hessian (optim/sqp_solver.cc) and the sizing program's
// HessianValues, which Ipopt reads (sizing/sizing_problem.cc).
#pragma once

#include <Eigen/Core>
#include <algorithm>

namespace tbridge {

// `column`: dg_r/dx_j over the rows; `multipliers`: lambda_r (a negative one counts as zero);
// `objective_slope`: df/dx_j. x_j > 0.
inline double ReciprocalCurvature(double x_j, const Eigen::Ref<const Eigen::VectorXd>& column,
                                  const Eigen::Ref<const Eigen::VectorXd>& multipliers,
                                  double objective_slope) {
  const double raise = (column.array().max(0.0) * multipliers.array().max(0.0)).sum();
  return 2.0 / x_j * (raise + std::max(0.0, -objective_slope));
}

}  // namespace tbridge
