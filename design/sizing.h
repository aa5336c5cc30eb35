// Member sizing from forces (SPEC.md §4): areas, radii, rest lengths, stiffness and masses.
#pragma once

#include <string>

#include "core/material.h"
#include "design/limit_mode.h"

namespace tbridge {

enum class MemberKind { kBar, kString, kDeckString };
const char* KindName(MemberKind kind);  // "bar" | "string" | "deck_string"

struct MemberSizing {
  std::string name;  // "i-j", 1-based
  MemberKind kind = MemberKind::kString;
  int i = 0, j = 0;          // 0-based nodes
  double length = 0;         // stretched (design) length [m]
  double force = 0;          // tension (strings) or compression (bars), >= 0 [N]
  double force_density = 0;  // force / length [N/m]
  double area = 0;           // [m^2]
  double radius = 0;         // solid circular section [m]
  double mass = 0;           // rho A length [kg]
  double rest_length = 0;    // strings: L0 = s / (1 + sigma/E) [m]; bars: length
  double stiffness = 0;      // strings: k = E A / L0 [N/m]; bars: 0 (rigid)
  double stress = 0;         // force / area [Pa]
  // What bounds the area: bars yield, buckling or min_radius, strings yield or min_radius as
  // sized; resized, prestress or stiffness (or the governing mode) once resized or verified.
  LimitMode governed_by = LimitMode::kNone;
  // The force of the reference state (design/design.h), which sets the rest length [N].
  double reference_force = 0;
  double force_min = 0;    // smallest force over every case [N]; < 0: slack or in tension
  double utilisation = 0;  // largest force / resistance over every case (and the dynamic check)
  // What `utilisation` compares: demand / resistance. The governing force [N] (a static case's,
  // or a run's dynamic demand) and the resistance it is held against [N] (A sigma_w; a bar's
  // yield or column-curve buckling resistance); for mode "slack" the strain measure
  // (working strain - strain) and the working strain sigma_w / E instead.
  double demand = 0;
  double resistance = 0;
  std::string governing_case;         // the case of that largest utilisation
  LimitMode mode = LimitMode::kNone;  // yield, buckling, slack, tension, dynamic, or a row's
};

// String working at its material's design stress under `tension`, or at the minimum area when
// that is larger (the extra tension of a prestressed minimum string is part of `tension`); its
// rest length makes it carry `reference_tension` at `length`.
MemberSizing SizeString(double length, double tension, double reference_tension, double min_area,
                        const MemberMaterial& material);

// How a solid circular pinned-pinned bar resists compression.
struct BarRule {
  bool column_curve = false;   // true: EN 1993-1-1 6.3.1.2; false: the paper's bare Euler load
  double yield_stress = 0;     // f_y [Pa]
  double yield_factor = 1;     // gamma_M0: yield resistance A f_y / gamma_M0
  double buckling_factor = 1;  // gamma_M1 (column curve) or SF (Euler) on the buckling resistance
  double imperfection = 0.49;  // alpha of the column curve
};

// Sets m's utilisation to demand / resistance (0 for a resistance of 0), with both and `mode`.
void Govern(MemberSizing& m, double demand, double resistance, LimitMode mode);
// Raises m's utilisation to demand / resistance when that is larger, naming where
// (`governing_case`) and how.
void RaiseUtilisation(MemberSizing& m, double demand, double resistance,
                      const std::string& governing_case, LimitMode mode);

// chi(lambda) of EN 1993-1-1 eq 6.49: Phi = 0.5 [1 + alpha (lambda - 0.2) + lambda^2],
// chi = 1 / (Phi + sqrt(Phi^2 - lambda^2)), at most 1.
double ColumnCurveChi(double slenderness, double alpha);

// The two resistances of a bar of `area` and `length` [N].
struct BarCapacity {
  double yield = 0;     // A f_y / gamma_M0
  double buckling = 0;  // chi A f_y / gamma_M1, or pi E A^2 / (4 l^2) / SF (Euler)
  // Their derivatives with respect to the area [N/m^2], for the sizing's sensitivities.
  double d_yield = 0;
  double d_buckling = 0;
};
BarCapacity BarResistance(double area, double length, const BarRule& rule, double youngs_modulus);

// Solid circular bar: the least area whose resistances both carry `compression`, at least
// `min_area`; governed_by says which bound it. Both sizers throw ConfigError naming the
// material key when the area, stiffness or mass is not finite (inputs at the edge of their
// ranges).
MemberSizing SizeBar(double length, double compression, double min_area, const BarRule& rule,
                     const MemberMaterial& material);

// Area of the Euler-critical solid circular bar: P_cr = pi^2 E I / l^2 with I = A^2/(4 pi).
double EulerArea(double length, double compression, double youngs_modulus);

}  // namespace tbridge
