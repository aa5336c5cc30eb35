// What a run reports of itself: its integrator and counts, peaks of stress, displacement and
// bar force, slack events and the energy balance (filled by RunMonitor and the driver).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "dynamics/model.h"
#include "dynamics/response.h"

namespace tbridge {

struct SlackEvents {
  int total = 0;                // slack <-> taut transitions, all strings
  std::vector<int> per_string;  // per model string
  int slack_at_start = 0, slack_at_end = 0;
  int ever_slack = 0;  // strings slack at the start or after some accepted step
};

// A reaction group's largest support reaction over a run [N]: horizontal, |(x, z)| (in plan),
// and vertical, |y| (bearing or uplift), each at its own instant.
struct ReactionPeak {
  double horizontal = 0, vertical = 0;
  void Take(const Eigen::Vector3d& r) {
    horizontal = std::max(horizontal, std::hypot(r.x(), r.z()));
    vertical = std::max(vertical, std::abs(r.y()));
  }
};

struct EnergyBalance {
  double kinetic_start = 0, elastic_start = 0;  // [J]
  double kinetic_end = 0, elastic_end = 0;      // [J]
  double external_work = 0;                     // work done by the loads since t = 0 [J]
  // By string damping [J]: with the integrator's own stages and weights (RK4, DOPRI5, SDIRK3),
  // so that the balance closes across slack transitions as well as the motion itself does.
  double dissipated = 0;
  // H = kinetic + elastic - external work + dissipated is conserved by the exact dynamics;
  // drift = max over the accepted steps of |H - H_0| / E_ref, E_ref = max(kinetic + elastic
  // at start, 1e-12 J).
  double reference = 0;
  double max_drift = 0;
  double final_drift = 0;
};

struct SimulationSummary {
  std::string integrator;
  std::string engine;    // "class1" | "classk" (EngineFor)
  int substeps = 1;      // RK4 sub-steps per step ("auto" beyond RK4's limit)
  int steps = 0;         // accepted steps
  int rejected = 0;      // dopri5 only
  long evaluations = 0;  // right-hand side calls
  double duration = 0;   // simulated [s]
  double wall_seconds = 0;
  double max_string_stress = 0;  // tension / area over strings and steps [Pa]
  std::string max_stress_string;
  double max_stress_time = 0;  // [s]
  double allowed_stress = 0;   // [Pa]
  bool stress_exceeds_allowed = false;
  SlackEvents slack;
  double max_bar_length_error = 0;  // max |l - l0| / l0 over bars and steps
  // Largest |displacement| of a deck node (model.deck_nodes) from the model's positions, per
  // axis x, y, z, over the accepted steps [m]; the node (0-based, -1 if none) and time [s].
  std::array<double, 3> peak_deck_displacement{0, 0, 0};
  std::array<int, 3> peak_deck_node{-1, -1, -1};
  std::array<double, 3> peak_deck_time{0, 0, 0};
  EnergyBalance energy;
  // Per model bar, only when record.bar_forces asks: the largest compression and the largest
  // tension at the start and after the accepted steps [N] (0 if never). Bar forces lambda l
  // come from the run's own engine (the class-1 closed form, or the class-k multipliers) with
  // the loads of the step just taken: one extra right-hand side per step.
  std::vector<double> peak_bar_compression, peak_bar_tension;
  // Per model string, at the start and after the accepted steps: the largest tension [N] and
  // the smallest strain (s - L0) / L0 (negative: slack that deep).
  std::vector<double> peak_string_tension, min_string_strain;
  // Per model.reaction_groups, where the run measures bar forces: its largest reaction at the
  // start and after the accepted steps, from the members' forces on its nodes and the constant
  // loads there (a timed load standing on a support node itself is not in it).
  std::vector<ReactionPeak> peak_reactions;
  std::vector<PrestrainReport> prestrain;
  bool has_frequency = false;
  FrequencyEstimate frequency;  // deck measurement of SPEC.md §9
  std::string frequency_note;   // why there is none, when has_frequency is false
  // Mean period from the crossings of the same deck signal (MeanPeriodFromCrossings), when
  // it has at least three crossings; empty otherwise.
  std::optional<FrequencyEstimate> crossing_frequency;
  // The dominant frequency of the antisymmetric deck signal (AntisymmetricDeckSignal), when
  // the motion has an antisymmetric part above 1e-6 of the symmetric one: the antisymmetric
  // modes, which the summed signal cannot show.
  std::optional<FrequencyEstimate> antisymmetric_frequency;
};

}  // namespace tbridge
