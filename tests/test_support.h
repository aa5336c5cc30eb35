// Shared helpers for the design tests: paper configs and member lookup by name.
#pragma once

#include <string>

#include "core/config.h"
#include "design/design.h"

namespace tbridge::test {

// The paper's planar bridge (SPEC §1): L = 12 m, F = 12000 N, beta = 10 deg, solver as given.
inline Config PaperConfig(int n, const std::string& solver = "ipopt") {
  Config c;
  c.bridge.n = n;
  c.design.solver = solver;
  return c;
}

// Finds a member by its "i-j" name in either node order; nullptr when absent.
inline const MemberSizing* FindMember(const Design& d, const std::string& name) {
  const auto dash = name.find('-');
  const std::string flipped = name.substr(dash + 1) + "-" + name.substr(0, dash);
  for (const auto* list : {&d.bars, &d.strings}) {
    for (const MemberSizing& m : *list) {
      if (m.name == name || m.name == flipped) return &m;
    }
  }
  return nullptr;
}

}  // namespace tbridge::test
