// A certificate that a point is a local minimum, from the Karush-Kuhn-Tucker conditions and
// the second-order condition, independent of the solver that found it. The program, in its
// scaled variables x (n of them):
//
//   min f(x)   s.t.   lo_x <= x <= hi_x,   g_r(x) >= lo_r   (r = 0..m-1).
//
// At a local minimum grad f = J_A^T lambda + mu_lo - mu_hi with lambda, mu >= 0 on the active
// rows and bounds (mu_lo on lower bounds, mu_hi on upper). The multipliers come from that
// equation by non-negative least squares (optim/nnls.h), so a solver's own multipliers are
// neither needed nor trusted; what remains of the equation is the stationarity residual. The
// second-order condition is checked on the Lagrangian's Hessian reduced to the tangent space
// of the strongly active constraints, from finite differences of its gradient; at a vertex
// (that space empty) the first-order conditions suffice.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

namespace tbridge {

struct KktInput {
  Eigen::VectorXd x, lo_x, hi_x;  // n; the bounds may be -inf / +inf
  Eigen::VectorXd grad_f;         // n: grad f(x)
  // g_r(x) - lo_r for every row of the whole problem (not only the active ones): the
  // feasibility is the largest violation over all of them. NaN counts as violated.
  Eigen::VectorXd slack;
  // The rows (indices into `slack`) the caller deems active; only they may carry multipliers.
  std::vector<int> active;
  Eigen::MatrixXd jac_active;  // active.size() x n: grad g_r(x) of the active rows, by row
  // grad f and jac_active (same rows, same order) at another point y, for the second-order
  // finite differences; y is x moved by about 1e-6 max(1, |x|_inf) and may lie just outside
  // the bounds. Empty: only a vertex can pass the second-order test.
  std::function<void(const Eigen::VectorXd& y, Eigen::VectorXd& grad_f, Eigen::MatrixXd& jac)> at;
  // A bound is active where x lies within this of it, times max(1, |bound|).
  double active_tolerance = 1e-6;
};

struct KktCertificate {
  // |grad f - J_A^T lambda - mu_lo + mu_hi|_inf / |grad f|_inf (the divisor 1 when grad f = 0).
  double stationarity = 0;
  // The largest violation max(0, lo_r - g_r) over every row and max(0, lo_x - x, x - hi_x) over
  // the variables, in their own units (absolute: the variables and rows are scaled).
  double feasibility = 0;
  // max lambda_r |g_r - lo_r| over the active rows and mu_i |x_i - bound_i| over the active
  // bounds, divided as the stationarity.
  double complementarity = 0;
  double largest_multiplier = 0;  // over rows and bounds
  bool second_order = false;
  bool proved_local_optimum = false;
  int active_rows = 0;           // active.size()
  int active_bounds = 0;         // lower and upper bounds within active_tolerance
  int free_variables = 0;        // variables at neither bound
  int null_space_dimension = 0;  // n minus the rank of the strongly active normals
  // The smallest eigenvalue of the reduced Hessian (NaN where none was formed).
  double smallest_curvature = 0;
  std::string second_order_by;  // "vertex", "reduced Hessian", or "" where it failed
  std::string failed;           // what failed, e.g. "stationarity 3.2e-03 > 1.0e-06"; "" proved
  Eigen::VectorXd multipliers;  // per active row, in the order of `active`
  Eigen::VectorXd bound_multipliers;  // n: mu_lo - mu_hi (> 0 on a lower, < 0 on an upper bound)
};

// Certifies `in.x` with every measure <= `tolerance`. The second-order test costs
// 2 null_space_dimension calls of `in.at`. Throws std::invalid_argument on mismatched sizes, an
// active index outside `slack`, or a non-finite x, grad_f or jac_active (and on wrong sizes
// or non-finite values returned by `at`).
KktCertificate CertifyLocalOptimum(const KktInput& in, double tolerance = 1e-6);

}  // namespace tbridge
