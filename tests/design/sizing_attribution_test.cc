// The sizing's multipliers and the mass split by them: the non-negative least squares against
// enumerating every active set, the multipliers against the change of the optimum when a limit
// moves (the envelope theorem), and the split against the mass it splits.

#include "sizing/sizing_attribution.h"

#include <Eigen/QR>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "design/design.h"
#include "optim/nnls.h"
#include "optim/solvers.h"

namespace tbridge {
namespace {

// The second algorithm: every subset of columns solved by least squares; the best whose
// solution is non-negative is the minimum (the problem is convex, and its minimiser solves
// the least-squares problem on its own support).
Eigen::VectorXd BruteForceNnls(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  const int n = static_cast<int>(A.cols());
  Eigen::VectorXd best = Eigen::VectorXd::Zero(n);
  double best_residual = b.norm();
  for (int mask = 1; mask < (1 << n); ++mask) {
    std::vector<int> cols;
    for (int j = 0; j < n; ++j) {
      if (mask & (1 << j)) cols.push_back(j);
    }
    Eigen::MatrixXd sub(A.rows(), static_cast<Eigen::Index>(cols.size()));
    for (size_t k = 0; k < cols.size(); ++k) sub.col(static_cast<Eigen::Index>(k)) = A.col(cols[k]);
    const Eigen::VectorXd s = sub.completeOrthogonalDecomposition().solve(b);
    if (s.minCoeff() < 0) continue;
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
    for (size_t k = 0; k < cols.size(); ++k) z[cols[k]] = s[static_cast<Eigen::Index>(k)];
    const double residual = (A * z - b).norm();
    if (residual < best_residual) best_residual = residual, best = z;
  }
  return best;
}

TEST_CASE("non-negative least squares finds what enumerating the active sets finds",
          "[design][attribution]") {
  std::srand(7);
  for (int trial = 0; trial < 40; ++trial) {
    // Tall, square and wide problems, as the multipliers' are (variables x active rows).
    const int rows = 3 + trial % 5, cols = 2 + trial % 6;
    const Eigen::MatrixXd A = Eigen::MatrixXd::Random(rows, cols);
    const Eigen::VectorXd b = Eigen::VectorXd::Random(rows);
    double residual = 0;
    const Eigen::VectorXd z = NonNegativeLeastSquares(A, b, &residual);
    const Eigen::VectorXd ref = BruteForceNnls(A, b);
    INFO("trial " << trial << ": " << rows << " x " << cols);
    CHECK(z.minCoeff() >= 0);
    // The minimum residual is unique (the solution need not be, for wide A): both methods solve
    // least squares on a support by orthogonal factorisations, 1e-12 of |b| ~ 1.
    CHECK(residual == Approx((A * ref - b).norm()).margin(1e-12));
  }
}

Design SmallDesign() {
  Config config;  // engineering defaults at n = 2
  config.bridge.n = 2;
  return RunDesign(config);
}

// The sizing's optimum from the first design's sizes, for a deflection limit span / `limit`.
struct Optimum {
  double mass_scaled = 0;
  Eigen::VectorXd x;
};
Optimum Solve(Design d, double limit, const Eigen::VectorXd* start) {
  d.config.loads.deflection_limit = limit;
  const SizingProblem problem(d, SizingCorrections{});
  Eigen::VectorXd x =
      start ? *start : problem.VariablesOf(MemberAreas(d), problem.AlphaOf(d.reference_forces));
  SolverOptions options;
  options.tolerance = 1e-12;
  options.max_iterations = 3000;
  REQUIRE(SolveNlp(SolverKind::kNlopt, problem, options, x).success);
  return {problem.Objective(x), x};
}

TEST_CASE("the sizing's multipliers are the optimum's sensitivity to its limits",
          "[design][attribution]") {
  const Design d = SmallDesign();
  const double limit = d.config.loads.deflection_limit;
  const Optimum at = Solve(d, limit, nullptr);
  const SizingProblem problem(d, SizingCorrections{});
  Eigen::VectorXd g(problem.num_constraints()), lo, hi;
  problem.Constraints(at.x, g);
  problem.ConstraintBounds(lo, hi);
  std::vector<char> active(static_cast<size_t>(g.size()), 0);
  for (Eigen::Index r = 0; r < g.size(); ++r) active[r] = g[r] <= lo[r] + 1e-4;
  const SizingProblem posed(d, SizingCorrections{}, &active);
  const MassAttribution a = AttributeMass(posed, at.x, {}, Eigen::VectorXd());
  INFO("active rows " << a.active_rows << ", stationarity residual " << a.stationarity_residual);
  // At a converged optimum the gradient is a non-negative combination of the active rows.
  CHECK(a.stationarity_residual <= 1e-4);
  // The kinds add up to the mass: f = grad f . x (the mass is linear, zero at zero), to the
  // stationarity residual's share of it.
  double sum = 0;
  for (const double m : a.mass_by_kind_kg) sum += m;
  CHECK(sum == Approx(a.structure_kg).epsilon(10 * a.stationarity_residual + 1e-9));
  // The envelope theorem: a deflection row g = 1 - delta / delta_lim held at its margin l
  // moves by (1 - l) eps when delta_lim grows by (1 + eps), so the optimum falls by
  // eps (1 - l) sum lambda over the deflection rows. Central differences at eps = 1e-3:
  // truncation O(eps^2) relative, the solver's 1e-12; 2 % allows for the active set
  // changing within the step (a deflection row leaving it).
  double lambda_deflection = 0;
  for (int r = 0; r < posed.num_constraints(); ++r) {
    const SizingRow::Kind k = posed.rows()[r].kind;
    if (k == SizingRow::kDeflectionDown || k == SizingRow::kDeflectionUp)
      lambda_deflection += a.multipliers[r];
  }
  REQUIRE(lambda_deflection > 0);  // the default bridge's deflection limit binds
  const double eps = 1e-3;
  const Optimum looser = Solve(d, limit / (1 + eps), &at.x),
                tighter = Solve(d, limit / (1 - eps), &at.x);
  const double measured = (tighter.mass_scaled - looser.mass_scaled) / (2 * eps);
  CHECK(measured == Approx((1 - 1e-4) * lambda_deflection).epsilon(0.02));
}

}  // namespace
}  // namespace tbridge
