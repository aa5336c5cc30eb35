// Material constants (SI). `Material` is the bridge's material: the deck beams' always, and
// the bars' and strings' unless `strings` or `bars` gives them their own values (cables for
// the strings, tubes for the bars). An absent value of a member kind is the section's (its
// partial factor: design.yield_safety_factor).
#pragma once

#include <optional>

namespace tbridge {

// What the bars are made of, where it differs from `Material`.
struct BarMaterialConfig {
  std::optional<double> density;            // [kg/m^3]
  std::optional<double> yield_stress;       // f_y [Pa]
  std::optional<double> youngs_modulus;     // E [Pa]
  std::optional<double> partial_factor;     // gamma_M0 on the yield resistance [-]
  std::optional<double> thermal_expansion;  // alpha_T [1/K]
};

// What the strings are made of: a steel rod as a bar is (EN 1993-1-1 6.2.3), or a cable of
// EN 1993-1-11 when `breaking_stress` is given: F_Rd = min(F_uk / 1.5, F_k) / gamma_R (6.3.2)
// with F_uk = k_e f_uk A (the breaking strength after the end terminations' loss factor k_e)
// and F_k = f_k A (the 0.2 % proof strength, `yield_stress`).
struct StringMaterialConfig : BarMaterialConfig {
  std::optional<double> breaking_stress;  // f_uk on the metallic area [Pa]
  std::optional<double> end_efficiency;   // k_e of the end terminations [-]
};

struct Material {
  double density = 7862.0;            // rho [kg/m^3]
  double yield_stress = 6.9e8;        // sigma_yield [Pa]
  double youngs_modulus = 2.06e11;    // E [Pa]
  double thermal_expansion = 1.2e-5;  // alpha_T [1/K]: steel (EN 1993-1-1 3.2.6)
  StringMaterialConfig strings;
  BarMaterialConfig bars;
};

// One member kind's material with every value resolved.
struct MemberMaterial {
  double density = 0;            // [kg/m^3]
  double yield_stress = 0;       // f_y, or a cable's proof strength f_k [Pa]
  double youngs_modulus = 0;     // [Pa]
  double partial_factor = 1;     // gamma_M0, or a cable's gamma_R [-]
  double breaking_stress = 0;    // a cable's f_uk [Pa]; 0: not a cable
  double end_efficiency = 1;     // a cable's k_e [-]
  double thermal_expansion = 0;  // alpha_T [1/K]
  bool cable() const { return breaking_stress > 0; }
  // The design resistance per unit area [Pa]: f_y / gamma_M0, or for a cable
  // min(k_e f_uk / 1.5, f_k) / gamma_R.
  double DesignStress() const;
  // The clause the tension resistance follows ("EN 1993-1-1 6.2.3", "EN 1993-1-11 6.3.2").
  const char* TensionClause() const;
  // The serviceability stress limit under the characteristic combination [Pa]: a rod's
  // f_y / gamma_M,ser (EN 1993-2 7.3(1)), a cable's f_const = f_const_ratio x f_uk (EN 1993-1-11
  // 7.2(2)), which keeps its wires' creep and fatigue small and leaves room for the stress that
  // bending at the sockets adds.
  double ServiceStress(double gamma_m_ser, double f_const_ratio) const;
  // The clause that limit follows ("EN 1993-2 7.3(1)", "EN 1993-1-11 7.2(2)").
  const char* ServiceClause() const;
};

// The resolved materials; `yield_safety_factor` is design.yield_safety_factor.
MemberMaterial StringMaterial(const Material& m, double yield_safety_factor);
MemberMaterial BarMaterial(const Material& m, double yield_safety_factor);

}  // namespace tbridge
