// The static check of a sized design: each load case solved as a nonlinear static problem
// of the prestressed bridge (statics/static_solve.h: rigid bars, strings that go slack, large
// displacements) from its reference state, for deflections, support reactions and member
// forces. What it finds is a report; the design records it (sizing/verified_design.h).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/progress.h"
#include "design/design.h"
#include "design/prestress_states.h"
#include "design/verification.h"
#include "statics/static_solve.h"

namespace tbridge {

// Solves every case and reports each member's largest utilisation under them
// (StaticCheck::members): bars and strings under the ultimate cases, slack strings that must
// stay taut under the serviceability cases (mode "slack"), and the largest deflection.
// A travelling family is solved at every deck station, first linearly about the reference
// state (statics/static_solve.h StaticTangent: one factorisation, a solve per station and one
// per family), then nonlinearly where the linear pass comes within loads.station_margin of
// the largest it found (of a member's utilisation, of the deflection) or of the limit 1
// (core/config_fields.h says why the default margin holds). The solves run in two lanes
// (core/two_lanes.h), each case's stations split in halves; each station's solve starts from
// the last station's equilibrium (the reference state's for a half's first, or after one that
// did not converge; StaticSeries, statics/static_solve.h), to the same equilibrium within the
// solve's tolerance (forces balanced to 1e-10 of the largest;
// tests/verify/station_screen_test.cc). On a symmetric design (its structure, string sizes,
// reference loads and state their own mirror images about mid-span; design/mirror.h
// MidSpanMirror) under a family that is its own image, a station past mid-span is not solved:
// its response is the mirror image of its image station's (StaticCheck::mirrored). The
// default at n = 8 solves 396 of 777. Changes nothing in `design`.
// `progress` (optional) is told the nonlinear solves done against their number, as stage
// "static check".
StaticCheck CheckStatics(const Design& design, ProgressReporter* progress = nullptr);

// The static check of `design` in each state of its prestress (PrestressStatesOf: as designed,
// after the loss, with the rest lengths off by their tolerance; DesignInState): the other
// states' cases, their labels with the state's suffix, after the design's own; each member's
// finding, the deflection and the abutments' reactions the largest over the states. A state with
// no reference state (its rest lengths changed, the bridge does not stand) fails the check with
// a case that says so.
// `others`: the design's other states (OtherStates).
StaticCheck CheckStaticsInEveryState(const Design& design, const std::vector<DesignState>& others,
                                     ProgressReporter* progress = nullptr);

// The case and deck station a label names, as the static check and the design file write it:
// "NAME" for a case that does not travel (station -1), "NAME at node N" for a travelling case
// at the station whose first deck node is N (1-based). Throws ConfigError naming `key`, the
// label and the labels allowed.
struct CaseAt {
  int case_index = -1;
  int station = -1;
  int state = 0;  // the state of the prestress (PrestressStatesOf's index), by the label's suffix
};
CaseAt CaseOfLabel(const Design& design, const std::string& label, const std::string& key);

// The node positions [m] (3 x n_n) under that case, solved as the static check solves it: the
// nonlinear static problem from the reference state. Throws ModelError when it does not
// converge.
Eigen::Matrix3Xd SolveCaseNodes(const Design& design, const CaseAt& at);

}  // namespace tbridge
