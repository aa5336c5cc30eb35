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
    "once; `p` only 1 when `bridge.planes` = 2; `travelling_load.dt` at most "
    "`travelling_load.duration`."};

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
      KeyInfo{
          "max_deck_displacement", "m",
          "peak vertical displacement of any free deck node in the travelling-load run <= this"},
      c.max_deck_displacement, Range::Positive(), Absent::kNull);
  v.OptionalNumber(
      KeyInfo{"span_over_displacement", "–", "span / that peak >= this (e.g. 1000 for L/1000)"},
      c.span_over_displacement, Range::Positive(), Absent::kNull);
  v.Bool(KeyInfo{"no_slack_under_service", "–",
                 "no string that must stay taut (the deck chain; the 3D bridge's transverse strings) goes "
                 "slack (s < L0) at any step of the travelling-load run; other strings may"},
         c.no_slack_under_service);
  v.OptionalNumber(
      KeyInfo{"max_dynamic_stress_ratio", "–",
              "peak string stress / sigma_w <= this. The design works every string at sigma_w, so "
              "any load on top of it gives > 1; yield is at `yield_safety_factor`"},
      c.max_dynamic_stress_ratio, Range::Positive(), Absent::kNull);
  v.Bool(KeyInfo{"bar_capacity_during_motion", "–",
                 "peak bar force in the travelling-load run <= the design's bar resistance "
                 "(`design.bar_resistance`: the column curve, or the paper's Euler load) in compression, "
                 "its yield resistance in tension, at every step (bar forces lambda·l from the class-k "
                 "multipliers, dynamics/classk.h, for any class)"},
         c.bar_capacity_during_motion);
  v.Bool(
      KeyInfo{"prestress_within_allowed", "–",
              "deck-string stress at the design length <= sigma_w (only `keep_area` can break it)"},
      c.prestress_within_allowed);
}

template <class T, class V>
void DescribeFields(T& t,
                    V& v) requires std::is_same_v<std::remove_const_t<T>, TravellingLoadConfig> {
  v.Number(
      KeyInfo{"duration", "s",
              "the service load (the design's deck node load f × `load_factor`, downward) stands "
              "on each free deck node in turn, in order of x, for duration/stations each, on top "
              "of the design loads; the bridge starts at rest in its design equilibrium"},
      t.duration, Range::Closed(1e-6, 100.0));
  v.Number(
      KeyInfo{
          "dt", "s",
          "largest step, at most `duration`; the step taken is the largest <= dt that puts a whole "
          "number of steps in each station, so the load switches on step boundaries. At 1e-4 s "
          "`\"auto\"` runs RK4 (with sub-steps) up to n = 9; at 5e-4 s up to n = 6-7 and SDIRK3 "
          "beyond, whose deck peak is within 3.4 % but string stress peaks 22 % low and "
          "short-string slack missed at n = 8 (BENCHMARKS.md, Sweep timing). Peaks and slack are "
          "sampled at each step, not at sub-steps. A blow-up (bar-length error above 1e-3, energy "
          "growth, non-finite state) stops the candidate as failed with a step to try"},
      t.dt, Range::Closed(1e-9, 1e-2));
  // DOPRI5's adaptive steps do not stop at the stations' load changes.
  static constexpr std::array<Named<IntegratorKind>, 3> kTravellingIntegrators{
      {{IntegratorKind::kAuto, "auto"}, {IntegratorKind::kRk4, "rk4"}, {IntegratorKind::kSdirk3, "sdirk3"}}};
  EnumChoice(
      v,
      KeyInfo{"integrator", "–",
              "as `dynamics.integrator`: `\"auto\"` runs RK4 where `dt` is at most 0.9 of its "
              "stability limit 2·sqrt(2)/omega_max, RK4 sub-steps beyond while they cost no more than an "
              "SDIRK3 step, else "
              "the implicit SDIRK3, which damps the modes far above 1/dt (string-bar rattling; at "
              "n = 4 and dt = 5e-4 s the deck peak moves by < 0.3 % and member force peaks by < 2 "
              "% against RK4 at a resolving step, tests/sweep/evaluation_test.cc; the gap grows "
              "with n, see `dt`). `\"rk4\"` with a small `dt` resolves every mode"},
      t.integrator, kTravellingIntegrators);
  v.Number(KeyInfo{"load_factor", "–", "moving load / f"}, t.load_factor,
           Range{0.0, 100.0, true, false});
  EnumChoice(v, KeyInfo{"string_mass", "–", "string mass in the modes and the run, as `dynamics.string_mass`"},
             t.string_mass, kStringMassNames);
  v.Number(KeyInfo{"damping_c", "N·s/m", "string damping in the modes' model and the run"},
           t.damping_c, Range::Closed(0.0, 1e9));
  v.Bool(KeyInfo{"deck_inertia", "–",
                 "the deck beams' and the standing payload's mass at the deck nodes, in the modes and the "
                 "run, as `dynamics.deck_inertia`"},
         t.deck_inertia);
}

template <class R, class V>
void DescribeFields(R& r, V& v) requires std::is_same_v<std::remove_const_t<R>, SweepReport> {
  v.Bool(KeyInfo{"first_frequency", "–", "compute the first frequency without the constraint"},
         r.first_frequency);
  v.Bool(KeyInfo{"travelling_load", "–", "run the travelling load without a dynamic constraint"},
         r.travelling_load);
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
  v.Choice(
      KeyInfo{
          "prestrain_sizing", "–",
          "r < 1 asks for the deck-string tension T = E·A0·(1/r − 1), A0 the design area. "
          "`grow_area`: A = max(A0, T/sigma_w), L0 = s/(1 + T/(E·A)), k = E·A/L0, mass rho·A·s: "
          "the prestress stays allowed and `mass.deck_strings` (and structure, total) show it. "
          "`keep_area`: A0 kept, L0 = r·s (Table 6's experiment); the stress E·(1/r − 1) may "
          "exceed sigma_w. The design itself is unchanged; only the candidate's copy is"},
      s.prestrain_sizing, {"grow_area", "keep_area"});
  v.Bool(KeyInfo{"verified", "–",
                 "each candidate is the verified design, as `tbridge design` writes it: its static check "
                 "of every case, its dynamic check and the resizing of what fails, so its mass carries "
                 "its dynamic premium over the first design (`mass_kg.first_design`); a candidate whose "
                 "verification does not pass is infeasible (`verified_design`). A deck prestrain r < 1 "
                 "changes the deck strings after the verification: the travelling-load run and the "
                 "constraints check the changed bridge. false: the minimum-mass design alone"},
         s.verified);
  v.Section("joint_mass", s.joint_mass);
  v.Section("constraints", s.constraints);
  v.Section("travelling_load", s.travelling_load);
  v.Section("report", s.report);
}

// The rules across keys of kSweepSection; throws ConfigError naming the key path.
void CheckSweepRules(const SweepConfig& sweep, const BridgeConfig& bridge);

// The README's text of the sweep section (as ConfigSectionText for the core sections).
std::string SweepSectionText();

}  // namespace tbridge
