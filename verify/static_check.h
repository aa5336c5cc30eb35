// The static check of a sized design: each load case solved as a nonlinear static problem
// of the prestressed bridge (statics/static_solve.h: rigid bars, strings that go slack, large
// displacements) from its reference state, for deflections, support reactions and member
// forces. What it finds is a report; the design records it (verify/verified_design.h).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "design/design.h"
#include "design/verification.h"
#include "core/progress.h"
#include "statics/static_solve.h"

namespace tbridge {

// Solves every case and reports each member's largest utilisation under them
// (StaticCheck::members): bars and strings under the ultimate cases, slack strings that must
// stay taut under the serviceability cases (mode "slack"), and the largest deflection.
// A travelling family is solved at every deck station, first linearly about the reference
// state (statics/static_solve.h StaticTangent: one factorisation, a solve per station and one
// per family), then nonlinearly where the linear pass comes within loads.station_margin of
// the largest it found (of a member's utilisation, of the deflection) or of the limit 1
// (core/config_fields.h says why the default margin holds). Changes nothing in `design`.
// `progress` (optional) is told the nonlinear solves done against their number, as stage
// "static check".
StaticCheck CheckStatics(const Design& design, ProgressReporter* progress = nullptr);

}  // namespace tbridge
