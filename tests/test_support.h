// Shared test helpers: the paper's configs and designs.
#pragma once

#include <initializer_list>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "core/config.h"
#include "design/design.h"
#include "optim/solvers.h"

namespace tbridge::test {

// True when this build has every solver named (CMake options TBRIDGE_WITH_IPOPT and
// TBRIDGE_WITH_NLOPT). A test that needs one is tagged [ipopt] or [nlopt], which ctest leaves
// out of a build without it (tests/CMakeLists.txt), and REQUIREs it: it never passes having
// run nothing.
inline bool HaveSolvers(std::initializer_list<SolverKind> solvers) {
  for (SolverKind solver : solvers) {
    if (!SolverBuiltIn(solver)) return false;
  }
  return true;
}

// The paper's planar bridge (SPEC §1): L = 12 m, F = 12000 N, beta = 10 deg, solver as given
// ("auto": the direct solve).
inline Config PaperConfig(int n, SolverKind solver = SolverKind::kAuto) {
  Config c;
  ApplyPaperSwitches(c);
  c.bridge.n = n;
  c.design.solver = solver;
  return c;
}

// `root` (a config or sweep file as JSON) with the paper's switches (ApplyPaperSwitches)
// written into its design and loads sections.
inline nlohmann::json WithPaperSwitches(nlohmann::json root) {
  nlohmann::json& design = root["design"];
  if (!design.contains("yield_safety_factor")) design["yield_safety_factor"] = 10.0;
  if (!design.contains("buckling_safety_factor")) design["buckling_safety_factor"] = 1.0;
  design["self_weight"] = false;
  design["bar_resistance"] = "euler";
  root["loads"] = {{"cases", {"paper"}}};
  return root;
}

// A "sweep" section run as the paper's outer loop: its designs as the minimum-mass problem
// gives them (not verified), the paper's dynamic check (its travelling load, no deck inertia), and
// no constraint the section does not name. Keys the section sets are kept.
inline nlohmann::json PaperSweep(nlohmann::json sweep) {
  sweep.emplace("verified", false);
  sweep["constraints"].emplace("no_slack_under_service", false);
  sweep["constraints"].emplace("bar_capacity_during_motion", false);
  return sweep;
}

// The paper's design for complexity n with default settings, computed once per process.
inline const Design& PaperDesign(int n) {
  static std::map<int, Design> cache;
  auto it = cache.find(n);
  if (it == cache.end()) it = cache.emplace(n, RunDesign(PaperConfig(n))).first;
  return it->second;
}

}  // namespace tbridge::test
