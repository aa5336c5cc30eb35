// The first derivatives of one vibration mode's eigenvalue with respect to each member's
// stiffness, force and mass, about the model's positions (dynamics/modal.h's constrained,
// rigid-bar model). For a simple eigenvalue omega^2 with its mass-normalised shape phi
// (phi^T M phi = 1) and the bar lengths held,
//
//   d omega^2 = phi^T (dK - omega^2 dM) phi
//
// (Haftka and Gürdal, Elements of Structural Optimization, 1992, sect. 7.3.1), so each member's
// share is a few products of its end nodes' shape. A repeated eigenvalue has directional
// derivatives only; these are then the derivatives of the Rayleigh quotient of the given shape,
// which bounds the cluster (the comfort rows pose every mode of a cluster).
//
// The terms, as modal.h assembles K and M:
//   string (taut: s >= L0): K_s = k e e^T + (T / s)(I - e e^T) on [dphi = phi_j - phi_i]:
//     d omega^2 / dk = (e^T dphi)^2,  d omega^2 / dT = (|dphi|^2 - (e^T dphi)^2) / s;
//     a slack string has neither;
//   bar: -(C / l) I, C its compression: d omega^2 / dC = -|dphi|^2 / l;
//   mass: a bar's m [1/3 1/6; 1/6 1/3] (x) I; a string's mass shared onto bars or nodes as
//     ForEachStringMassShare states: d omega^2 / dm = -omega^2 phi^T (dM/dm) phi, and
//     phi^T (dM/dm) phi is what the Rayleigh quotient's denominator moves by.
#pragma once

#include <vector>

#include "dynamics/modal.h"
#include "dynamics/model.h"

namespace tbridge {

struct ModeEnergies {
  double omega_squared = 0;  // [rad^2/s^2]
  // Per member [bars; strings], the derivative of omega^2 by:
  std::vector<double>
      by_stiffness;  // a string's axial stiffness k [rad^2/s^2 per N/m]; 0 for a bar
  std::vector<double>
      by_force;  // its tension T (string, k held) or compression C (bar) [rad^2/s^2 per N]
  // Per member, phi^T (dM/dm) phi for its own mass m (rho A L), shared as the model shares it
  // [1/kg]: omega^2 moves by -omega^2 times it per kg.
  std::vector<double> mass_energy;
};

// Of `mode` (mass-normalised, as ComputeModes gives it) of `model`, whose string mass is shared
// by `string_mass` (the mode BuildDynamicModel was given). O(members).
ModeEnergies ModeEnergiesOf(const DynamicModel& model, const Mode& mode,
                            StringMassMode string_mass);

}  // namespace tbridge
