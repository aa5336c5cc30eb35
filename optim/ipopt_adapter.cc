// Thin Ipopt adapter for an NlpProblem. The only file that includes Ipopt headers.
#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <mutex>
#include <thread>

#include "optim/nlp.h"

namespace tbridge {

namespace {

using Ipopt::Index;
using Ipopt::Number;

class NlpTnlp : public Ipopt::TNLP {
 public:
  NlpTnlp(const NlpProblem& problem, Eigen::VectorXd& x) : p_(problem), x_(x) {
    p_.VariableBounds(x_lo_, x_hi_);
    p_.ConstraintBounds(g_lo_, g_hi_);
  }

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac, Index& nnz_h,
                    IndexStyleEnum& style) override {
    n = p_.num_variables();
    m = p_.num_constraints();
    nnz_jac = static_cast<Index>(p_.JacobianPattern().size());
    nnz_h = static_cast<Index>(p_.HessianPattern().size());
    style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index m, Number* g_l,
                       Number* g_u) override {
    // Ipopt reads |bound| >= 1e19 as "no bound".
    for (Index i = 0; i < n; ++i) {
      x_l[i] = Finite(x_lo_[i]);
      x_u[i] = Finite(x_hi_[i]);
    }
    for (Index i = 0; i < m; ++i) {
      g_l[i] = Finite(g_lo_[i]);
      g_u[i] = Finite(g_hi_[i]);
    }
    return true;
  }

  bool get_starting_point(Index n, bool init_x, Number* x, bool init_z, Number*, Number*, Index,
                          bool init_lambda, Number*) override {
    if (!init_x || init_z || init_lambda) return false;
    for (Index i = 0; i < n; ++i) x[i] = x_[i];
    return true;
  }

  bool eval_f(Index n, const Number* x, bool, Number& f) override {
    f = p_.Objective(Eigen::Map<const Eigen::VectorXd>(x, n));
    return true;
  }

  bool eval_grad_f(Index n, const Number* x, bool, Number* grad) override {
    Eigen::Map<Eigen::VectorXd> g(grad, n);
    p_.ObjectiveGradient(Eigen::Map<const Eigen::VectorXd>(x, n), g);
    return true;
  }

  bool eval_g(Index n, const Number* x, bool, Index m, Number* g) override {
    Eigen::Map<Eigen::VectorXd> gv(g, m);
    p_.Constraints(Eigen::Map<const Eigen::VectorXd>(x, n), gv);
    return true;
  }

  bool eval_jac_g(Index n, const Number* x, bool, Index, Index, Index* rows, Index* cols,
                  Number* values) override {
    if (values == nullptr) {
      const auto& pattern = p_.JacobianPattern();
      for (size_t k = 0; k < pattern.size(); ++k) {
        rows[k] = pattern[k].first;
        cols[k] = pattern[k].second;
      }
    } else {
      p_.JacobianValues(Eigen::Map<const Eigen::VectorXd>(x, n), values);
    }
    return true;
  }

  bool eval_h(Index n, const Number* x, bool, Number obj_factor, Index, const Number* lambda, bool,
              Index, Index* rows, Index* cols, Number* values) override {
    if (values == nullptr) {
      const auto& pattern = p_.HessianPattern();
      for (size_t k = 0; k < pattern.size(); ++k) {
        rows[k] = pattern[k].first;
        cols[k] = pattern[k].second;
      }
    } else {
      p_.HessianValues(Eigen::Map<const Eigen::VectorXd>(x, n), obj_factor, lambda, values);
    }
    return true;
  }

  void finalize_solution(Ipopt::SolverReturn status, Index n, const Number* x, const Number*,
                         const Number*, Index m, const Number*, const Number* lambda, Number obj,
                         const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    x_ = Eigen::Map<const Eigen::VectorXd>(x, n);
    // Ipopt's lambda is <= 0 on a binding row g >= lo (its Lagrangian adds lambda g); the
    // outcome's are >= 0 there, as the SQP's.
    multipliers_ = -Eigen::Map<const Eigen::VectorXd>(lambda, m);
    final_status_ = status;
    objective_ = obj;
  }

  Ipopt::SolverReturn final_status() const { return final_status_; }
  double objective() const { return objective_; }
  const Eigen::VectorXd& multipliers() const { return multipliers_; }

 private:
  static double Finite(double v) { return std::isfinite(v) ? v : (v > 0 ? 2e19 : -2e19); }

