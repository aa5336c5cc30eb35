// Config of a custom tensegrity scene (the "structure" section): nodes, supports, bars,
// strings, node masses and constant loads given directly, for `tbridge simulate` and `modes`
// without a design. Plain data, SI units, node numbers 1-based as in every message and output.
// Every key is described once in core/structure_fields.h: unit, range and meaning, from which
// the parse, the echo, Validate() and the README's key table come.
#pragma once

#include <array>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/named_choice.h"

namespace tbridge {

class JsonSection;

// structure.groups[].kind: what a designed group may carry.
enum class TrussKind { kString, kBar, kTruss };
inline constexpr std::array<Named<TrussKind>, 3> kTrussKindNames{
    {{TrussKind::kString, "string"}, {TrussKind::kBar, "bar"}, {TrussKind::kTruss, "truss"}}};

// structure.groups[].buckling: see StructureGroupConfig::buckling.
enum class BucklingRule { kAuto, kEuler, kNone };
inline constexpr std::array<Named<BucklingRule>, 3> kBucklingRuleNames{
    {{BucklingRule::kAuto, "auto"},
     {BucklingRule::kEuler, "euler"},
     {BucklingRule::kNone, "none"}}};

// structure.limits.displacements[].axis; its value is the coordinate's index.
enum class Axis { kX = 0, kY = 1, kZ = 2 };
inline constexpr std::array<Named<Axis>, 3> kAxisNames{
    {{Axis::kX, "x"}, {Axis::kY, "y"}, {Axis::kZ, "z"}}};

// structure.prestress: see StructureConfig::prestress.
enum class StructurePrestress { kNone, kVariable };
inline constexpr std::array<Named<StructurePrestress>, 2> kStructurePrestressNames{
    {{StructurePrestress::kNone, "none"}, {StructurePrestress::kVariable, "variable"}}};

// structure.analysis: the statics of every case linear about the drawn (prestressed) state, or
// geometrically nonlinear (truss/truss_nonlinear.h). The modes are the drawn state's either way.
enum class TrussAnalysisKind { kLinear, kNonlinear };
inline constexpr std::array<Named<TrussAnalysisKind>, 2> kTrussAnalysisNames{
    {{TrussAnalysisKind::kLinear, "linear"}, {TrussAnalysisKind::kNonlinear, "nonlinear"}}};

inline const char* NameOf(TrussKind k) { return NameIn(kTrussKindNames, k); }
inline const char* NameOf(BucklingRule k) { return NameIn(kBucklingRuleNames, k); }
inline const char* NameOf(Axis k) { return NameIn(kAxisNames, k); }
inline const char* NameOf(StructurePrestress k) { return NameIn(kStructurePrestressNames, k); }
inline const char* NameOf(TrussAnalysisKind k) { return NameIn(kTrussAnalysisNames, k); }

// A rigid bar between two distinct nodes; its length is held at the given node positions.
struct StructureBarConfig {
  std::array<int, 2> nodes{1, 2};  // 1-based end nodes
  double mass_kg = 0;              // [kg], >= 0
};

// An elastic string: tension k (s - L0) + damping while s >= L0, slack below.
struct StructureStringConfig {
  std::array<int, 2> nodes{1, 2};  // 1-based end nodes
  double stiffness_n_m = 0;        // k [N/m], >= 0
  double damping_n_s_m = 0;        // c [N s/m], >= 0: force density term c (s . s_dot) / s^2
  // The rest length: exactly one of the two is given.
  std::optional<double> rest_length_m;  // L0 [m], > 0
  std::optional<double> rest_ratio;     // L0 / (length at the given node positions), > 0
  double mass_kg = 0;                   // [kg], >= 0; shared per dynamics.string_mass
  std::optional<double> area_m2;        // [m^2], > 0; only for the stress report
};

struct StructureNodeMass {
  int node = 1;        // 1-based
  double mass_kg = 0;  // point mass [kg], >= 0
};

struct StructureLoad {
  int node = 1;                            // 1-based
  std::array<double, 3> force_n{0, 0, 0};  // constant [N]
};

// A member of a structure to be designed (`tbridge design`): its group gives its kind, its
// material limits and its area, which every member of the group shares.
struct StructureMemberConfig {
  std::array<int, 2> nodes{1, 2};  // 1-based end nodes
  std::string group;               // the name of one of `groups`
};

// A family of members designed to one area: its kind says what it may carry.
struct StructureGroupConfig {
  std::string name;
  // "string": tension only (a compression row keeps it taut); "bar": compression only, with
  // Euler buckling unless `buckling` is "none"; "truss": either sign, elastic E A / L.
  TrussKind kind = TrussKind::kTruss;
  double min_area_m2 = 0;                        // [m^2], > 0
  std::optional<double> max_area_m2;             // [m^2]; none: unbounded
  std::optional<double> allowed_tension_pa;      // [Pa]; strings and trusses
  std::optional<double> allowed_compression_pa;  // [Pa]; bars and trusses
  // "auto": Euler for bars, none for trusses; "euler": a solid round section's Euler load
  // pi^2 E I / L^2 with I = A^2 / (4 pi), divided by design.buckling_safety_factor; "none".
  BucklingRule buckling = BucklingRule::kAuto;
};

// A load case of a designed structure: its node forces times `factor` (with the members'
// self-weight, design.self_weight, in every case and times the same factor).
struct StructureLoadCase {
  std::string name;
  double factor = 1.0;  // [-], > 0
  std::vector<StructureLoad> loads;
};

// A displacement limit of a designed structure: |u_axis(node)| <= max_m in every case.
struct StructureDisplacementLimit {
  int node = 1;  // 1-based, a free node
  Axis axis = Axis::kY;
  double max_m = 0;  // [m], > 0
};

struct StructureLimits {
  std::vector<StructureDisplacementLimit> displacements;
  // f_k >= the k-th entry [Hz], k = 1, 2, ...: the lowest natural frequencies, in order.
  std::vector<double> min_frequencies_hz;
};

struct StructureConfig {
  int dim = 3;  // 2: motion in the x-y plane (every z must be 0); 3: full 3D
  std::vector<std::array<double, 3>> nodes;  // [m]; node k is entry k - 1
  std::vector<int> pinned;                   // supports (prescribed, not integrated)
  std::vector<StructureNodeMass> node_masses;
  std::vector<StructureBarConfig> bars;
  std::vector<StructureStringConfig> strings;
  std::vector<StructureLoad> loads;
  // Free nodes whose summed vertical (y) displacement gives the frequency measurement and
  // the peak displacement report; empty = none.
  std::vector<int> deck_nodes;
  // sigma_w [Pa] for the stress report; required when a string has an area.
  std::optional<double> allowed_stress_pa;
  double gravity_m_s2 = 9.81;  // g, acting in -y when dynamics.gravity_on_structure is set
  // The designable form (`tbridge design`): members in groups, load cases and limits. A
  // structure is either this or the scene of `bars` and `strings`, never both.
  std::vector<StructureMemberConfig> members;
  std::vector<StructureGroupConfig> groups;
  std::vector<StructureLoadCase> load_cases;
  StructureLimits limits;
  // "none": each member's rest length is its drawn length; "variable": the amplitudes of the
  // structure's self-stress states are variables of the sizing beside the areas.
  StructurePrestress prestress = StructurePrestress::kNone;
  // "linear": each case's statics small-displacement about the drawn state; "nonlinear":
  // geometrically nonlinear (large displacements, the members' forces along their turned
  // directions).
  TrussAnalysisKind analysis = TrussAnalysisKind::kLinear;

  // Whether this is the designable form (`members` given).
  bool Designable() const { return !members.empty(); }

  // L0 of string `k`: rest_length_m, or rest_ratio x its length at the node positions.
  double RestLength(int k) const;
  // Length of the member joining 1-based nodes `ends` at the node positions [m].
  double Length(const std::array<int, 2>& ends) const;
};

// Strict parse, then CheckStructureRules; throws ConfigError (key path, value, allowed).
StructureConfig ParseStructureConfig(JsonSection section);
nlohmann::json ToJson(const StructureConfig& config);

}  // namespace tbridge
