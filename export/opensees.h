// A design as an OpenSees Tcl script: the bridge tbridge analyses, for a second opinion from
// an FE program (README.md, "Export").
//
// Every member is a corotTruss on its own material. A string is `uniaxialMaterial Elastic`
// with zero compression modulus, wrapped in InitStrainMaterial for its prestrain: with the
// modulus E' = E s / L0 and the initial strain (s - L0) / s, where s is its drawn length and
// L0 its rest length, its force E' A (l - L0) / s is tbridge's k (l - L0), zero below L0. A bar
// is Elastic (E, or kRigidBarFactor E with rigid bars) with the initial strain of its reference
// compression. Masses: each bar's (string shares included) as its density per length with
// the consistent mass matrix, and the modal model's node masses. The reference loads are
// pattern 1; each load case (each travelling station its own) is a proc `case_K TAG` that
// defines its pattern, so that a script can analyse one at a time from the reference state.
#pragma once

#include <ostream>

#include "export/fe_model.h"

namespace tbridge {

void WriteOpenSees(const FeModel& model, bool rigid_bars, std::ostream& os);

}  // namespace tbridge
