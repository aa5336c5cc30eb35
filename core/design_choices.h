// The choices of a design's config (design.bar_resistance, design.solver, loads.dynamic_method,
// comfort.*) as enums with their texts: parsed once at the config boundary, compared as values
// past it. The texts are those of the config file and of every output, unchanged: scripts read
// them.
#pragma once

#include <array>

#include "core/named_choice.h"

namespace tbridge {

// design.bar_resistance: see DesignConfig::bar_resistance.
enum class BarResistanceRule { kColumnCurve, kEuler };
inline constexpr std::array<Named<BarResistanceRule>, 2> kBarResistanceNames{
    {{BarResistanceRule::kColumnCurve, "column_curve"}, {BarResistanceRule::kEuler, "euler"}}};

// design.deck_section: see DesignConfig::deck_section.
enum class DeckSection { kPlate, kGirders };
inline constexpr std::array<Named<DeckSection>, 2> kDeckSectionNames{
    {{DeckSection::kPlate, "plate"}, {DeckSection::kGirders, "girders"}}};

// loads.dynamic_method: see LoadsConfig::dynamic_method.
enum class DynamicMethod { kModal, kRk4 };
inline constexpr std::array<Named<DynamicMethod>, 2> kDynamicMethodNames{
    {{DynamicMethod::kModal, "modal"}, {DynamicMethod::kRk4, "rk4"}}};

// comfort.traffic_class: Sétra's Stage 1 classes, from very dense crowds (I) to seldom used (IV).
enum class TrafficClass { kI, kII, kIII, kIV };
inline constexpr std::array<Named<TrafficClass>, 4> kTrafficClassNames{{{TrafficClass::kI, "I"},
                                                                        {TrafficClass::kII, "II"},
                                                                        {TrafficClass::kIII, "III"},
                                                                        {TrafficClass::kIV, "IV"}}};

// comfort.comfort_level: Sétra's Stage 2 level asked for.
enum class ComfortLevel { kMaximum, kMean, kMinimum };
inline constexpr std::array<Named<ComfortLevel>, 3> kComfortLevelNames{
    {{ComfortLevel::kMaximum, "maximum"},
     {ComfortLevel::kMean, "mean"},
     {ComfortLevel::kMinimum, "minimum"}}};

// comfort.construction: what sets the damping ratio's default (Sétra, HiVoSS 4.4.2).
enum class Construction { kSteel, kComposite, kPrestressedConcrete, kReinforcedConcrete, kTimber };
inline constexpr std::array<Named<Construction>, 5> kConstructionNames{
    {{Construction::kSteel, "steel"},
     {Construction::kComposite, "composite"},
     {Construction::kPrestressedConcrete, "prestressed_concrete"},
     {Construction::kReinforcedConcrete, "reinforced_concrete"},
     {Construction::kTimber, "timber"}}};

// The solvers: design.solver's values (kSolverChoiceNames) and the one that ran, in the outputs'
// `solver.name` (kSolverNames: also "sqp", the verified sizing's own, and "none", a design read
// from its file). One enum for both, as the config's choice is the solver that runs wherever it
// names one.
enum class SolverKind { kAuto, kNone, kDirect, kSqp, kIpopt, kNlopt };
inline constexpr std::array<Named<SolverKind>, 4> kSolverChoiceNames{
    {{SolverKind::kAuto, "auto"},
     {SolverKind::kDirect, "direct"},
     {SolverKind::kIpopt, "ipopt"},
     {SolverKind::kNlopt, "nlopt"}}};
inline constexpr std::array<Named<SolverKind>, 6> kSolverNames{{{SolverKind::kAuto, "auto"},
                                                                {SolverKind::kNone, "none"},
                                                                {SolverKind::kDirect, "direct"},
                                                                {SolverKind::kSqp, "sqp"},
                                                                {SolverKind::kIpopt, "ipopt"},
                                                                {SolverKind::kNlopt, "nlopt"}}};

// loads.cases: see LoadsConfig::cases.
enum class LoadFamily {
  kPaper,
  kPermanent,
  kPayload,
  kTravelling,
  kPaperTravelling,
  kWind,
  kTemperature
};
inline constexpr std::array<Named<LoadFamily>, 7> kLoadFamilyNames{
    {{LoadFamily::kPaper, "paper"},
     {LoadFamily::kPermanent, "permanent"},
     {LoadFamily::kPayload, "payload"},
     {LoadFamily::kTravelling, "travelling"},
     {LoadFamily::kPaperTravelling, "paper_travelling"},
     {LoadFamily::kWind, "wind"},
     {LoadFamily::kTemperature, "temperature"}}};

inline const char* NameOf(BarResistanceRule k) { return NameIn(kBarResistanceNames, k); }
inline const char* NameOf(DeckSection k) { return NameIn(kDeckSectionNames, k); }
inline const char* NameOf(DynamicMethod k) { return NameIn(kDynamicMethodNames, k); }
inline const char* NameOf(TrafficClass k) { return NameIn(kTrafficClassNames, k); }
inline const char* NameOf(ComfortLevel k) { return NameIn(kComfortLevelNames, k); }
inline const char* NameOf(Construction k) { return NameIn(kConstructionNames, k); }
inline const char* NameOf(SolverKind k) { return NameIn(kSolverNames, k); }
inline const char* NameOf(LoadFamily k) { return NameIn(kLoadFamilyNames, k); }

// Each enum's table, by its type: for code that reads or writes any of them alike (the design
// file's record of the loads, io/design_loads.cc).
inline constexpr const auto& NamesOf(TrafficClass) { return kTrafficClassNames; }
inline constexpr const auto& NamesOf(ComfortLevel) { return kComfortLevelNames; }

}  // namespace tbridge
