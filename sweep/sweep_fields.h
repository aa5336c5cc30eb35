// Each key of the `sweep` section described once (protocol: core/config_visitors.h); its
// default is the struct member's initial value (sweep/sweep_config.h), except `beta_deg`,
// whose default is the config's bridge.beta_deg.
#pragma once

#include <type_traits>

#include "core/config_fields.h"
#include "core/config_visitors.h"
#include "sweep/sweep_config.h"

namespace tbridge {

inline const SectionInfo kSweepSection{
    "sweep", "the outer loop (`tbridge sweep`)",
    "the grid lists `n`, `p`, `beta_deg` and `deck_prestrain` are non-empty and name each value "
    "once; `p` only 1 when `bridge.planes` = 2. The dynamic constraints read the design's dynamic "
    "check (the runs `loads.cases` asks for, see the loads section); the section `travelling_load` "
    "of earlier versions is refused, naming the key that replaced each of its keys."};

template <class J, class V>
void DescribeFields(J& j, V& v) requires std::is_same_v<std::remove_const_t<J>, JointMassConfig> {
  v.Number(KeyInfo{"per_node_kg", "kg", "joint mass per free node, added to the objective"},
           j.per_node_kg, Range::Closed(0.0, 1e6));
  v.Number(KeyInfo{"per_force_kg_per_N", "kg/N",
                   "joint mass per N of the largest member force (bar compression or string "
                   "tension) meeting at each free node"},
           j.per_force_kg_per_N, Range::Closed(0.0, 1.0));
}

template <class C, class V>
void DescribeFields(C& c, V& v) requires std::is_same_v<std::remove_const_t<C>, SweepConstraints> {
  v.OptionalNumber(
      KeyInfo{"min_first_frequency_rad_s", "rad/s",
              "lowest linearised frequency (dynamics/modal.h, bar lengths held) >= this"},
      c.min_first_frequency_rad_s, Range::Positive(), Absent::kNull);
  v.OptionalNumber(
      KeyInfo{"max_deck_displacement", "m",
              "peak vertical displacement of any deck node from the run's start, over the dynamic "
              "check's runs, <= this"},
      c.max_deck_displacement, Range::Positive(), Absent::kNull);
  v.OptionalNumber(
      KeyInfo{"span_over_displacement", "–", "span / that peak >= this (e.g. 1000 for L/1000)"},
      c.span_over_displacement, Range::Positive(), Absent::kNull);
  v.Bool(
      KeyInfo{
          "no_slack_under_service", "–",
          "no string that must stay taut (the deck chain; the 3D bridge's transverse strings) goes "
          "slack (s < L0) in any of the dynamic check's runs; other strings may"},
      c.no_slack_under_service);
  v.OptionalNumber(
      KeyInfo{
          "max_dynamic_stress_ratio", "–",
          "every string's dynamic utilisation (the dynamic check's factored demand over A·sigma_w; "
          "with the paper's switches, every factor 1: its peak stress / sigma_w) <= this. "
          "The paper's design works every string at sigma_w, so any load on top of it gives > 1; "
          "yield is at `yield_safety_factor`"},
      c.max_dynamic_stress_ratio, Range::Positive(), Absent::kNull);
  v.Bool(
      KeyInfo{"bar_capacity_during_motion", "–",
              "every bar's dynamic utilisation <= 1: the dynamic check's factored demand over the "
              "design's bar resistance (`design.bar_resistance`: the column curve, or the paper's "
              "Euler load)"},
      c.bar_capacity_during_motion);
  v.Bool(
      KeyInfo{"prestress_within_allowed", "–",
              "deck-string stress at the design length <= sigma_w (only `keep_area` can break it)"},
      c.prestress_within_allowed);
}

template <class R, class V>
void DescribeFields(R& r, V& v) requires std::is_same_v<std::remove_const_t<R>, SweepReport> {
  v.Bool(KeyInfo{"first_frequency", "–", "compute the first frequency without the constraint"},
         r.first_frequency);
  v.Bool(
      KeyInfo{"dynamic_check", "–",
              "run the design's dynamic check (and report its peaks) without a dynamic constraint"},
      r.dynamic_check);
}

template <class S, class V>
void DescribeFields(S& s, V& v) requires std::is_same_v<std::remove_const_t<S>, SweepConfig> {
  v.Integers(KeyInfo{"n", "–", "complexities", true}, s.n, 1, kMaxComplexity);
  v.Integers(KeyInfo{"p", "–", "bars per module"}, s.p, 1, kMaxBarsPerModule);
  v.Numbers(KeyInfo{"beta_deg", "deg", "aspect angles", false, nullptr, "`[bridge.beta_deg]`"},
            s.beta_deg, kBetaDegRange);
  v.Numbers(KeyInfo{"deck_prestrain", "–",
                    "rest/stretched length r of the deck strings; 1.0 = the design state "
                    "(prestressed at sigma_w by the minimum radius)"},
            s.deck_prestrain, Range{0.0, 1.0, true, false});
  EnumChoice(
      v,
      KeyInfo{
          "prestrain_sizing", "–",
          "r < 1 asks for the deck-string tension T = E·A0·(1/r − 1), A0 the design area. "
          "`grow_area`: A = max(A0, T/sigma_w), L0 = s/(1 + T/(E·A)), k = E·A/L0, mass rho·A·s: "
          "the prestress stays allowed and `mass.deck_strings` (and structure, total) show it. "
          "`keep_area`: A0 kept, L0 = r·s (Table 6's experiment); the stress E·(1/r − 1) may "
          "exceed sigma_w. The design itself is unchanged; only the candidate's copy is"},
      s.prestrain_sizing, kPrestrainSizingNames);
  v.Bool(
      KeyInfo{
          "verified", "–",
          "each candidate is the verified design, as `tbridge design` writes it: its static check "
          "of every case, its dynamic check and the resizing of what fails, so its mass carries "
          "its dynamic premium over the first design (`mass_kg.first_design`); a candidate whose "
          "verification does not pass is infeasible (`verified_design`). A deck prestrain r < 1 "
          "changes the deck strings after the verification: the dynamic check is run again on "
          "the changed bridge, and the constraints read it. false: the minimum-mass design alone"},
      s.verified);
  v.Section("joint_mass", s.joint_mass);
  v.Section("constraints", s.constraints);
  v.Section("report", s.report);
}

// The rules across keys of kSweepSection; throws ConfigError naming the key path.
void CheckSweepRules(const SweepConfig& sweep, const BridgeConfig& bridge);

// The README's text of the sweep section (as ConfigSectionText for the core sections).
std::string SweepSectionText();

}  // namespace tbridge
