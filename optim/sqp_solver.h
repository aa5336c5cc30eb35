// Sequential quadratic programming with a diagonal, conservative Hessian for sizing problems:
// inequality rows g(x) >= g_lo, positive variables (areas) and a few free ones (prestress).
//
// At each iterate every row is approximated, in each positive variable x_j that raises it, by
// its reciprocal expansion g ~ g_0 + dg/dx_j x_j0 (1 - x_j0 / x_j) (CONLIN, Fleury and
// Braibant 1986): a member's stress, a buckling row and a deflection row of a structure all
// behave so in its members' areas. Their second derivatives, -2 (dg/dx_j) / x_j, weighted by
// the last multipliers, give the Lagrangian's diagonal Hessian, or a diagonal secant estimate
// where that is larger (alone for a free variable). The quadratic subproblem
// (optim/dense_qp.h) carries the rows' linearisation and a move limit per variable (a trust
// region: x_j / (1 + r_j) .. x_j (1 + r_j) for a positive one), and an l1 merit function, with
// a second-order correction, accepts or shortens its step.
//
// Why not NLopt's SLSQP: its quasi-Newton Hessian starts from the identity at every solve and
// learns the curvature over about as many iterations as there are variables (the default at
// n = 6: 116 evaluations for 128 variables, 20 ms each in its dense subproblem), where the
// structure's own curvature is known from the first gradient.
#pragma once

#include <Eigen/Core>

#include "optim/nlp.h"

namespace tbridge {

// `x`: the start on entry, the solution on return. Only inequality rows (g_hi = +inf, finite
// g_lo); throws std::logic_error otherwise. options.max_iterations bounds the evaluations of
// the rows, options.tolerance the relative change of the objective and the rows' violation
// at which it stops.
SolverOutcome SolveWithSqp(const NlpProblem& problem, const SolverOptions& options,
                           Eigen::VectorXd& x);

}  // namespace tbridge
