// What a member's cross-section area sets, each written once: the radius of its solid round
// section, its mass over a length and its axial stiffness over its rest length. The sizing, the
// design reader, the dynamic model, the sweep's deck-string growth and the truss all take these
// from here, so a member's area means the same in every output.
#pragma once

#include <cmath>
#include <numbers>

namespace tbridge {

// The radius [m] of a solid round section of `area` [m^2] (area >= 0).
inline double RadiusOfArea(double area) { return std::sqrt(area / std::numbers::pi); }

// The mass rho A l [kg] of `length` [m] of a member of `area` [m^2] and `density` [kg/m^3].
inline double MassOfArea(double density, double area, double length) {
  return density * area * length;
}

// The axial stiffness E A / L0 [N/m] of a member of `area` [m^2], Young's modulus
// `youngs_modulus` [Pa] and rest length `rest_length` [m] > 0.
inline double AxialStiffness(double youngs_modulus, double area, double rest_length) {
  return youngs_modulus * area / rest_length;
}

// The rest length L0 = L / (1 + T / (E A)) [m] of a string of `area` [m^2] that carries
// `force` [N] at `length` [m]; the length itself where the area is 0.
inline double RestLengthOfArea(double youngs_modulus, double area, double force, double length) {
  return length / (1.0 + (area > 0 ? force / area : 0.0) / youngs_modulus);
}

// The same stiffness, E A / L0 at L0 = RestLengthOfArea(E, A, T, L), written from the length
// the string is at: (E A + T) / L [N/m]. The sizing takes this form because it is linear in
// (A, T): at (dA, dT) it is the stiffness's derivative along that change.
inline double TautStringStiffness(double youngs_modulus, double area, double force, double length) {
  return (youngs_modulus * area + force) / length;
}

}  // namespace tbridge
