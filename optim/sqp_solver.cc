#include "optim/sqp_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "optim/dense_qp.h"
#include "optim/nnls.h"
#include "optim/reciprocal_curvature.h"

namespace tbridge {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// The subproblems' tolerance on a row (DenseQpSolver::Solve's default).
constexpr double kQpTolerance = 1e-11;

// The problem's values and derivatives at one point (the Jacobian dense: the rows are dense
// in the variables, every member's force reads every area through the stiffness).
struct Point {
  Eigen::VectorXd x, grad, g;
  Eigen::MatrixXd jac;
  double f = 0;
};

class Evaluator {
 public:
  explicit Evaluator(const NlpProblem& problem) : problem_(problem) {}
  // f and g at pt.x; false where either is not finite (an unstable point).
  bool Values(Point& pt) {
    ++evaluations;
    pt.f = problem_.Objective(pt.x);
    problem_.Constraints(pt.x, pt.g);
    return std::isfinite(pt.f) && pt.g.allFinite();
  }
  void Derivatives(Point& pt) {
    problem_.ObjectiveGradient(pt.x, pt.grad);
    if (problem_.DenseJacobian(pt.x, pt.jac)) return;
    const auto& pattern = problem_.JacobianPattern();
    values_.resize(pattern.size());
    problem_.JacobianValues(pt.x, values_.data());
    pt.jac.setZero();
    for (size_t k = 0; k < pattern.size(); ++k)
      pt.jac(pattern[k].first, pattern[k].second) = values_[k];
  }
  int evaluations = 0;

 private:
  const NlpProblem& problem_;
  std::vector<double> values_;
};

double Violation(const Eigen::VectorXd& g, const Eigen::VectorXd& lo) {
  return (lo - g).cwiseMax(0.0).sum();
}

// The multipliers that best explain the start as a stationary point (non-negative least
// squares over the rows within 1e-2 of their bound and the variables on theirs). Zero
// multipliers would leave the first subproblem a linear program that jumps to a corner of the
// move limits, far from a start that is already near an optimum (a resizing's previous
// design): the optimum is flat, and the outer iterations then chase a different design.
Eigen::VectorXd StartMultipliers(const Point& pt, const Eigen::VectorXd& g_lo,
                                 const Eigen::VectorXd& lo) {
  const int n = static_cast<int>(pt.x.size()), m = static_cast<int>(pt.g.size());
  std::vector<int> rows, bounds;
  for (int i = 0; i < m; ++i) {
    if (pt.g[i] - g_lo[i] <= 1e-2) rows.push_back(i);
  }
  for (int j = 0; j < n; ++j) {
    if (std::isfinite(lo[j]) && pt.x[j] <= lo[j] * (1 + 1e-6) + 1e-12) bounds.push_back(j);
  }
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m);
  if (rows.empty()) return lambda;
  const int k = static_cast<int>(rows.size());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, k + static_cast<int>(bounds.size()));
  for (int c = 0; c < k; ++c) A.col(c) = pt.jac.row(rows[c]).transpose();
  for (size_t c = 0; c < bounds.size(); ++c) A(bounds[c], k + static_cast<int>(c)) = 1.0;
  const Eigen::VectorXd z = NonNegativeLeastSquares(A, pt.grad);
  for (int c = 0; c < k; ++c) lambda[rows[c]] = z[c];
  return lambda;
}

// The subproblem's right-hand sides b (rows C p >= b), each lowered to nine tenths of the most
// its row can reach within the move limits. A row violated far beyond what one step can mend
// (a bar near its floor reads 1 - F / R(A) of -1e12) would otherwise make the subproblem
// infeasible, and its elastic form ill-scaled.
void RelaxUnreachable(DenseQp& qp, const Eigen::VectorXd& b) {
  const Eigen::Index m = qp.C.rows(), n = qp.C.cols();
  qp.b.resize(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    double reach = 0;
    for (Eigen::Index j = 0; j < n; ++j) {
      const double c = qp.C(i, j);
      reach += c > 0 ? c * qp.hi[j] : c < 0 ? c * qp.lo[j] : 0.0;
    }
    // A row that cannot rise within the limits (reach <= 0) may fall by a tenth more.
    qp.b[i] = std::min(b[i], reach > 0 ? 0.9 * reach : 1.1 * reach - 1e-12);
    if (!std::isfinite(qp.b[i])) qp.b[i] = b[i];
  }
}

