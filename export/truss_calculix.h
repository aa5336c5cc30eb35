// A structure's design (truss/truss_design.h) as a CalculiX input deck, for a second opinion on its
// analysis: each member a SPRINGA element of force N0 + (E A / L) e at elongation e (N0 its
// prestress, 0 without), its consistent mass as m/6 at each end and 2m/3 at
// a midpoint node held to the ends' mean by *EQUATION (export/calculix.h says why not T3D2), the
// node masses, one *STATIC step per load case with its factored loads and the members' factored
// weight (linear, or geometrically nonlinear where the structure is prestressed or its analysis
// nonlinear), and a *FREQUENCY step of the unloaded structure (a perturbation about the
// prestressed state where there is one). Each static step prints U of
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
