// Which NLP solvers this build has, and the one call that reaches them. Each solver adapter
// is its own module (tbridge_ipopt.so, tbridge_nlopt.so; CMake options TBRIDGE_WITH_IPOPT and
// TBRIDGE_WITH_NLOPT), loaded on first use, so a build without either stays possible and a
// command that designs nothing never loads them; this file is the only place that knows which
// were built in.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "design/nlp.h"

namespace tbridge {

// The values of design.solver this build accepts, in order: "auto", "direct", then "ipopt"
// and "nlopt" when built in. "auto" and "direct" need no library.
std::vector<std::string> BuiltInSolvers();
// The iterative solvers built in ("ipopt", "nlopt"), possibly none.
std::vector<std::string> BuiltInIterativeSolvers();
bool SolverBuiltIn(const std::string& name);

// Throws ConfigError naming design.solver, the value and the solvers built in when `name`
// (a value of design.solver) needs a library this build lacks.
void RequireSolverBuiltIn(const std::string& name);

// Solves `problem` with the iterative solver `name` ("ipopt" or "nlopt", or "sqp": the
// verified sizing's own, design/sqp_solver.h, always built in and not a value of
// design.solver); `x` is the start on entry and the solution on return. Throws ConfigError
// (design.solver) when `name` is not built in.
SolverOutcome SolveNlp(const std::string& name, const NlpProblem& problem,
                       const SolverOptions& options, Eigen::VectorXd& x);

}  // namespace tbridge