// The outcome of a subproblem the dense QP could not solve (its elastic form, which always has
// a solution in exact arithmetic): a status per cause, with what to try.
void QpFailure(DenseQpStatus status, SolverOutcome& out) {
  switch (status) {
    case DenseQpStatus::kInfeasible:
      out.status = "QP_INFEASIBLE";
      out.message =
          "the quadratic subproblem's rows were dependent and contradictory to rounding "
          "(try design.solver \"ipopt\")";
      return;
    case DenseQpStatus::kNotPositiveDefinite:
      out.status = "QP_NOT_POSITIVE_DEFINITE";
      out.message =
          "the quadratic subproblem's curvature was not positive definite (a row or the "
          "mass not finite at this point)";
      return;
    case DenseQpStatus::kStepLimit:
    case DenseQpStatus::kSolved:
      out.status = "QP_STEP_LIMIT";
      out.message =
          "the quadratic subproblem took more active-set steps than its limit "
          "(try design.solver \"ipopt\")";
      return;
  }
}

// The quadratic subproblem at `cur` (its right-hand sides apart): the Lagrangian's diagonal
// Hessian, the gradients and the move limits (move_lo, move_hi: where a move limit, not a
// bound, limits the step).
void PoseSubproblem(const Point& cur, const Eigen::VectorXd& lambda, const Eigen::VectorXd& secant,
                    const Eigen::VectorXd& reach, const Eigen::VectorXd& lo,
                    const Eigen::VectorXd& hi, DenseQp& qp, std::vector<char>& move_lo,
                    std::vector<char>& move_hi) {
  const int n = static_cast<int>(cur.x.size());
  const Eigen::VectorXd abs_sum = cur.jac.cwiseAbs().transpose() * lambda.cwiseAbs();
  for (int j = 0; j < n; ++j) {
    // The reciprocal rows' curvature in a positive variable, at least the secant's.
    double h = secant[j];
    if (lo[j] > 0)
      h = std::max(h, ReciprocalCurvature(cur.x[j], cur.jac.col(j), lambda, cur.grad[j]));
    double step_lo, step_hi;
    if (lo[j] > 0) {
      step_lo = cur.x[j] / (1 + reach[j]) - cur.x[j];
      step_hi = cur.x[j] * (1 + reach[j]) - cur.x[j];
    } else {
      const double r = reach[j] * std::max(1.0, std::abs(cur.x[j]));
      step_lo = -r;
      step_hi = r;
    }
    move_lo[j] = step_lo > lo[j] - cur.x[j];
    move_hi[j] = step_hi < hi[j] - cur.x[j];
    qp.lo[j] = std::max(step_lo, lo[j] - cur.x[j]);
    qp.hi[j] = std::min(step_hi, hi[j] - cur.x[j]);
    // A floor that keeps the subproblem strictly convex without steering it: its quadratic
    // term over the move limit is a millionth of the linear one, the rows' included where no
    // multiplier weighs them yet (the prestress, which the mass does not read, had a
    // curvature of 1e-18 there, and the subproblem's transformed rows all lay along it).
    const double width = std::max(qp.hi[j] - qp.lo[j], 1e-300);
    const double rows =
        std::max(abs_sum[j], cur.jac.rows() > 0 ? cur.jac.col(j).cwiseAbs().maxCoeff() : 0.0);
    qp.G(j, j) = std::max(h, 1e-6 * (std::abs(cur.grad[j]) + rows + 1e-12) / width);
  }
  qp.a = cur.grad;
  qp.C = cur.jac;
}

