// One candidate of the outer loop: its grid point, and its evaluation
// design -> (prestrained deck strings) -> first frequency -> dynamic check -> constraints.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "design/design.h"
#include "sweep/sweep_config.h"

namespace tbridge {

struct Candidate {
  int index = 0;  // 0-based position in the grid (n outermost, then p, beta, prestrain)
  int n = 1, p = 1;
  double beta_deg = 10;
  double deck_prestrain = 1.0;  // rest / stretched length of the deck strings; 1 = design state
};

// The grid in its fixed order: index = ((i_n * |p| + i_p) * |beta| + i_beta) * |prestrain| + i_r.
std::vector<Candidate> EnumerateCandidates(const SweepConfig& sweep);

// Names of the constraints, in the order they are checked and reported.
inline constexpr const char* kVerifiedDesign = "verified_design";
inline constexpr const char* kMinFirstFrequency = "min_first_frequency";
inline constexpr const char* kDynamicCheckDone = "dynamic_check_done";
inline constexpr const char* kMaxDeckDisplacement = "max_deck_displacement";
inline constexpr const char* kSpanOverDisplacement = "span_over_displacement";
inline constexpr const char* kNoSlack = "no_slack_under_service";
inline constexpr const char* kMaxDynamicStress = "max_dynamic_stress_ratio";
inline constexpr const char* kBarCapacity = "bar_capacity_during_motion";
inline constexpr const char* kPrestressAllowed = "prestress_within_allowed";

struct CandidateRow {
  Candidate candidate;
  bool ok = true;  // false: the design or a run failed; `note` says why
  std::string note;
  // Masses [kg]: the design's parts after any deck-string growth (MassBreakdown).
  double bars = 0, strings = 0, deck_strings = 0, deck_beams = 0, structure = 0, total = 0;
  double joint_mass = 0;  // [kg]
  // The verification (sweep.verified): the structure mass of the first design, before any
  // resizing [kg]; the designs run; the verdict and the largest utilisation.
  double first_design = 0;
  int designs = 1;
  std::optional<bool> verified;
  std::optional<double> utilisation_max;
  double objective = 0;  // total + joint_mass [kg]
  int free_nodes = 0;
  double deck_string_area_factor = 1;  // deck-string area / design area (grow_area)
  double prestress = 0;                // stress of the deck strings at the design length [Pa]
  double allowed_stress = 0;           // sigma_w [Pa]
  std::optional<double> first_frequency_rad_s;
  // The design's dynamic check (sweep.constraints' dynamic ones, or sweep.report.dynamic_check):
  // whether every run it asks for was done; over the runs done, the peak deck displacement, the
  // largest dynamic utilisation of a string and of a bar, and the strings that must stay taut
  // and went slack; each run with how it ran ("paper_travelling: rk4x2") or why not.
  std::optional<bool> dynamic_check_done;
  std::optional<double> peak_deck_displacement;  // [m]
  std::optional<double> dynamic_string_utilisation;
  std::optional<double> dynamic_bar_utilisation;
  std::optional<int> slack_taut_strings;
  std::optional<std::string> dynamic_runs;
  bool feasible = false;
  std::vector<std::string> violated;  // constraint names, in the order above
  // With bridge.beta_deg "auto": what the angle's search noted (the angle at a range end, no
  // angle passing), "" when nothing.
  std::string angle_note;
};

// Evaluates one candidate of `spec`. Design or run failures (ModelError) give a row with
// ok = false and the message in `note`; bad input (ConfigError) propagates.
//
// With sweep.verified the design is DesignAndVerify's (tbridge design's): checked statically
// and dynamically and resized until it passes; a verdict that fails makes the row infeasible
// (verified_design), its note the verdict. The dynamic model of the modes carries gravity on
// the structure with design.self_weight, and the deck's inertia except under the paper's
// switches: the dynamic check's model.
//
// Deck prestrain r < 1 (SweepConfig::prestrain_sizing):
// - grow_area: the wanted deck-string tension is T = E A0 (1/r - 1), A0 the design area. The
//   area becomes A = max(A0, T / sigma_w), the rest length L0 = s / (1 + T / (E A)), the
//   stiffness E A / L0, the mass rho A s; mass.deck_strings, structure and total include it.
//   The design itself (design/) is untouched: the row's design is a copy.
// - keep_area: the deck strings get rest length r s, area and mass unchanged; the prestress
//   E (1/r - 1) is reported and checked by prestress_within_allowed.
// The changed bridge's dynamic check is run again; with r = 1 a verified candidate's own is read.
CandidateRow EvaluateCandidate(const SweepSpec& spec, const Candidate& candidate);

// The config of one candidate: the base with bridge.n, p and beta_deg set.
Config CandidateConfig(const SweepSpec& spec, const Candidate& candidate);

// Joint mass of a design [kg]: per_node_kg per free node plus per_force_kg_per_N times the
// largest member force (bar compression or string tension) meeting at each free node.
double JointMass(const Design& design, const JointMassConfig& joint);

}  // namespace tbridge
