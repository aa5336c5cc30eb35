// Which strings may go slack. The deck chain carries the planar bridge's one self-stress: it
// must stay taut, and a design whose deck chain goes slack fails. Any other string may go
// slack when the bridge carries the load without it.

#include <catch2/catch.hpp>

#include "checks/verdict.h"
#include "core/config.h"
#include "sizing/verified_design.h"

namespace tbridge {
namespace {

TEST_CASE(
    "a deck chain that goes slack fails the design and only a string that must stay taut fails for "
    "slack",
    "[verify]") {
  // The 40 m footbridge with the paper's blanket (yield factor 10, Euler, its one case): its
  // deck strings, prestressed at exactly the working stress, go slack under the paper's
  // travelling load (README, "The trade").
  Config blanket = LoadConfig(TBRIDGE_SOURCE_DIR "/configs/footbridge_steel_40m.json");
  ApplyPaperSwitches(blanket);
  const Design d = DesignAndVerify(blanket);
  const Verdict v = DesignVerdict(d);
  CHECK_FALSE(v.pass);
  bool deck_slack = false;
  for (int k = 0; k < static_cast<int>(d.strings.size()); ++k) {
    const MemberSizing& m = d.strings[k];
    INFO("string " << m.name << ": " << NameOf(m.mode) << " " << m.utilisation);
    if (m.mode != LimitMode::kSlack) continue;
    // Only a string that must stay taut is failed for going slack, and then by more than 1.
    CHECK(MustStayTaut(d, k));
    CHECK(m.utilisation > 1.0);
    deck_slack = deck_slack || m.kind == MemberKind::kDeckString;
  }
  CHECK(deck_slack);
}

}  // namespace
}  // namespace tbridge
