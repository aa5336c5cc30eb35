// Config of a dynamic scenario (the "dynamics" section). Plain data with defaults, SI units.
// Every key is described once in core/dynamics_fields.h: unit, range and meaning, from which
// the parse, the echo, Validate() and the README's key table come.
#pragma once

#include <array>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "core/dynamics_choices.h"
#include "core/member_group.h"

namespace tbridge {

class JsonSection;

// Bar-length constraint stabilisation (eqs 24-26, corrected in SPEC.md §8): the length error
// h = b.b - l0^2 obeys h'' + 2 zeta omega h' + omega^2 h = 0.
struct StabilisationConfig {
  bool enabled = false;
  double omega_rad_s = 100.0;  // omega [rad/s], > 0
  double zeta = 1.0;           // zeta [-], >= 0
};

// Rest length = ratio x stretched (design) length for every string of `group`; k = E A / L0.
struct PrestrainConfig {
  MemberGroup group = MemberGroup::kDeck;  // one of kPrestrainGroupNames
  double ratio = 1.0;                      // (0, 1.5]
};

// The paper's perturbation: both end nodes of every bar of one length class move down (-y)
// by delta. Classes are numbered from the longest bar (1) to the shortest (Table 5).
struct PerturbationConfig {
  int bar_class = 0;  // 0 = no perturbation, else 1..number of classes
  double delta = 0;   // [m]; positive = downwards
};

// Initial displacement and velocity of one node (1-based, as in every output).
struct NodeInitialConfig {
  int node = 1;
  std::array<double, 3> displacement{0, 0, 0};  // [m]
  std::array<double, 3> velocity{0, 0, 0};      // [m/s]
};

// A force on one node (1-based) for t_start <= t < t_end; schedules add up. It grows linearly
// from zero over the first rise_s and falls linearly to zero over the last fall_s, so a load
// that moves along the deck (the lever rule between two nodes) is a chain of such ramps.
struct LoadStepConfig {
  double t_start = 0;  // [s]
  double t_end = 0;    // [s], > t_start
  int node = 1;
  std::array<double, 3> force{0, 0, 0};  // [N]
  double rise_s = 0;                     // [s], >= 0; rise_s + fall_s <= t_end - t_start
  double fall_s = 0;                     // [s], >= 0
  double frequency_hz = 0;  // [Hz], >= 0; > 0: the force times sin(2 pi frequency_hz t)
  double spread_s = 0;      // [s], >= 0; > 0: the shape's mean over spread_s about each time
};

struct RecordConfig {
  std::vector<int> nodes;  // 1-based nodes whose positions go to the history; empty = none
  int every = 1;           // record every k-th step (and the first); >= 1
  bool csv = true;         // write history.csv (when nodes are recorded)
  // Peak compression and tension of every bar over the run, into the summary; costs one
  // extra right-hand side and sparse solve per step (dynamics/simulation.h).
  bool bar_forces = false;
};

// Frequency from the deck motion (SPEC.md §9): the summed vertical deck-node displacement,
// sampled every `every` steps, then its dominant spectral peak.
struct FrequencyConfig {
  bool enabled = true;
  int every = 10;  // >= 1
};

// When a run counts as blown up (it stops with a ModelError).
struct GuardConfig {
  double max_bar_length_error = 1e-3;  // relative |l - l0| / l0, (0, 1]
  // (H - H0) / E_ref where H = kinetic + elastic - external work + dissipated, and E_ref the
  // initial kinetic + elastic energy; > 0
  double max_energy_growth = 0.5;
};

// Work and output one run may take, checked before it starts (CheckRunLimits in
// dynamics/simulation.h), so that a typo in duration or dt fails at once, naming the key,
// instead of running for days or running out of memory.
struct LimitsConfig {
  // Integration steps: ceil(duration / dt) for the fixed-step integrators, accepted steps
  // for dopri5 (counted as it runs); [1, 2e9].
  long max_steps = 1000000000;
  // Bytes written or held for writing [B]: history.csv (about 20 bytes per value), the VTK
  // export when asked, and the deck signals of the frequency measurement (16 bytes a sample);
  // [1, 1e15].
  double max_output_bytes = 1e10;
};

struct DynamicsConfig {
  double duration = 1.0;  // simulated time [s]
  double dt = 1e-5;       // step (rk4) or first step and output spacing (dopri5) [s]
  // "auto" | "rk4" | "dopri5" | "sdirk3". "auto": RK4 when dt is at most 0.9 of its stability
  // limit 2 sqrt(2)/omega_max (omega_max of the initial state, by power iteration), RK4
  // sub-steps while they cost no more than one SDIRK3 step (estimated from the model's
  // counts), else the implicit SDIRK3 at the same dt
  // (ResolveIntegrator in dynamics/integrator_policy.h; BENCHMARKS.md has the evidence).
  IntegratorKind integrator = IntegratorKind::kAuto;
  // "auto": the class-1 closed form when no node carries two bars, else class k;
  // "class1" (throws for a class-k bridge) | "classk" (Lagrange multipliers, any bridge)
  EngineKind engine = EngineKind::kAuto;
  double rtol = 1e-8;                                    // dopri5 relative tolerance
  double atol = 1e-10;                                   // dopri5 absolute tolerance [m, m/s]
  StringMassMode string_mass = StringMassMode::kOnBars;  // "bars" (eq 27) | "nodes" | "off"
  double damping_c = 0;                                  // c per string [N s/m]
  StabilisationConfig stabilisation;
  std::vector<PrestrainConfig> prestrain;
  PerturbationConfig perturbation;
  std::vector<NodeInitialConfig> initial;
  std::vector<LoadStepConfig> loads;
  RecordConfig record;
  FrequencyConfig frequency;
  GuardConfig guard;
  bool gravity_on_structure = false;  // add m g (down) of bars and node masses to the loads
  bool deck_inertia = true;           // deck beams (and payload) as masses at the deck nodes
  LimitsConfig limits;
};

// Strict parse, then CheckDynamicsRules; throws ConfigError (key path, value, allowed).
DynamicsConfig ParseDynamicsConfig(JsonSection section);
nlohmann::json ToJson(const DynamicsConfig& config);

}  // namespace tbridge