// The subproblem with one slack s >= 0 on every row, at `price` per unit (linear and
// quadratic): always feasible, its solution the least violation where `qp` has none.
void PoseElastic(const DenseQp& qp, double price, DenseQp& elastic) {
  const Eigen::Index n = qp.G.rows(), m = qp.C.rows();
  elastic.G.setZero(n + 1, n + 1);
  elastic.G.topLeftCorner(n, n) = qp.G;
  elastic.G(n, n) = price;
  elastic.a.resize(n + 1);
  elastic.a << qp.a, price;
  elastic.C.resize(m, n + 1);
  elastic.C << qp.C, Eigen::VectorXd::Ones(m);
  elastic.b = qp.b;
  elastic.lo.resize(n + 1);
  elastic.lo << qp.lo, 0.0;
  elastic.hi.resize(n + 1);
  elastic.hi << qp.hi, kInf;
}

// The variables' and the rows' bounds; throws where a row is not g >= a finite lower bound.
void ReadBounds(const NlpProblem& problem, Eigen::VectorXd& lo, Eigen::VectorXd& hi,
                Eigen::VectorXd& g_lo, Eigen::VectorXd& g_hi) {
  const int m = problem.num_constraints();
  if (problem.num_equalities() > 0) throw std::logic_error("SQP: equality rows are not supported");
  problem.VariableBounds(lo, hi);
  problem.ConstraintBounds(g_lo, g_hi);
  for (int r = 0; r < m; ++r) {
    if (g_hi[r] != kInf || !std::isfinite(g_lo[r])) {
      throw std::logic_error("SQP: rows must read g >= finite lower bound");
    }
  }
}

// The step's subproblem, from the last one's active set, or its elastic form where the
// linearised rows cannot all hold; false (out's status and message set) where that fails too.
bool SolveSubproblem(DenseQpSolver& qp_solver, DenseQp& qp, DenseQp& elastic, double nu,
                     const Point& cur, std::vector<int>& warm, DenseQpSolution& sol,
                     bool& used_elastic, SolverOutcome& out) {
  const int n = static_cast<int>(cur.x.size());
  // From the last subproblem's active set: from one iteration to the next it changes in a
  // few rows (n = 7: 500 steps per subproblem from none).
  qp_solver.Solve(qp, sol, kQpTolerance, &warm);
  if (sol.solved) warm = sol.active;
  used_elastic = false;
  if (!sol.solved) {
    // The linearised rows cannot all hold within the move limits: the least violation, at a
    // price above any multiplier.
    used_elastic = true;
    PoseElastic(qp, std::max({10.0 * nu, 10.0 * cur.grad.cwiseAbs().maxCoeff(), 1.0}), elastic);
    qp_solver.Solve(elastic, sol);
    if (!sol.solved) {
      QpFailure(sol.status, out);
      return false;
    }
    sol.p.conservativeResize(n);
  }
  return true;
}

// The l1 merit f + nu * (rows' violation) at the current point (viol0 its violation), and its
// slope along the step.
struct Merit {
  double nu, viol0, merit0, slope;
  const Eigen::VectorXd& g_lo;
  bool Decreases(const Point& trial, double t) const {
    return trial.f + nu * Violation(trial.g, g_lo) <= merit0 + 1e-4 * t * std::min(slope, 0.0);
  }
};

// The merit at cur along the step p (b_full: the linearised rows' right-hand sides).
Merit MeritAlong(const Point& cur, const Eigen::VectorXd& p, const Eigen::VectorXd& b_full,
                 const Eigen::VectorXd& g_lo, double nu) {
  const double viol0 = Violation(cur.g, g_lo);
  const double lin = (b_full - cur.jac * p).cwiseMax(0.0).sum();
  const double slope = cur.grad.dot(p) - nu * (viol0 - lin);
  const double merit0 = cur.f + nu * viol0;
  return Merit{nu, viol0, merit0, slope, g_lo};
}

// The subproblem's storage for n variables and m rows (G diagonal: zero off it).
void SizeSubproblem(int n, int m, DenseQp& qp) {
  qp.G.setZero(n, n);
  qp.C.resize(m, n);
  qp.lo.resize(n);
  qp.hi.resize(n);
}