  const NlpProblem& p_;
  Eigen::VectorXd& x_;
  Eigen::VectorXd x_lo_, x_hi_, g_lo_, g_hi_;
  Ipopt::SolverReturn final_status_ = Ipopt::INTERNAL_ERROR;
  double objective_ = 0;
  Eigen::VectorXd multipliers_;
};

std::string StatusName(Ipopt::ApplicationReturnStatus s) {
  switch (s) {
    case Ipopt::Solve_Succeeded:
      return "Solve_Succeeded";
    case Ipopt::Solved_To_Acceptable_Level:
      return "Solved_To_Acceptable_Level";
    case Ipopt::Infeasible_Problem_Detected:
      return "Infeasible_Problem_Detected";
    case Ipopt::Search_Direction_Becomes_Too_Small:
      return "Search_Direction_Becomes_Too_Small";
    case Ipopt::Diverging_Iterates:
      return "Diverging_Iterates";
    case Ipopt::User_Requested_Stop:
      return "User_Requested_Stop";
    case Ipopt::Feasible_Point_Found:
      return "Feasible_Point_Found";
    case Ipopt::Maximum_Iterations_Exceeded:
      return "Maximum_Iterations_Exceeded";
    case Ipopt::Restoration_Failed:
      return "Restoration_Failed";
    case Ipopt::Error_In_Step_Computation:
      return "Error_In_Step_Computation";
    case Ipopt::Maximum_CpuTime_Exceeded:
      return "Maximum_CpuTime_Exceeded";
    case Ipopt::Not_Enough_Degrees_Of_Freedom:
      return "Not_Enough_Degrees_Of_Freedom";
    case Ipopt::Invalid_Problem_Definition:
      return "Invalid_Problem_Definition";
    case Ipopt::Invalid_Option:
      return "Invalid_Option";
    case Ipopt::Invalid_Number_Detected:
      return "Invalid_Number_Detected";
    default:
      return "Internal_Error";
  }
}

// Debian's Ipopt factorises with the sequential MUMPS, whose Fortran modules keep state
// between calls: two solves at once crash it, and so can solves taken in turn by different
// threads (seen under the address sanitizer). So one thread, started on first use, runs every
// solve in order of arrival, and any caller may run designs on several threads.
class SolverThread {
 public:
  static SolverThread& Instance() {
    static SolverThread thread;
    return thread;
  }

  // Runs `job` on the solver thread and returns its result (or rethrows its exception).
  SolverOutcome Run(const std::function<SolverOutcome()>& job) {
    std::packaged_task<SolverOutcome()> task(job);
    std::future<SolverOutcome> result = task.get_future();
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      queue_.push_back(&task);
    }
    wake_.notify_one();
    return result.get();
  }

  ~SolverThread() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_one();
    worker_.join();
  }

 private:
  SolverThread() : worker_([this] { Loop(); }) {}

  void Loop() {
    for (;;) {
      std::packaged_task<SolverOutcome()>* task = nullptr;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [this] { return stop_ || !queue_.empty(); });
        if (queue_.empty()) return;  // stopping, nothing left
        task = queue_.front();
        queue_.pop_front();
      }
      (*task)();  // the caller waits on its future, so the task outlives this call
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::packaged_task<SolverOutcome()>*> queue_;
  bool stop_ = false;
  std::thread worker_;  // last: starts once the members above exist
};

SolverOutcome SolveHere(const NlpProblem& problem, const SolverOptions& options,
                        Eigen::VectorXd& x) {
  Ipopt::SmartPtr<NlpTnlp> nlp = new NlpTnlp(problem, x);
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->Options()->SetIntegerValue("print_level", options.verbose ? 5 : 0);
  app->Options()->SetStringValue("sb", "yes");  // no banner
  app->Options()->SetNumericValue("tol", options.tolerance);
  app->Options()->SetNumericValue("constr_viol_tol", options.tolerance);
  app->Options()->SetIntegerValue("max_iter", options.max_iterations);
  app->Options()->SetStringValue("mu_strategy", "adaptive");
  if (!options.acceptable) app->Options()->SetIntegerValue("acceptable_iter", 0);
  // Bounds are exact physical limits (zero force, prestress floors): do not relax them.
  app->Options()->SetNumericValue("bound_relax_factor", 0.0);
  // A problem that gives no Hessian (its pattern empty) has it approximated (L-BFGS).
  if (problem.HessianPattern().empty())
    app->Options()->SetStringValue("hessian_approximation", "limited-memory");

  SolverOutcome out;
  out.solver = SolverKind::kIpopt;
  Ipopt::ApplicationReturnStatus status = app->Initialize();
  if (status != Ipopt::Solve_Succeeded) {
    out.status = StatusName(status);
    out.message = "Ipopt failed to initialise";
    return out;
  }
  status = app->OptimizeTNLP(Ipopt::GetRawPtr(nlp));
  out.status = StatusName(status);
  out.success = status == Ipopt::Solve_Succeeded || status == Ipopt::Solved_To_Acceptable_Level;
  out.iterations = Ipopt::IsValid(app->Statistics()) ? app->Statistics()->IterationCount() : 0;
  out.objective = problem.Objective(x);
  out.multipliers = nlp->multipliers();
  out.message = out.success ? "optimal" : "Ipopt stopped with " + out.status;
  return out;
}

}  // namespace

SolverOutcome SolveWithIpopt(const NlpProblem& problem, const SolverOptions& options,
                             Eigen::VectorXd& x) {
  return SolverThread::Instance().Run([&] { return SolveHere(problem, options, x); });
}

}  // namespace tbridge

// The module's entry point, looked up by optim/solvers.cc: the adapter's solve function.
extern "C" __attribute__((visibility("default"))) void* tbridge_solver_entry() {
  return reinterpret_cast<void*>(&tbridge::SolveWithIpopt);
}
