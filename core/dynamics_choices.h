// The choices of a dynamic run (dynamics.integrator, dynamics.engine, dynamics.string_mass)
// as enums with their texts: parsed once at the config boundary, compared as values past it.
#pragma once

#include <array>

#include "core/named_choice.h"

namespace tbridge {

// dynamics.integrator: see DynamicsConfig::integrator.
enum class IntegratorKind { kAuto, kRk4, kDopri5, kSdirk3 };
inline constexpr std::array<Named<IntegratorKind>, 4> kIntegratorNames{
    {{IntegratorKind::kAuto, "auto"},
     {IntegratorKind::kRk4, "rk4"},
     {IntegratorKind::kDopri5, "dopri5"},
     {IntegratorKind::kSdirk3, "sdirk3"}}};

// dynamics.engine: see DynamicsConfig::engine.
enum class EngineKind { kAuto, kClass1, kClassK };
inline constexpr std::array<Named<EngineKind>, 3> kEngineNames{{{EngineKind::kAuto, "auto"},
                                                                {EngineKind::kClass1, "class1"},
                                                                {EngineKind::kClassK, "classk"}}};

// How string mass enters the dynamics (eq 27); dynamics.string_mass.
enum class StringMassMode {
  kOnBars,   // "bars": half of each string's mass goes to the bar at each end, spread uniformly (eq
             // 27)
  kAtNodes,  // "nodes": half of each string's mass lumped at each end node
  kOff       // "off": massless strings
};
inline constexpr std::array<Named<StringMassMode>, 3> kStringMassNames{
    {{StringMassMode::kOnBars, "bars"},
     {StringMassMode::kAtNodes, "nodes"},
     {StringMassMode::kOff, "off"}}};

inline const char* NameOf(IntegratorKind k) { return NameIn(kIntegratorNames, k); }
inline const char* NameOf(EngineKind k) { return NameIn(kEngineNames, k); }
inline const char* NameOf(StringMassMode k) { return NameIn(kStringMassNames, k); }

}  // namespace tbridge
