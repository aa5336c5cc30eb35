// A smooth nonlinear program as the solver adapters see it, independent of any solver:
//   min f(x)  s.t.  x_lo <= x <= x_hi,  g_lo <= g(x) <= g_hi,
// with a fixed sparsity pattern for the constraint Jacobian and for the lower triangle of the
// Lagrangian's Hessian. The first num_equalities() rows of g are equalities (g_lo = g_hi);
// every other row has g_hi = +inf. Infinite bounds are std::numeric_limits<double>::infinity().
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/design_choices.h"

namespace tbridge {

class NlpProblem {
 public:
  using Pattern = std::vector<std::pair<int, int>>;  // (row, col) pairs
  virtual ~NlpProblem() = default;

  virtual int num_variables() const = 0;
  virtual int num_constraints() const = 0;
  virtual int num_equalities() const { return 0; }
  virtual void VariableBounds(Eigen::VectorXd& lo, Eigen::VectorXd& hi) const = 0;
  virtual void ConstraintBounds(Eigen::VectorXd& lo, Eigen::VectorXd& hi) const = 0;
  virtual double Objective(const Eigen::Ref<const Eigen::VectorXd>& x) const = 0;
  virtual void ObjectiveGradient(const Eigen::Ref<const Eigen::VectorXd>& x,
                                 Eigen::Ref<Eigen::VectorXd> grad) const = 0;
  virtual void Constraints(const Eigen::Ref<const Eigen::VectorXd>& x,
                           Eigen::Ref<Eigen::VectorXd> g) const = 0;
  virtual const Pattern& JacobianPattern() const = 0;
  // Values in JacobianPattern() order.
  virtual void JacobianValues(const Eigen::Ref<const Eigen::VectorXd>& x, double* values) const = 0;
  // The Jacobian as a dense matrix (rows x variables), for a solver that keeps it so (the
  // SQP); false where the problem gives it only by its pattern. A problem whose rows read
  // every variable saves the pattern (a pair per entry) and the copy through it.
  virtual bool DenseJacobian(const Eigen::Ref<const Eigen::VectorXd>& x,
                             Eigen::MatrixXd& jac) const {
    (void)x;
    (void)jac;
    return false;
  }
  // Lower triangle (row >= col) of the Hessian of sigma f + sum_i lambda_i g_i.
  virtual const Pattern& HessianPattern() const = 0;
  virtual void HessianValues(const Eigen::Ref<const Eigen::VectorXd>& x, double sigma,
                             const double* lambda, double* values) const = 0;
};

// What a solver reports back: a value, not a getter.
struct SolverOutcome {
  SolverKind solver = SolverKind::kNone;  // kDirect, kSqp, kIpopt or kNlopt
  std::string status;                     // the solver's own status name
  std::string message;                    // human-readable detail
  int iterations = 0;
  bool success = false;
  double objective = 0;  // f at the returned x
  // The rows' multipliers at the returned x, >= 0 on a binding row g >= lo (the SQP's last
  // subproblem's, Ipopt's own; empty for NLopt).
  Eigen::VectorXd multipliers;
};

struct SolverOptions {
  double tolerance = 1e-10;
  int max_iterations = 3000;
  bool verbose = false;
  // Called with the evaluations so far at each iteration of the solvers that take it (the
  // SQP): a long solve reports progress, and its caller's cancel hook may throw to stop it.
  std::function<void(int)> each_iteration;
  // The rows' multipliers at the start, one per row (the SQP; empty: it estimates them).
  Eigen::VectorXd start_multipliers;
  // Whether a solver may stop at its own looser "acceptable" level (Ipopt's, after iterations
  // that make no progress) and call it a success. A solve whose point is to be certified to
  // the tolerance does not let it.
  bool acceptable = true;
};

// Adapters: each is the only file that includes its solver's headers, and each is its own
// module (tbridge_ipopt.so, tbridge_nlopt.so), present only when built in and loaded on first
// use: call them through SolveNlp (optim/solvers.h), which knows which are. `x` is the start on
// entry and the solution on return. Both may be called from several threads; Ipopt solves
// then run one at a time, all on one thread of the adapter (its sequential MUMPS is not
// reentrant).
SolverOutcome SolveWithIpopt(const NlpProblem& problem, const SolverOptions& options,
                             Eigen::VectorXd& x);
SolverOutcome SolveWithNlopt(const NlpProblem& problem, const SolverOptions& options,
                             Eigen::VectorXd& x);

}  // namespace tbridge
