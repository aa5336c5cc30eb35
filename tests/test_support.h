// Shared test helpers: the paper's configs and designs.
#pragma once

#include <map>
#include <string>

#include "core/config.h"
#include "design/design.h"

namespace tbridge::test {

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
