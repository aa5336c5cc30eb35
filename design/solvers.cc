#include "design/solvers.h"

#include <dlfcn.h>

#include <algorithm>
#include <filesystem>
#include <mutex>

#include "core/error.h"
#include "design/sqp_solver.h"

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

SolveFunction Adapter(const std::string& name) {
  static std::mutex mutex;
  static SolveFunction ipopt = nullptr, nlopt = nullptr;
  const std::lock_guard<std::mutex> lock(mutex);
  SolveFunction& f = name == "ipopt" ? ipopt : nlopt;
  if (f == nullptr) f = LoadAdapter(name);
  return f;
}

}  // namespace

std::vector<std::string> BuiltInIterativeSolvers() {
  std::vector<std::string> names;
#ifdef TBRIDGE_HAVE_IPOPT
  names.push_back("ipopt");
#endif
#ifdef TBRIDGE_HAVE_NLOPT
  names.push_back("nlopt");
#endif
  return names;
}

std::vector<std::string> BuiltInSolvers() {
  std::vector<std::string> names{"auto", "direct"};
  for (const std::string& s : BuiltInIterativeSolvers()) names.push_back(s);
  return names;
}

bool SolverBuiltIn(const std::string& name) {
  const std::vector<std::string> names = BuiltInSolvers();
  return std::find(names.begin(), names.end(), name) != names.end();
}

void RequireSolverBuiltIn(const std::string& name) {
  if (SolverBuiltIn(name)) return;
  std::string list;
  for (const std::string& s : BuiltInSolvers()) list += (list.empty() ? "\"" : ", \"") + s + "\"";
  const std::string option = name == "ipopt" ? "TBRIDGE_WITH_IPOPT" : "TBRIDGE_WITH_NLOPT";
  throw ConfigError(
      "design.solver", "\"" + Printable(name) + "\"",
      "this build has no " + name + " (built in: " + list + "; rebuild with -D" + option + "=ON)");
}

SolverOutcome SolveNlp(const std::string& name, const NlpProblem& problem,
                       const SolverOptions& options, Eigen::VectorXd& x) {
  if (name == "sqp") return SolveWithSqp(problem, options, x);
  RequireSolverBuiltIn(name);
  if (name == "ipopt" || name == "nlopt") return Adapter(name)(problem, options, x);
  throw ConfigError("design.solver", "\"" + Printable(name) + "\"",
                    "not an iterative solver (\"ipopt\" or \"nlopt\")");
}

}  // namespace tbridge