// The iterates' storage for n variables and m rows, and the start (x within its bounds) with
// its values and derivatives; false where the start is not a finite point.
bool Start(Evaluator& eval, const Eigen::VectorXd& x, const Eigen::VectorXd& lo,
           const Eigen::VectorXd& hi, int m, Point& cur, Point& trial) {
  const Eigen::Index n = lo.size();
  for (Point* pt : {&cur, &trial}) {
    pt->grad.resize(n);
    pt->g.resize(m);
    pt->jac.resize(m, n);
  }
  cur.x = x.cwiseMax(lo).cwiseMin(hi);
  if (!eval.Values(cur)) return false;
  eval.Derivatives(cur);
  return true;
}

// What the line search works on: the subproblem (for the second-order correction), the
// variables' bounds and the evaluations it may spend.
struct LineSearchContext {
  Evaluator& eval;
  int max_evaluations;
  DenseQpSolver& qp_solver;
  DenseQp& qp;
  DenseQpSolution& sol;
  const std::vector<int>& warm;
  const Eigen::VectorXd &lo, &hi, &g_lo;
};

// Halves the step t along p from cur until the merit decreases enough, ten trials at most;
// true where a trial is accepted (in trial; p and multiplier then the step taken).
bool LineSearch(const LineSearchContext& c, const Merit& merit, bool used_elastic, const Point& cur,
                Point& trial, Eigen::VectorXd& p, Eigen::VectorXd& multiplier, double& t) {
  for (int ls = 0; ls < 10 && c.eval.evaluations < c.max_evaluations; ++ls) {
    trial.x = (cur.x + t * p).cwiseMax(c.lo).cwiseMin(c.hi);
    const bool finite = c.eval.Values(trial);
    if (finite && merit.Decreases(trial, t)) return true;
    if (ls == 0 && finite && !used_elastic && c.eval.evaluations < c.max_evaluations) {
      // Second-order correction (Nocedal and Wright, 18.3): near the optimum a full step
      // may raise the merit by the rows' curvature alone and be cut down step after step
      // (the Maratos effect). The rows' linearisation, shifted by what the full step
      // missed, gives a corrected step from the same point.
      RelaxUnreachable(c.qp, c.g_lo - trial.g + cur.jac * p);
      c.qp_solver.Solve(c.qp, c.sol, kQpTolerance, &c.warm);
      if (c.sol.solved) {
        trial.x = (cur.x + c.sol.p).cwiseMax(c.lo).cwiseMin(c.hi);
        if (c.eval.Values(trial) && merit.Decreases(trial, 1.0)) {
          p = c.sol.p;
          multiplier = c.sol.row_multiplier;
          return true;
        }
      }
    }
    t *= 0.5;
  }
  return false;
}

// After an accepted step: the diagonal secant curvature from the Lagrangian's gradient before
// and after, the variables whose step met its move limit (limited), and the largest relative
// step (step_rel). True where any step met its move limit.
bool SecantAndLimits(const Point& cur, const Point& trial, const Eigen::VectorXd& multiplier,
                     const Eigen::VectorXd& p, const DenseQp& qp, const std::vector<char>& move_lo,
                     const std::vector<char>& move_hi, Eigen::VectorXd& old_grad_l,
                     Eigen::VectorXd& new_grad_l, Eigen::VectorXd& secant,
                     std::vector<char>& limited, double& step_rel) {
  const int n = static_cast<int>(cur.x.size());
  // The Lagrangian's gradient before and after, for the secant curvature.
  old_grad_l.noalias() = cur.grad - cur.jac.transpose() * multiplier;
  new_grad_l.noalias() = trial.grad - trial.jac.transpose() * multiplier;
  bool at_limit = false;
  std::fill(limited.begin(), limited.end(), 0);
  step_rel = 0;
  for (int j = 0; j < n; ++j) {
    const double s = trial.x[j] - cur.x[j];
    step_rel = std::max(step_rel, std::abs(s) / std::max(1.0, std::abs(cur.x[j])));
    if (s != 0.0) {
      const double y = new_grad_l[j] - old_grad_l[j];
      if (y * s > 0) secant[j] = y / s;
    }
    const double width = qp.hi[j] - qp.lo[j];
    if ((move_lo[j] && p[j] <= qp.lo[j] + 1e-9 * width) ||
        (move_hi[j] && p[j] >= qp.hi[j] - 1e-9 * width)) {
      at_limit = true;
      limited[j] = 1;
    }
  }
  return at_limit;
}

