// Shared test helpers: the paper's configs and designs.
#pragma once

#include <initializer_list>
#include <map>
#include <string>

#include "core/config.h"
#include "design/design.h"
#include "design/solvers.h"

namespace tbridge::test {

// True when this build has every solver named (CMake options TBRIDGE_WITH_IPOPT and
// TBRIDGE_WITH_NLOPT); a test that needs a missing one returns early on false.
inline bool HaveSolvers(std::initializer_list<const char*> names) {
  for (const char* name : names) {
    if (!SolverBuiltIn(name)) return false;
  }
  return true;
}

// The paper's planar bridge (SPEC §1): L = 12 m, F = 12000 N, beta = 10 deg, solver as given ("auto": the direct solve).
inline Config PaperConfig(int n, const std::string& solver = "auto") {
  Config c;
  c.bridge.n = n;
  c.design.solver = solver;
  return c;
}

// The paper's design for complexity n with default settings, computed once per process.
inline const Design& PaperDesign(int n) {
  static std::map<int, Design> cache;
  auto it = cache.find(n);
  if (it == cache.end()) it = cache.emplace(n, RunDesign(PaperConfig(n))).first;
  return it->second;
}

}  // namespace tbridge::test
