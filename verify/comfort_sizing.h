// The comfort check as a constraint of the verified sizing (verify/verified_design.h), by an
// outer correction rather than eigenvalue sensitivities in the sizing's program.
//
// At resonance a mode's steady acceleration F* / (2 xi M*) does not depend on its stiffness,
// only on where its frequency lies: psi(f) and Sétra's range (which load case, if any). The deck
// beams' and the crowd's mass is given and the damping too, so what the sizing can change is the
// frequency, by the stiffness. For each failing mode the correction finds the least frequency
// scale s >= 1 (both the crowded and the empty frequency moved by s, its modal mass and shape
// kept) at which the mode passes: either its acceleration falls within the limit (psi falls on
// the flank of its trapezoid), or it leaves the risk ranges its class is checked in (psi or the
// load case vanish), whichever comes first, which is the lighter. The next sizing then asks
// for s^2 times the stiffness (SizingCorrections::stiffness_factor on every deflection), and a
// design that still fails is corrected again from its own frequencies.
#pragma once

#include <string>

#include "design/design.h"
#include "design/sizing_problem.h"

namespace tbridge {

struct ComfortCorrection {
  double stiffness_factor = 1.0;  // on the stiffness the next sizing asks for (1: comfort passes)
  std::string governs;            // which mode asks for it and why; empty when none
};

// The correction `design`'s comfort report asks for (design.comfort, recorded). Changes nothing.
ComfortCorrection ComfortCorrectionOf(const Design& design);

// Applies it: the sizing's stiffness factor and the record's comfort fields. Does nothing when
// comfort.sizing_constraint is false.
void CorrectForComfort(const Design& design, SizingCorrections& corrections, Resizing& record);

}  // namespace tbridge
