// A design's one verdict, PASS / FAIL / INCOMPLETE, from its checks' reports.
#pragma once

#include <string>

#include "design/deck_beams.h"
#include "design/design.h"

namespace tbridge {

// The design's one verdict, built from its checks' reports. FAIL: a member's utilisation over
// 1 (1e-9 allows for the rounding of a member sized exactly to its resistance), unstable, a
// static case with no equilibrium, a deflection over its limit or a deck mode over its comfort
// limit. Otherwise INCOMPLETE when a check, a run or an asked-for case was not done (comfort
// counts when comfort.check asks for it and the paper's switches are off), else PASS.
enum class VerdictOutcome { kPass, kFail, kIncomplete };
const char* VerdictName(VerdictOutcome outcome);  // "PASS" | "FAIL" | "INCOMPLETE"
struct Verdict {
  VerdictOutcome outcome = VerdictOutcome::kIncomplete;
  bool pass = false;  // outcome == kPass
  double utilisation_max = 0;
  std::string governing;     // "member 3-5 (buckling, uls_payload_full)"
  std::string summary;       // "PASS: ...", "FAIL: ...; ..." or "INCOMPLETE: ...; ..."
  std::string scope;         // what the checks cover, and what they do not
  DeckBeamCheck deck_beams;  // the deck beams' check the verdict read (design/deck_beams.h)
};
Verdict DesignVerdict(const Design& design);

}  // namespace tbridge
