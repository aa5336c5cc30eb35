// A design as a CalculiX input deck (.inp): the bridge tbridge analyses, for a second opinion
// from an FE program (README.md, "Export").
//
// - Strings: SPRINGA elements (corotational axial springs) with *SPRING, NONLINEAR: the tension
//   k (s - L0) tbridge uses, zero below the rest length, so the reference tension is the table's
//   force at the drawn length.
// - Bars: SPRINGA elements that start from their reference compression: elastic (E A / l) or,
//   with `rigid_bars`, kRigidBarFactor times stiffer, which stands for tbridge's rigid bars.
// - Masses: the modal model's node masses, and each bar's mass (string shares included) as m/6
//   at each end and 2m/3 at a midpoint node held to the ends' mean by *EQUATION: the consistent
//   mass of a uniform bar, exactly (a rigid body's mass, centre and inertia).
// - Steps: the reference state; then each load case (each travelling station its own) followed
//   by a step back to the reference loads, so that every case starts from the prestressed
//   reference state, the springs being elastic; then the modal model's loads and *FREQUENCY
//   about that state (PERTURBATION). Each static step prints U of the design's nodes (NSET
//   NODES) and RF of the supports (NSET SUPPORTS) to the .dat file; a comment line
//   "** tbridge step: LABEL" names the case of each step.
#pragma once

#include <ostream>
#include <string>

#include "export/fe_model.h"

namespace tbridge {

// Bar stiffness over E A / l with --rigid-bars: a bar then shortens by 1e-6 of its elastic
// shortening, far below the 1e-5 the comparison with tbridge asks for.
inline constexpr double kRigidBarFactor = 1e6;

struct CalculixOptions {
  bool rigid_bars = false;
  int modes = 10;  // eigenmodes asked of *FREQUENCY (capped at a quarter of the model's motions)
};

void WriteCalculix(const FeModel& model, const CalculixOptions& options, std::ostream& os);

// A number as a CalculiX field: always with a decimal point (CalculiX reads a number without one
// as an integer field), in at most 20 characters (its field width): 14 digits.
std::string CalculixNumber(double v);

}  // namespace tbridge
