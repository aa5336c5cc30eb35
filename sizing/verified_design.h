// A design that holds under its own checks: the minimum-mass design, its static and dynamic
// checks (checks/static_check.h, checks/dynamic_check.h), and a fully-stressed resizing of
// what fails, repeated.
//
// Each pass designs with per-member area floors (RunDesign's `area_floor`), so the self-weight
// fixed point, the prestress and the rest lengths are recomputed with the new sizes. A member
// that fails in yield grows by its utilisation, one that buckles by its square root (Euler's
// load grows with A^2); a slack string that must stay taut (MustStayTaut) or a deflection
// past its limit stiffens every string by the deflection's excess (at least 10 %). Floors only
// rise, so no member shrinks while it fails. The loop ends when the verdict passes or after
// `design.max_sizings` designs, saying why not. With the paper's switches (loads.cases ["paper"])
// the design is the paper's: it is checked and reported, not resized.
#pragma once

#include <string>
#include <vector>

#include "core/progress.h"
#include "design/design.h"
#include "design/verification.h"

namespace tbridge {

// Records the checks' reports in the design: each member's utilisation rises to the largest
// the checks found (with its case and mode), and the reports are kept for the outputs. The
// checks themselves change nothing; this is the one place their findings enter a design.
void RecordChecks(Design& design, StaticCheck statics, DynamicCheck dynamics, ComfortCheck comfort);

// `tbridge check`: the checks run again on a design as given (read from its file), nothing
// resized. The utilisations the design carried are dropped first: they become the checks' own.
// `progress` (optional) follows the checks, stage by stage.
void CheckAgain(Design& design, ProgressReporter* progress = nullptr);

// The areas that mend a checked design member by member: each member that a check found over
// its resistance (a string's yield, a bar's yield or buckling, a run's peak) gets the area whose
// resistance carries the found demand with a margin of 2e-4, and the members of its group
// (`group_of`, per member [bars; strings]: its mirror images) the largest of theirs. `mended`
// gets how many failed. Empty where a member fails otherwise (a taut string gone slack), which
// no area mends. The verified sizing mends so a design whose mass has settled while it fails.
std::vector<double> MendedAreas(const Design& design, const std::vector<int>& group_of,
                                int* mended);

// Sizes to start a verified design from, in place of its equilibrium design's: another
// design's of the same bridge drawn otherwise (the angle's search starts each angle from the
// nearest angle designed, whose optimum lies near).
struct SizingStart {
  std::vector<double> areas;         // [m^2] per member [bars; strings]
  Eigen::VectorXd prestress_forces;  // [N] per member: projected on the bridge's self-stresses
};

// The last design, with its static check and its `resizing` record.
// At most config.design.max_sizings sizings. `start` (optional) replaces the first design's
// sizes as the first sizing's start; the second start and the mass's premium still refer to
// the first design's, and a start whose member count differs is not used.
//
// `piece_below`: whether a binding comfort row's piece below is tried once the loop settles
// (docs/verified_sizing.md); the angle's search leaves it to the angle chosen: tried at every
// angle, it took the 30 m footbridge's search at n = 4 from 16 s to 85 s for the same masses.
enum class PieceBelowTrial { kTried, kNotTried };
Design DesignAndVerify(const Config& config, ProgressReporter* progress = nullptr,
                       const SizingStart* start = nullptr,
                       PieceBelowTrial piece_below = PieceBelowTrial::kTried);

}  // namespace tbridge