// The move limits after a step t p: a variable whose step changes sign halves its reach, one
// that met its limit on a full step doubles it (to 9 at most), a shortened step cuts it.
void AdaptReach(double t, const Eigen::VectorXd& p, const std::vector<char>& limited,
                Eigen::VectorXd& reach, Eigen::VectorXd& last_step) {
  const Eigen::Index n = p.size();
  for (Eigen::Index j = 0; j < n; ++j) {
    const double s = t * p[j];
    if (s * last_step[j] < 0) {
      reach[j] *= 0.5;
    } else if (t == 1.0 && limited[static_cast<size_t>(j)]) {
      reach[j] = std::min(2.0 * reach[j], 9.0);
    } else if (t < 1.0) {
      reach[j] *= 0.7;
    }
    last_step[j] = s;
  }
}

// How an accepted step ended.
struct StepReport {
  bool used_elastic, at_limit;
  double t, df, viol0, step_rel;
};

// Whether the iterations stop after an accepted step to cur (out's status set where they do);
// small_steps and stalled count the steps in a row that settle or stall.
bool Stops(const Point& cur, const Eigen::VectorXd& g_lo, double tol, const StepReport& step,
           int& small_steps, int& stalled, SolverOutcome& out) {
  const bool feasible = (g_lo - cur.g).maxCoeff() <= tol;
  // Settled: a full step inside the move limits that changes the objective by less than the
  // tolerance, or two such steps in a row at a limit (a variable still shrinking there,
  // step after step, changes the mass by less than the tolerance each time: the default at
  // n = 6 crawled so for 270 evaluations and 7e-5 of the mass).
  const bool small = feasible && !step.used_elastic && step.df <= tol * std::abs(cur.f);
  small_steps = small ? small_steps + 1 : 0;
  if (small && ((step.t == 1.0 && !step.at_limit) || small_steps >= 2)) {
    out.status = "FTOL_REACHED";
    out.success = true;
    return true;
  }
  // Stalled outside the rows: steps that change neither the objective nor the violation (by a
  // millionth of either), five in a row: a row that no step within the move limits mends.
  const double viol = Violation(cur.g, g_lo);
  const bool still = !feasible && step.df <= tol * std::abs(cur.f) &&
                     std::abs(step.viol0 - viol) <= 1e-6 * step.viol0;
  stalled = still ? stalled + 1 : 0;
  if (stalled >= 5) {
    out.status = "INFEASIBLE";
    out.message =
        "the rows cannot all be met from here: the violation settled at " + std::to_string(viol);
    return true;
  }
  if (feasible && step.step_rel <= tol) {
    out.status = "XTOL_REACHED";
    out.success = true;
    return true;
  }
  return false;
}

}  // namespace

