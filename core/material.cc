#include "core/material.h"

#include <algorithm>

namespace tbridge {

namespace {

MemberMaterial Resolve(const Material& m, const BarMaterialConfig& own,
                       double yield_safety_factor) {
  MemberMaterial out;
  out.density = own.density.value_or(m.density);
  out.yield_stress = own.yield_stress.value_or(m.yield_stress);
  out.youngs_modulus = own.youngs_modulus.value_or(m.youngs_modulus);
  out.partial_factor = own.partial_factor.value_or(yield_safety_factor);
  out.thermal_expansion = own.thermal_expansion.value_or(m.thermal_expansion);
  return out;
}

}  // namespace

double MemberMaterial::DesignStress() const {
  // EN 1993-1-11 6.3.2: the 1.5 keeps a cable's stress at the ultimate load well below its
  // breaking strength, where the wires' fatigue and creep stay small.
  const double strength =
      cable() ? std::min(end_efficiency * breaking_stress / 1.5, yield_stress) : yield_stress;
  return strength / partial_factor;
}

const char* MemberMaterial::TensionClause() const {
  return cable() ? "EN 1993-1-11 6.3.2" : "EN 1993-1-1 6.2.3";
}

double MemberMaterial::ServiceStress(double gamma_m_ser, double f_const_ratio) const {
  return cable() ? f_const_ratio * breaking_stress : yield_stress / gamma_m_ser;
}

const char* MemberMaterial::ServiceClause() const {
  return cable() ? "EN 1993-1-11 7.2(2)" : "EN 1993-2 7.3(1)";
}

MemberMaterial StringMaterial(const Material& m, double yield_safety_factor) {
  MemberMaterial out = Resolve(m, m.strings, yield_safety_factor);
  out.breaking_stress = m.strings.breaking_stress.value_or(0.0);
  out.end_efficiency = m.strings.end_efficiency.value_or(1.0);
  return out;
}

MemberMaterial BarMaterial(const Material& m, double yield_safety_factor) {
  return Resolve(m, m.bars, yield_safety_factor);
}

}  // namespace tbridge
