// Each key of the `dynamics` section described once (protocol: core/config_visitors.h); its
// default is the struct member's initial value (core/dynamics_config.h).
#pragma once

#include <type_traits>
#include <vector>

#include "core/config_visitors.h"
#include "core/dynamics_config.h"

namespace tbridge {

inline const SectionInfo kDynamicsSection{
    "dynamics", "a dynamic scenario (`tbridge simulate`)",
    "`dt` at most `duration`; `loads[].t_end` greater than "
    "its `t_start` by at least `rise_s` + `fall_s`; each `prestrain` group at most once."};

// Largest node number accepted before the structure is known; the simulation checks the
// real node count.
inline constexpr int kMaxDynamicsNode = 1 << 20;

template <class S, class V>
void DescribeFields(S& s,
                    V& v) requires std::is_same_v<std::remove_const_t<S>, StabilisationConfig> {
  v.Bool(KeyInfo{"enabled", "–", "bar-length constraint stabilisation (eqs 24-26)"}, s.enabled);
  v.Number(KeyInfo{"omega_rad_s", "rad/s",
                   "omega of h'' + 2·zeta·omega·h' + omega²·h = 0, h = b·b − l²"},
           s.omega_rad_s, Range::Closed(1e-6, 1e9));
  v.Number(KeyInfo{"zeta", "–", "zeta of the same"}, s.zeta, Range::Closed(0.0, 1e3));
}

template <class P, class V>
void DescribeFields(P& p, V& v) requires std::is_same_v<std::remove_const_t<P>, PrestrainConfig> {
  EnumChoice(v, KeyInfo{"group", "–", "the strings whose rest length is set", true}, p.group,
             kPrestrainGroupNames);
  v.Number(KeyInfo{"ratio", "–",
                   "rest length = ratio × stretched length, k = E·A/L0 recomputed; the implied "
                   "stress E·(1/ratio − 1) is reported and flagged above the allowed stress",
                   true},
           p.ratio, Range{0.0, 1.5, true, false});
}

template <class P, class V>
void DescribeFields(P& p,
                    V& v) requires std::is_same_v<std::remove_const_t<P>, PerturbationConfig> {
  v.Integer(
      KeyInfo{"bar_class", "–",
              "bars grouped by length, 1 = the longest (the paper's delta_1); 0 = no perturbation"},
      p.bar_class, 0, kMaxDynamicsNode);
  v.Number(
      KeyInfo{"delta", "m", "both end nodes of every bar of the class move down (−y) by delta"},
      p.delta, Range::Closed(-100.0, 100.0));
}

template <class I, class V>
void DescribeFields(I& i, V& v) requires std::is_same_v<std::remove_const_t<I>, NodeInitialConfig> {
  v.Integer(KeyInfo{"node", "–", "any free node (1-based); the initial state must keep bar lengths",
                    true},
            i.node, 1, kMaxDynamicsNode);
  v.Vector3(KeyInfo{"displacement", "m", "initial displacement of the node"}, i.displacement);
  v.Vector3(KeyInfo{"velocity", "m/s", "initial velocity of the node"}, i.velocity);
}

template <class L, class V>
void DescribeFields(L& l, V& v) requires std::is_same_v<std::remove_const_t<L>, LoadStepConfig> {
  v.Number(KeyInfo{"t_start", "s", "the force acts for t_start <= t < t_end", true}, l.t_start,
           Range::NonNegative());
  v.Number(KeyInfo{"t_end", "s", "end of the force, greater than t_start", true}, l.t_end,
           Range::NonNegative());
  v.Integer(KeyInfo{"node", "–", "the node (1-based)", true}, l.node, 1, kMaxDynamicsNode);
  v.Vector3(KeyInfo{"force", "N", "the force, on top of the design's deck loads"}, l.force);
  v.Number(KeyInfo{"rise_s", "s",
                   "the force grows linearly from 0 at t_start to its full value at t_start + "
                   "rise_s (0: a step)"},
           l.rise_s, Range::NonNegative());
  v.Number(KeyInfo{"fall_s", "s",
                   "the force falls linearly to 0 over the last fall_s before t_end (0: a step). "
                   "A load moving at speed v between deck nodes h apart is, on each node, a ramp "
                   "with rise_s = fall_s = h/v"},
           l.fall_s, Range::NonNegative());
  v.Number(
      KeyInfo{
          "frequency_hz", "Hz",
          "0: the force as given; f > 0: the force times sin(2·pi·f·t), a harmonic load such as a "
          "pedestrian crowd's (the comfort check's load, `comfort`)"},
      l.frequency_hz, Range::Closed(0.0, 1e6));
  v.Number(KeyInfo{"spread_s", "s",
                   "0: the shape as given; s > 0: at each time the mean of that shape over the "
                   "s about it, so that each corner of the ramps turns over s and the force acts "
                   "from t_start - s/2 to t_end + s/2. A load spread over a length c moving at v "
                   "is, on each deck node, its point load's ramps spread over s = c/v"},
           l.spread_s, Range::Closed(0.0, 1e6));
}

template <class R, class V>
void DescribeFields(R& r, V& v) requires std::is_same_v<std::remove_const_t<R>, RecordConfig> {
  v.Integers(KeyInfo{"nodes", "–", "nodes (1-based) written to history.csv"}, r.nodes, 1,
             kMaxDynamicsNode);
  v.Integer(KeyInfo{"every", "steps", "record every k-th step"}, r.every, 1, 1 << 30);
  v.Bool(KeyInfo{"csv", "–", "write history.csv"}, r.csv);
  v.Bool(KeyInfo{"bar_forces", "–",
                 "peak compression and tension of every bar over the run (`bar_force_peaks` in "
                 "summary.json, [N]), from the class-k multipliers for any class; one extra "
                 "right-hand side and sparse solve per step"},
         r.bar_forces);
}

template <class F, class V>
void DescribeFields(F& f, V& v) requires std::is_same_v<std::remove_const_t<F>, FrequencyConfig> {
  v.Bool(KeyInfo{"enabled", "–",
                 "measure the deck frequency (SPEC §9: dominant spectral peak of the summed "
                 "vertical deck displacement); none, and the summary says why, where the record "
                 "holds fewer than two periods of it or drifts (dynamics/response.h)"},
         f.enabled);
  v.Integer(KeyInfo{"every", "steps", "sampling of that signal"}, f.every, 1, 1 << 30);
}

template <class G, class V>
void DescribeFields(G& g, V& v) requires std::is_same_v<std::remove_const_t<G>, GuardConfig> {
  v.Number(
      KeyInfo{"max_bar_length_error", "–", "stop when a bar's relative length error exceeds this"},
      g.max_bar_length_error, Range{0.0, 1.0, true, false});
  v.Number(KeyInfo{"max_energy_growth", "–",
                   "stop when the energy balance drifts by more than this fraction"},
           g.max_energy_growth, Range{0.0, 1e6, true, false});
}

template <class L, class V>
void DescribeFields(L& l, V& v) requires std::is_same_v<std::remove_const_t<L>, LimitsConfig> {
  // Whole numbers of steps; int counters in the driver hold up to 2^31 - 1.
  v.Integer(
      KeyInfo{"max_steps", "steps",
              "most integration steps of one run: ceil(duration/dt) is checked before the run (and "
              "before the design) for `rk4`, `sdirk3` and `auto`; `dopri5`, whose count is unknown "
              "beforehand, stops with an error naming this key when its accepted steps reach it"},
      l.max_steps, 1, 2000000000);
  v.Number(
      KeyInfo{"max_output_bytes", "B",
              "most bytes a run writes or holds for writing, checked before it starts: history.csv "
              "(records × (1 + dim × nodes) values × 20 B; 8 B a value in memory when `record.csv` "
              "is false), the `--vtk` export (~1 kB + 108 B a node + 60 B a member per sample) and "
              "the deck signals of the frequency measurement (16 B a sample)"},
      l.max_output_bytes, Range::Closed(1.0, 1e15));
}

template <class D, class V>
void DescribeFields(D& d, V& v) requires std::is_same_v<std::remove_const_t<D>, DynamicsConfig> {
  v.Number(KeyInfo{"duration", "s", "simulated time"}, d.duration, Range::Closed(1e-9, 1e6));
  v.Number(
      KeyInfo{"dt", "s",
              "RK4 and SDIRK3 step; DOPRI5's first step and output spacing; at most `duration`"},
      d.dt, Range::Closed(1e-12, 1.0));
  EnumChoice(
      v,
      KeyInfo{"integrator", "–",
              "`\"rk4\"`: fixed-step classical RK4 (the paper's); `\"dopri5\"`: adaptive "
              "Dormand-Prince 5(4); `\"sdirk3\"`: fixed-step implicit L-stable SDIRK3 with "
              "Newton on a sparse Jacobian (dynamics/sdirk.h); `\"auto\"`: RK4 when `dt` <= "
              "0.9 × 2√2/ω_max; beyond, RK4 with m = ceil(dt / (0.9 × 2√2/ω_max)) sub-steps "
              "per step while m RK4 steps cost no more than one SDIRK3 step, as estimated from the "
              "model's member, coordinate and sparse-factor counts (12-27 on the paper's "
              "bridges n = 2..7, ~40 at n = 8; summary.json "
              "`run.substeps`); else SDIRK3 at the same `dt` (below)"},
      d.integrator, kIntegratorNames);
  EnumChoice(
      v,
      KeyInfo{
          "engine", "–",
          "`auto`: the class-1 closed form when no node carries two bars, else class k (bar "
          "lengths held by Lagrange multipliers, sparse Cholesky per evaluation); `classk` forces "
          "class k on any bridge (the cross-check); `class1` on a class-k bridge is an error"},
      d.engine, kEngineNames);
  v.Number(KeyInfo{"rtol", "–", "DOPRI5 relative tolerance: RMS of err / (atol + rtol·|y|) <= 1"},
           d.rtol, Range::Closed(1e-14, 1e-1));
  v.Number(KeyInfo{"atol", "m and m/s", "DOPRI5 absolute tolerance, of positions and velocities"},
           d.atol, Range::Closed(1e-16, 1.0));
  EnumChoice(
      v,
      KeyInfo{"string_mass", "–",
              "eq. 27: half of each string's mass (rho·A·L0) on the bars at each end, spread "
              "uniformly; or lumped at the end nodes; or massless strings"},
      d.string_mass, kStringMassNames);
  v.Number(
      KeyInfo{"damping_c", "N·s/m", "c of every string: force density term c·(s·ṡ)/s² (eq. 16)"},
      d.damping_c, Range::Closed(0.0, 1e9));
  v.Section("stabilisation", d.stabilisation);
  v.List(KeyInfo{"prestrain", "–", "rest lengths of string groups of a designed bridge"},
         d.prestrain, Described{});
  v.Section("perturbation", d.perturbation);
  v.List(KeyInfo{"initial", "–", "initial displacement and velocity of nodes"}, d.initial,
         Described{});
  v.List(KeyInfo{"loads", "–", "extra node forces on a schedule; they add up"}, d.loads,
         Described{});
  v.Section("record", d.record);
  v.Section("frequency", d.frequency);
  v.Section("guard", d.guard);
  v.Bool(
      KeyInfo{
          "gravity_on_structure", "–",
          "add the weight of bars and node masses to the loads (the paper's runs have none). For a "
          "designed bridge it follows `design.self_weight` unless given; the run then starts from "
          "the "
          "static equilibrium under the loads it applies (the members' weight lumped as the "
          "dynamic model "
          "lumps its masses)"},
      d.gravity_on_structure);
  v.Bool(KeyInfo{"deck_inertia", "–",
                 "a designed bridge's deck beams (and the payload, where the run's loads carry its "
                 "weight) are "
                 "masses at the deck nodes, not only loads. The paper's Table 5–6 runs leave them "
                 "out (false)"},
         d.deck_inertia);
  v.Section("limits", d.limits);
}

// The rules across keys of kDynamicsSection; throws ConfigError naming the key path.
void CheckDynamicsRules(const DynamicsConfig& config);

}  // namespace tbridge
