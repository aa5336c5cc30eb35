// A structure's design (truss/truss_design.h) as an OpenSees Tcl script that runs as it stands:
// each member an element on its own material, `truss` where the design's statics is linear and
// unstressed, `corotTruss` (turning with its chord) where it is prestressed or nonlinear; the
// material `Elastic` E, wrapped in `InitStrainMaterial` of strain N0 / (E A) for a prestress N0,
// so that its force is N0 + E A (l - L) / L as tbridge's; each member's consistent mass (-rho,
// -cMass), the node masses. Each load case (its factored loads and the members' factored
// weight) is a proc `case_K TAG`, and every case is analysed from the drawn state with
// recorders of the displacements and the support reactions (export/opensees.h).
#pragma once

#include <ostream>

#include "truss/truss_design.h"

namespace tbridge {

void WriteTrussOpenSees(const TrussDesign& design, std::ostream& os);

}  // namespace tbridge
