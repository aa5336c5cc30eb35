// The sizing's sequential quadratic programming against closed-form optima and against a
// second algorithm (NLopt's SLSQP) on the verified sizing problem itself.

#include "optim/sqp_solver.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <limits>

#include "design/design.h"
#include "optim/solvers.h"
#include "sizing/sizing_problem.h"

namespace tbridge {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// min  w^T x + c y  s.t. rows(x, y) >= 0, x >= floor: a small program with positive variables
// x (areas) and optionally one free variable y (a prestress), dense Jacobian.
class SmallProgram : public NlpProblem {
 public:
  using Rows =
      std::function<void(const Eigen::Ref<const Eigen::VectorXd>&, Eigen::Ref<Eigen::VectorXd>)>;
  SmallProgram(Eigen::VectorXd weights, int positive, int rows, Rows g)
      : w_(std::move(weights)), positive_(positive), rows_(rows), g_(std::move(g)) {
    for (int r = 0; r < rows_; ++r) {
      for (int c = 0; c < num_variables(); ++c) pattern_.emplace_back(r, c);
    }
  }
  int num_variables() const override { return static_cast<int>(w_.size()); }
  int num_constraints() const override { return rows_; }
  void VariableBounds(Eigen::VectorXd& lo, Eigen::VectorXd& hi) const override {
    lo = Eigen::VectorXd::Constant(num_variables(), -kInf);
    lo.head(positive_).setConstant(0.01);
    hi = Eigen::VectorXd::Constant(num_variables(), kInf);
  }
  void ConstraintBounds(Eigen::VectorXd& lo, Eigen::VectorXd& hi) const override {
    lo = Eigen::VectorXd::Zero(rows_);
    hi = Eigen::VectorXd::Constant(rows_, kInf);
  }
  double Objective(const Eigen::Ref<const Eigen::VectorXd>& x) const override { return w_.dot(x); }
  void ObjectiveGradient(const Eigen::Ref<const Eigen::VectorXd>&,
                         Eigen::Ref<Eigen::VectorXd> grad) const override {
    grad = w_;
  }
  void Constraints(const Eigen::Ref<const Eigen::VectorXd>& x,
                   Eigen::Ref<Eigen::VectorXd> g) const override {
    g_(x, g);
  }
  const Pattern& JacobianPattern() const override { return pattern_; }
  // Central differences at 1e-7: the rows are smooth, O(1), so the derivatives carry ~1e-9
  // error, far inside the 1e-6 tolerance the solver stops at.
  void JacobianValues(const Eigen::Ref<const Eigen::VectorXd>& x, double* values) const override {
    Eigen::VectorXd xp = x, gp(rows_), gm(rows_);
    for (int c = 0; c < num_variables(); ++c) {
      const double h = 1e-7 * std::max(1.0, std::abs(x[c]));
      xp[c] = x[c] + h;
      g_(xp, gp);
      xp[c] = x[c] - h;
      g_(xp, gm);
      xp[c] = x[c];
      for (int r = 0; r < rows_; ++r) values[r * num_variables() + c] = (gp[r] - gm[r]) / (2 * h);
    }
  }
  const Pattern& HessianPattern() const override { return hessian_; }
  void HessianValues(const Eigen::Ref<const Eigen::VectorXd>&, double, const double*,
                     double*) const override {}

