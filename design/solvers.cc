#include "design/solvers.h"

#include <algorithm>

#include "core/error.h"

namespace tbridge {

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
  throw ConfigError("design.solver", "\"" + Printable(name) + "\"",
                    "this build has no " + name + " (built in: " + list + "; rebuild with -D" + option + "=ON)");
}

SolverOutcome SolveNlp(const std::string& name, const NlpProblem& problem, const SolverOptions& options,
                       Eigen::VectorXd& x) {
  RequireSolverBuiltIn(name);
#ifdef TBRIDGE_HAVE_IPOPT
  if (name == "ipopt") return SolveWithIpopt(problem, options, x);
#endif
#ifdef TBRIDGE_HAVE_NLOPT
  if (name == "nlopt") return SolveWithNlopt(problem, options, x);
#endif
  throw ConfigError("design.solver", "\"" + Printable(name) + "\"", "not an iterative solver (\"ipopt\" or \"nlopt\")");
}

}  // namespace tbridge
