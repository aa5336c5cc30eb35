// A structure's design (truss/truss_design.h) as a CalculiX input deck, for a second opinion on its
// linear analysis: each member a SPRINGA element of axial stiffness E A / L (linear, through zero:
// the designed structure carries no prestress), its consistent mass as m/6 at each end and 2m/3 at
// a midpoint node held to the ends' mean by *EQUATION (export/calculix.h says why not T3D2), the
// node masses, one linear *STATIC step per load case with its factored loads and the members'
// factored weight, and a *FREQUENCY step of the unloaded structure. Each static step prints U of
// the structure's nodes (NSET NODES); "** tbridge step: NAME" names it. Not RF: CalculiX evaluates
// a SPRINGA's force along the member as displaced even in a linear step, so its reactions differ
// from the linear theory's by the members' rotation (0.3-1 % on the 10-bar truss, and they do not
// sum to the loads), while its displacements are the linear solution's.
#pragma once

#include <ostream>

#include "truss/truss_design.h"

namespace tbridge {

// `modes`: the frequencies asked of CalculiX (0: no frequency step).
void WriteTrussCalculix(const TrussDesign& design, int modes, std::ostream& os);

}  // namespace tbridge