 private:
  Eigen::VectorXd w_;
  int positive_, rows_;
  Rows g_;
  Pattern pattern_, hessian_;
};

SolverOutcome Solve(const NlpProblem& program, Eigen::VectorXd& x, double tolerance) {
  SolverOptions options;
  options.tolerance = tolerance;
  options.max_iterations = 3000;
  return SolveWithSqp(program, options, x);
}

TEST_CASE("SQP: the reciprocal program's optimum in closed form", "[sqp]") {
  // min x1 + 2 x2 s.t. 1 - 1/x1 - 1/x2 >= 0 (a two-member stiffness row): stationarity gives
  // x1 = 1 + sqrt(2), x2 = x1 / sqrt(2), the mass (1 + sqrt(2))^2.
  const SmallProgram program(Eigen::Vector2d(1, 2), 2, 1,
                             [](const auto& x, auto g) { g[0] = 1 - 1 / x[0] - 1 / x[1]; });
  Eigen::VectorXd x = Eigen::Vector2d(10, 0.5);  // infeasible start, far from the optimum
  const SolverOutcome out = Solve(program, x, 1e-10);
  INFO(out.status << " after " << out.iterations);
  REQUIRE(out.success);
  const double r2 = std::sqrt(2.0);
  // 1e-7: the solver stops on a change of 1e-10 of the objective. The active row fixes the
  // point along its normal; along the row the objective is flat to first order, so the error
  // there is up to the square root of the stop (measured below 1e-7).
  CHECK(x[0] == Approx(1 + r2).epsilon(1e-7));
  CHECK(x[1] == Approx((1 + r2) / r2).epsilon(1e-7));
  CHECK(out.objective == Approx((1 + r2) * (1 + r2)).epsilon(1e-9));
  // The reciprocal curvature is this row's own: a handful of evaluations.
  CHECK(out.iterations <= 30);
}

TEST_CASE("SQP: a free variable and a row that couples it", "[sqp]") {
  // min x1 + x2 - y s.t. x1 x2 - 1 - y^2 >= 0: for each y, x1 = x2 = sqrt(1 + y^2); then
  // 2 y / sqrt(1 + y^2) = 1 gives y = 1/sqrt(3), x = 2/sqrt(3), the objective sqrt(3).
  const SmallProgram program(Eigen::Vector3d(1, 1, -1), 2, 1,
                             [](const auto& x, auto g) { g[0] = x[0] * x[1] - 1 - x[2] * x[2]; });
  Eigen::VectorXd x = Eigen::Vector3d(3, 3, 0);
  const SolverOutcome out = Solve(program, x, 1e-10);
  INFO(out.status << " after " << out.iterations);
  REQUIRE(out.success);
  const double r3 = std::sqrt(3.0);
  // 3e-5 on the variables, 1e-9 on the objective: the objective is flat to first order at
  // the optimum, so a stop at 1e-10 of it leaves the variables about its square root, 1e-5,
  // away (measured 4e-6 and 2e-5).
  CHECK(x[0] == Approx(2 / r3).epsilon(3e-5));
  CHECK(x[1] == Approx(2 / r3).epsilon(3e-5));
  CHECK(x[2] == Approx(1 / r3).epsilon(3e-5));
  CHECK(out.objective == Approx(r3).epsilon(1e-9));
}

TEST_CASE("SQP: a row that no point meets is reported, not chased", "[sqp]") {
  // min x1 + x2 s.t. 1 - x1 - x2 - (x1 x2)^-1 >= 0 with x >= 0.01: the row is at most
  // 1 - 2 sqrt(p) - 1/p < 0 for every product p, so no point meets it. The solver stops
  // unsuccessful once its steps change nothing, well before its evaluation limit.
  const SmallProgram program(Eigen::Vector2d(1, 1), 2, 1, [](const auto& x, auto g) {
    g[0] = 1 - x[0] - x[1] - 1 / (x[0] * x[1]);
  });
  Eigen::VectorXd x = Eigen::Vector2d(1, 1);
  const SolverOutcome out = Solve(program, x, 1e-6);  // at most 3 000 evaluations
  INFO(out.status << " after " << out.iterations << ": " << out.message);
  CHECK_FALSE(out.success);
  CHECK(out.iterations < 1000);  // a third of the limit; measured 207 (the floor approached)
}

TEST_CASE("SQP: the verified sizing problem solved as SLSQP solves it, or lighter",
          "[sqp][nlopt]") {
  REQUIRE(SolverBuiltIn(SolverKind::kNlopt));  // the second algorithm is NLopt's (tagged [nlopt])
  Config config;  // the engineering defaults at n = 3: every case and station
  config.bridge.n = 3;
  const Design d = RunDesign(config);
  SizingCorrections corrections;
  corrections.demand_factor.assign(d.bars.size() + d.strings.size(), 1.2);
  const SizingProblem problem(d, corrections);
  const Eigen::VectorXd start =
      problem.VariablesOf(MemberAreas(d), problem.AlphaOf(d.reference_forces));
  SolverOptions options;
  options.tolerance = 1e-6;  // as the verified sizing asks
  Eigen::VectorXd x_sqp = start, x_slsqp = start;
  const SolverOutcome sqp = SolveWithSqp(problem, options, x_sqp);
  const SolverOutcome slsqp = SolveNlp(SolverKind::kNlopt, problem, options, x_slsqp);
  REQUIRE(sqp.success);
  REQUIRE(slsqp.success);
  Eigen::VectorXd g(problem.num_constraints()), lo, hi;
  problem.ConstraintBounds(lo, hi);
  problem.Constraints(x_sqp, g);
  INFO("SQP " << sqp.objective << " in " << sqp.iterations << ", SLSQP " << slsqp.objective
              << " in " << slsqp.iterations);
  // Feasible to the stop's 1e-6 on every row (each a utilisation's complement, O(1)).
  CHECK((lo - g).maxCoeff() <= 1e-6);
  // The same optimum to the stop: both settle to 1e-6 of the objective; 1e-5 leaves room for
  // each to stop on its own side of it. Not heavier than SLSQP's beyond that.
  CHECK(sqp.objective <= slsqp.objective * (1 + 1e-5));
  // The point of it: fewer evaluations (each a factorisation and every adjoint solve).
  CHECK(sqp.iterations < slsqp.iterations);
}

}  // namespace
}  // namespace tbridge
