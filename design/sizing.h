// Member sizing from forces (SPEC.md §4): areas, radii, rest lengths, stiffness and masses.
#pragma once

#include <string>

#include "core/material.h"

namespace tbridge {

enum class MemberKind { kBar, kString, kDeckString };
const char* KindName(MemberKind kind);  // "bar" | "string" | "deck_string"

struct MemberSizing {
  std::string name;         // "i-j", 1-based
  MemberKind kind = MemberKind::kString;
  int i = 0, j = 0;         // 0-based nodes
  double length = 0;        // stretched (design) length [m]
  double force = 0;         // tension (strings) or compression (bars), >= 0 [N]
  double force_density = 0; // force / length [N/m]
  double area = 0;          // [m^2]
  double radius = 0;        // solid circular section [m]
  double mass = 0;          // rho A length [kg]
  double rest_length = 0;   // strings: L0 = s / (1 + sigma/E) [m]; bars: length
  double stiffness = 0;     // strings: k = E A / L0 [N/m]; bars: 0 (rigid)
  double stress = 0;        // force / area [Pa]
  std::string governed_by;  // bars: "yield" | "buckling" | "min_radius"; strings: "yield" |
                            // "min_radius"
};

// String working at `working_stress`, or at the minimum area when that is larger (the extra
// tension of a prestressed minimum string is part of `tension`).
MemberSizing SizeString(double length, double tension, double min_area, double working_stress,
                        const Material& material);

// Solid circular bar: A = max(C / sigma_w, 2 l sqrt(SF C / (pi E)), min_area).
// Both throw ConfigError naming the material key when the area, stiffness or mass is not
// finite (inputs at the edge of their ranges).
MemberSizing SizeBar(double length, double compression, double min_area, double working_stress,
                     double buckling_safety_factor, const Material& material);

// Area of the Euler-critical solid circular bar: P_cr = pi^2 E I / l^2 with I = A^2/(4 pi).
double EulerArea(double length, double compression, double youngs_modulus);

}  // namespace tbridge
