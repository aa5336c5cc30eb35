// Thin NLopt (SLSQP) adapter for an NlpProblem. The only file that includes NLopt headers.
// SLSQP works on dense matrices (the constraint gradients are m x n): its cost grows with the
// cube of the variable count, so it suits small problems such as the self-stress form of the
// design; Ipopt serves large ones.
#include <limits>
#include <nlopt.hpp>
#include <stdexcept>

#include "optim/nlp.h"

namespace tbridge {

namespace {

struct Context {
  const NlpProblem* problem;
  Eigen::VectorXd g;               // constraint values
  std::vector<double> jac_values;  // in pattern order
  int evaluations = 0;
};

double ObjectiveFn(unsigned n, const double* x, double* grad, void* data) {
  auto* c = static_cast<Context*>(data);
  ++c->evaluations;
  if (grad) {
    Eigen::Map<Eigen::VectorXd> g(grad, n);
    c->problem->ObjectiveGradient(Eigen::Map<const Eigen::VectorXd>(x, n), g);
  }
  return c->problem->Objective(Eigen::Map<const Eigen::VectorXd>(x, n));
}

// NLopt wants fc(x) <= 0 for inequalities and fc(x) = 0 for equalities, with a dense
// m x n row-major gradient. `first`, `count` select the rows of g; `sign` maps g >= lo to
// lo - g <= 0; `offset` holds the equality right-hand side or the lower bounds.
struct RowBlock {
  Context* context;
  int first, count;
  double sign;
  Eigen::VectorXd offset;
};

void ConstraintFn(unsigned m, double* result, unsigned n, const double* x, double* grad,
                  void* data) {
  auto* block = static_cast<RowBlock*>(data);
  const NlpProblem& p = *block->context->problem;
  Eigen::Map<const Eigen::VectorXd> xv(x, n);
  p.Constraints(xv, block->context->g);
  for (unsigned r = 0; r < m; ++r) {
    result[r] = block->sign * (block->context->g[block->first + r] - block->offset[r]);
  }
  if (grad) {
    std::fill(grad, grad + static_cast<size_t>(m) * n, 0.0);
    p.JacobianValues(xv, block->context->jac_values.data());
    const auto& pattern = p.JacobianPattern();
    for (size_t k = 0; k < pattern.size(); ++k) {
      const int row = pattern[k].first - block->first;
      if (row < 0 || row >= block->count) continue;
      grad[static_cast<size_t>(row) * n + pattern[k].second] =
          block->sign * block->context->jac_values[k];
    }
  }
}

}  // namespace

SolverOutcome SolveWithNlopt(const NlpProblem& problem, const SolverOptions& options,
                             Eigen::VectorXd& x) {
  const int n = problem.num_variables();
  const int m_eq = problem.num_equalities();
  const int m_in = problem.num_constraints() - m_eq;
  Context context{&problem, Eigen::VectorXd(problem.num_constraints()),
                  std::vector<double>(problem.JacobianPattern().size()), 0};
  Eigen::VectorXd lo, hi, g_lo, g_hi;
  problem.VariableBounds(lo, hi);
  problem.ConstraintBounds(g_lo, g_hi);
  RowBlock equalities{&context, 0, m_eq, 1.0, g_lo.head(m_eq)};
  for (int r = m_eq; r < problem.num_constraints(); ++r) {
    if (g_hi[r] != std::numeric_limits<double>::infinity() || !std::isfinite(g_lo[r])) {
      throw std::logic_error("NLopt adapter: inequality rows must read g >= finite lower bound");
    }
  }
  RowBlock inequalities{&context, m_eq, m_in, -1.0, g_lo.tail(m_in)};

  nlopt::opt opt(nlopt::LD_SLSQP, static_cast<unsigned>(n));
  opt.set_lower_bounds(std::vector<double>(lo.data(), lo.data() + n));
  opt.set_upper_bounds(std::vector<double>(hi.data(), hi.data() + n));
  opt.set_min_objective(ObjectiveFn, &context);
  if (m_eq > 0) {
    opt.add_equality_mconstraint(ConstraintFn, &equalities,
                                 std::vector<double>(m_eq, options.tolerance));
  }
  if (m_in > 0) {
    opt.add_inequality_mconstraint(ConstraintFn, &inequalities,
                                   std::vector<double>(m_in, options.tolerance));
  }
  opt.set_ftol_rel(options.tolerance);
  opt.set_xtol_rel(options.tolerance);
  opt.set_maxeval(options.max_iterations);

  SolverOutcome out;
  out.solver = SolverKind::kNlopt;
  std::vector<double> xs(x.data(), x.data() + n);
  double f = 0;
  try {
    const nlopt::result r = opt.optimize(xs, f);
    switch (r) {
      case nlopt::SUCCESS:
        out.status = "SUCCESS";
        break;
      case nlopt::STOPVAL_REACHED:
        out.status = "STOPVAL_REACHED";
        break;
      case nlopt::FTOL_REACHED:
        out.status = "FTOL_REACHED";
        break;
      case nlopt::XTOL_REACHED:
        out.status = "XTOL_REACHED";
        break;
      case nlopt::MAXEVAL_REACHED:
        out.status = "MAXEVAL_REACHED";
        break;
      case nlopt::MAXTIME_REACHED:
        out.status = "MAXTIME_REACHED";
        break;
      default:
        out.status = "RESULT_" + std::to_string(static_cast<int>(r));
        break;
    }
    out.success = r == nlopt::SUCCESS || r == nlopt::FTOL_REACHED || r == nlopt::XTOL_REACHED;
  } catch (const nlopt::roundoff_limited&) {
    out.status = "ROUNDOFF_LIMITED";
  } catch (const std::exception& e) {
    out.status = "FAILURE";
    out.message = e.what();
  }
  x = Eigen::Map<Eigen::VectorXd>(xs.data(), n);
  out.iterations = context.evaluations;
  out.objective = problem.Objective(x);
  if (out.message.empty())
    out.message = out.success ? "optimal" : "NLopt stopped with " + out.status;
  return out;
}

}  // namespace tbridge

// The module's entry point, looked up by optim/solvers.cc: the adapter's solve function.
extern "C" __attribute__((visibility("default"))) void* tbridge_solver_entry() {
  return reinterpret_cast<void*>(&tbridge::SolveWithNlopt);
}
