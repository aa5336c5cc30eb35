// The "sweep" section of a config: the candidate grid of the outer loop, the objective's
// joint-mass term, and the optional static and dynamic constraints, which read the design's own
// checks (the loads section says what they run).
// Every key is described once in sweep/sweep_fields.h: unit, range and meaning, from which
// the parse, the echo, Validate() and the README's key table come.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/config.h"
#include "core/named_choice.h"

namespace tbridge {

// sweep.prestrain_sizing: see SweepConfig::prestrain_sizing.
enum class PrestrainSizing { kGrowArea, kKeepArea };
inline constexpr std::array<Named<PrestrainSizing>, 2> kPrestrainSizingNames{
    {{PrestrainSizing::kGrowArea, "grow_area"}, {PrestrainSizing::kKeepArea, "keep_area"}}};

// Joint (node) mass added to the objective, after Carpentieri, Skelton and Fraternali's
// parametric design: per_node_kg for every free node, plus per_force_kg_per_N times the
// largest member force meeting at each free node.
struct JointMassConfig {
  double per_node_kg = 0;         // [kg], >= 0
  double per_force_kg_per_N = 0;  // [kg/N], >= 0
  bool enabled() const { return per_node_kg > 0 || per_force_kg_per_N > 0; }
};

// Each constraint is off when absent. The dynamic ones read the design's dynamic check
// (checks/dynamic_check.h): the runs its loads section asks for, each member's factored demand
// over its resistance. A candidate whose check left a run undone cannot show them and is
// infeasible (dynamic_check_done).
struct SweepConstraints {
  std::optional<double> min_first_frequency_rad_s;  // [rad/s], > 0
  std::optional<double> max_deck_displacement;      // peak |dy| of a deck node in a run [m], > 0
  std::optional<double> span_over_displacement;     // span / that peak must be >= this [-], > 0
  bool no_slack_under_service = true;  // no string that must stay taut goes slack in a run
  std::optional<double> max_dynamic_stress_ratio;  // strings' dynamic utilisation <= this [-], > 0
  bool bar_capacity_during_motion = true;          // bars' dynamic utilisation <= 1
  bool prestress_within_allowed = false;           // prestrained strings' stress <= sigma_w
  bool Dynamic() const {
    return max_deck_displacement || span_over_displacement || no_slack_under_service ||
           max_dynamic_stress_ratio || bar_capacity_during_motion;
  }
};

// What to compute even when no constraint needs it.
struct SweepReport {
  bool first_frequency = false;
  bool dynamic_check = false;  // the design's dynamic check, with no dynamic constraint
};

struct SweepConfig {
  std::vector<int> n;     // complexities, each in [1, kMaxComplexity]; non-empty
  std::vector<int> p{1};  // bars per module, each in [1, kMaxBarsPerModule]
  std::vector<double>
      beta_deg;  // aspect angles [deg], each in [1, 90); parse default: bridge.beta_deg
  // Rest / stretched length of the deck strings; 1.0 = the design state (prestressed at
  // sigma_w by the minimum radius), each in (0, 1].
  std::vector<double> deck_prestrain{1.0};
  // "grow_area": a prestrain ratio r < 1 asks for the deck-string tension E A0 (1/r - 1) of
  // the design area A0; the area grows to tension / sigma_w (never shrinks) so the prestress
  // stays allowed, and the mass shows it. "keep_area": A0 is kept, rest length = r x length
  // (the paper's Table 6 experiment); the implied stress E (1/r - 1) may exceed sigma_w.
  PrestrainSizing prestrain_sizing = PrestrainSizing::kGrowArea;
  // Each candidate is the verified design (sizing/verified_design.h: its static and dynamic
  // checks, and the resizing of what fails), as tbridge design writes it; false: the
  // minimum-mass design alone.
  bool verified = true;
  JointMassConfig joint_mass;
  SweepConstraints constraints;
  SweepReport report;

  bool NeedsModes() const {
    return report.first_frequency || constraints.min_first_frequency_rad_s.has_value();
  }
  bool NeedsDynamicCheck() const { return report.dynamic_check || constraints.Dynamic(); }
  int size() const {
    return static_cast<int>(n.size() * p.size() * beta_deg.size() * deck_prestrain.size());
  }
};

// A sweep file: a normal config (bridge, material, design; no dynamics) plus "sweep".
struct SweepSpec {
  Config base;  // bridge.n, p, beta_deg are overridden per candidate
  SweepConfig sweep;
};

// Strict parse. bridge.n may be omitted (the grid sets it). Throws ConfigError naming the key
// path, the value and what is allowed: unknown keys, empty or repeated grid values, values out
// of range, a "dynamics" section, a "structure" section (a custom scene), p > 1 with planes = 2.
SweepSpec ParseSweepSpec(const nlohmann::json& root);
SweepSpec LoadSweepSpec(const std::string& path);
// Checks a spec built in code as ParseSweepSpec checks a file: Validate(base), every sweep key
// in its range and the rules across keys. Throws ConfigError naming the key path.
void Validate(const SweepSpec& spec);
// Resolved spec with every default filled in, echoed into the outputs.
nlohmann::json ToJson(const SweepSpec& spec);

}  // namespace tbridge
