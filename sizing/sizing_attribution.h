// What drives the mass of a verified sizing (docs/verified_sizing.md): the constraints'
// Lagrange multipliers at the solution, and the structure's mass split among the kinds of
// constraint by them.
//
// At a minimum of f(x) subject to g_r(x) >= l_r and x >= x_min, the gradient of the mass is
// a non-negative combination of the active constraints' gradients:
//   grad f = sum_r lambda_r grad g_r + mu,   lambda, mu >= 0.
// The multipliers come from that equation by non-negative least squares (optim/nnls.h), for
// any solver. The mass is linear in the variables and zero at zero, so f = grad f . x and a
// change df = grad f . dx exactly; the terms lambda_r grad g_r . x of the rows of a kind K
// (and mu . x of the minimum sizes) are the mass that K costs, the prestress included (more
// prestress for stiffness shows as strength mass moved to the deflection rows), and the kinds
// add up to the structure's mass up to the stationarity residual. Along dx from the first
// design the same terms split the premium.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "design/verification.h"
#include "sizing/sizing_problem.h"

namespace tbridge {

// The attribution at `x` of `problem` (the rows it poses; pass the active ones). `dynamic[j]`:
// the share of member j's strength demand that the dynamic runs add over the static cases,
// 1 - static / dynamic utilisation (0 when the static cases govern): that share of its
// strength rows' mass counts as "dynamics".
// `reference_x` (the first design's variables; empty: none) gives the premium split.
MassAttribution AttributeMass(const SizingProblem& problem, const Eigen::VectorXd& x,
                              const std::vector<double>& dynamic,
                              const Eigen::VectorXd& reference_x);

}  // namespace tbridge