SolverOutcome SolveWithSqp(const NlpProblem& problem, const SolverOptions& options,
                           Eigen::VectorXd& x) {
  const int n = problem.num_variables();
  const int m = problem.num_constraints();
  Eigen::VectorXd lo, hi, g_lo, g_hi;
  ReadBounds(problem, lo, hi, g_lo, g_hi);
  const double tol = options.tolerance;
  SolverOutcome out;
  out.solver = SolverKind::kSqp;

  Evaluator eval(problem);
  Point cur, trial;
  if (!Start(eval, x, lo, hi, m, cur, trial)) {
    out.status = "FAILURE";
    out.message = "the start is not a finite point";
    out.iterations = eval.evaluations;
    return out;
  }

  // The last subproblem's multipliers weigh the rows' curvature; a diagonal secant estimate
  // serves where it is larger (and alone for the variables without a positive lower bound).
  // The caller's, where it has them (a solve of more rows from the last one's optimum).
  Eigen::VectorXd lambda = options.start_multipliers.size() == m ? options.start_multipliers
                                                                 : StartMultipliers(cur, g_lo, lo);
  Eigen::VectorXd secant = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd old_grad_l(n), new_grad_l(n);
  // Move limits, one per variable (MMA's asymptotes adapt so, Svanberg 1987): a positive variable
  // within x / (1 + r) .. x (1 + r), another within +-r max(1, |x|). A variable whose step
  // changes sign halves its r; one that meets its limit on a full step doubles it.
  Eigen::VectorXd reach = Eigen::VectorXd::Ones(n), last_step = Eigen::VectorXd::Zero(n);
  double nu = 0;  // the merit function's penalty
  DenseQpSolver qp_solver;
  DenseQp qp, elastic;
  DenseQpSolution sol;
  // The last subproblem's active set; at first the rows with a positive start multiplier
  // (the dual method drops any whose multiplier comes out negative, so it only saves steps).
  std::vector<int> warm;
  for (int r = 0; r < m; ++r) {
    if (lambda[r] > 0) warm.push_back(r);
  }
  SizeSubproblem(n, m, qp);
  std::vector<char> move_lo(n), move_hi(n), limited(n);
  Eigen::VectorXd b_full(m);  // the linearised rows' right-hand sides, g_lo - g
  const LineSearchContext search{eval, options.max_iterations, qp_solver, qp, sol, warm, lo, hi,
                                 g_lo};

  out.status = "MAXEVAL_REACHED";
  int small_steps = 0;  // accepted steps in a row that changed the objective by less than tol
  int stalled = 0;      // accepted steps in a row that changed nothing while infeasible
  while (eval.evaluations < options.max_iterations) {
    if (options.each_iteration) options.each_iteration(eval.evaluations);
    PoseSubproblem(cur, lambda, secant, reach, lo, hi, qp, move_lo, move_hi);
    b_full = g_lo - cur.g;
    RelaxUnreachable(qp, b_full);
    bool used_elastic = false;
    if (!SolveSubproblem(qp_solver, qp, elastic, nu, cur, warm, sol, used_elastic, out)) break;
    Eigen::VectorXd p = sol.p;
    Eigen::VectorXd multiplier = sol.row_multiplier;

    // l1 merit: f + nu * (rows' violation), nu above every multiplier.
    nu = std::max(nu, 1.1 * multiplier.maxCoeff() + 1e-12);
    const Merit merit = MeritAlong(cur, p, b_full, g_lo, nu);
    double t = 1.0;
    if (!LineSearch(search, merit, used_elastic, cur, trial, p, multiplier, t)) {
      // The model overreached: a smaller trust region.
      reach /= 4.0;
      if (reach.maxCoeff() < 1e-12) {
        out.status = "ROUNDOFF_LIMITED";
        break;
      }
      continue;
    }
    eval.Derivatives(trial);
    double step_rel = 0;
    const bool at_limit = SecantAndLimits(cur, trial, multiplier, p, qp, move_lo, move_hi,
                                          old_grad_l, new_grad_l, secant, limited, step_rel);
    const double df = std::abs(trial.f - cur.f);
    std::swap(cur, trial);
    lambda = multiplier;
    AdaptReach(t, p, limited, reach, last_step);
    if (Stops(cur, g_lo, tol, {used_elastic, at_limit, t, df, merit.viol0, step_rel}, small_steps,
              stalled, out)) {
      break;
    }
  }
  x = cur.x;
  out.multipliers = lambda;
  out.iterations = eval.evaluations;
  out.objective = cur.f;
  if (out.message.empty()) out.message = out.success ? "optimal" : "SQP stopped with " + out.status;
  return out;
}

}  // namespace tbridge
