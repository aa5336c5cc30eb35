#include "optim/solvers.h"

#include <dlfcn.h>

#include <algorithm>
#include <filesystem>
#include <mutex>

#include "core/error.h"
#include "core/json_reader.h"
#include "optim/sqp_solver.h"

namespace tbridge {

namespace {

using SolveFunction = SolverOutcome (*)(const NlpProblem&, const SolverOptions&, Eigen::VectorXd&);

// The adapter module of `name` ("ipopt" or "nlopt"), loaded once on first use: from the folder
// of the running executable, else from the build folder. Throws ConfigError naming
// design.solver when neither loads.
SolveFunction LoadAdapter(const std::string& name) {
  namespace fs = std::filesystem;
  const std::string file = "tbridge_" + name + ".so";
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  std::string errors;
  for (const fs::path& dir : {ec ? fs::path() : exe.parent_path(), fs::path(TBRIDGE_MODULE_DIR)}) {
    if (dir.empty()) continue;
    const fs::path path = dir / file;
    if (!fs::exists(path, ec)) continue;
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      errors += std::string("; ") + dlerror();
      continue;
    }
    auto entry = reinterpret_cast<void* (*)()>(dlsym(handle, "tbridge_solver_entry"));
    if (entry != nullptr) return reinterpret_cast<SolveFunction>(entry());
    errors += "; " + path.string() + " has no tbridge_solver_entry";
  }
  throw ConfigError(
      "design.solver", "\"" + name + "\"",
      "its module " + file + " is not next to the executable nor in " TBRIDGE_MODULE_DIR + errors);
}

SolveFunction Adapter(SolverKind solver) {
  static std::mutex mutex;
  static SolveFunction ipopt = nullptr, nlopt = nullptr;
  const std::lock_guard<std::mutex> lock(mutex);
  SolveFunction& f = solver == SolverKind::kIpopt ? ipopt : nlopt;
  if (f == nullptr) f = LoadAdapter(NameOf(solver));
  return f;
}

}  // namespace

std::vector<SolverKind> BuiltInIterativeSolvers() {
  std::vector<SolverKind> solvers;
#ifdef TBRIDGE_HAVE_IPOPT
  solvers.push_back(SolverKind::kIpopt);
#endif
#ifdef TBRIDGE_HAVE_NLOPT
  solvers.push_back(SolverKind::kNlopt);
#endif
  return solvers;
}

std::vector<SolverKind> BuiltInSolvers() {
  std::vector<SolverKind> solvers{SolverKind::kAuto, SolverKind::kDirect};
  for (SolverKind s : BuiltInIterativeSolvers()) solvers.push_back(s);
  return solvers;
}

bool SolverBuiltIn(SolverKind solver) {
  if (solver == SolverKind::kSqp) return true;
  const std::vector<SolverKind> solvers = BuiltInSolvers();
  return std::find(solvers.begin(), solvers.end(), solver) != solvers.end();
}

void RequireSolverBuiltIn(SolverKind solver) {
  if (SolverBuiltIn(solver)) return;
  const std::string list = ChoiceText(NamesIn(kSolverNames, BuiltInSolvers()));
  const std::string name = NameOf(solver);
  const std::string option =
      solver == SolverKind::kIpopt ? "TBRIDGE_WITH_IPOPT" : "TBRIDGE_WITH_NLOPT";
  throw ConfigError(
      "design.solver", "\"" + name + "\"",
      "this build has no " + name + " (built in: " + list + "; rebuild with -D" + option + "=ON)");
}

SolverOutcome SolveNlp(SolverKind solver, const NlpProblem& problem, const SolverOptions& options,
                       Eigen::VectorXd& x) {
  if (solver == SolverKind::kSqp) return SolveWithSqp(problem, options, x);
  if (solver != SolverKind::kIpopt && solver != SolverKind::kNlopt) {
    throw ConfigError("design.solver", "\"" + std::string(NameOf(solver)) + "\"",
                      "not an iterative solver (\"ipopt\" or \"nlopt\")");
  }
  RequireSolverBuiltIn(solver);
  return Adapter(solver)(problem, options, x);
}

}  // namespace tbridge
