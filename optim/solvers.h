// Which NLP solvers this build has, and the one call that reaches them. Each solver adapter
// is its own module (tbridge_ipopt.so, tbridge_nlopt.so; CMake options TBRIDGE_WITH_IPOPT and
// TBRIDGE_WITH_NLOPT), loaded on first use, so a build without either stays possible and a
// command that designs nothing never loads them; this file is the only place that knows which
// were built in.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "optim/nlp.h"

namespace tbridge {

// The values of design.solver this build accepts, in order: kAuto, kDirect, then kIpopt and
// kNlopt when built in. kAuto and kDirect need no library.
std::vector<SolverKind> BuiltInSolvers();
// The iterative solvers built in (kIpopt, kNlopt), possibly none.
std::vector<SolverKind> BuiltInIterativeSolvers();
// Whether this build has `solver`: kSqp (the verified sizing's own) always, kNone never.
bool SolverBuiltIn(SolverKind solver);

// Throws ConfigError naming design.solver, the value and the solvers built in when `solver`
// (a value of design.solver) needs a library this build lacks.
void RequireSolverBuiltIn(SolverKind solver);

// Solves `problem` with the iterative solver `solver` (kIpopt or kNlopt, or kSqp: the verified
// sizing's own, optim/sqp_solver.h, always built in and not a value of design.solver); `x` is
// the start on entry and the solution on return. Throws ConfigError (design.solver) when
// `solver` is not built in or not iterative.
SolverOutcome SolveNlp(SolverKind solver, const NlpProblem& problem, const SolverOptions& options,
                       Eigen::VectorXd& x);

}  // namespace tbridge
