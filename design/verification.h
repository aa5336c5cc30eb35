// What the checks of a sized design found (filled by checks/ and sizing/, written by the design
// report): plain data, so that the design's outputs can carry it without knowing how it was
// checked.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/deck_motion_kind.h"
#include "core/design_choices.h"
#include "core/member_group.h"
#include "design/limit_mode.h"
#include "optim/kkt_certificate.h"

namespace tbridge {

// What a check found: it ran and everything it checks holds, it ran and something fails, it
// (or part of it) was not run, or the code does not ask for it (comfort, when every deck
// frequency is above EN 1990 A2's triggers). A design is PASS only when every check passed or
// was not required.
enum class CheckStatus { kPassed, kFailed, kNotRun, kNotRequired };
const char* CheckStatusName(
    CheckStatus status);  // "passed" | "failed" | "not_run" | "not_required"

// One member's governing finding in a check: the largest demand / resistance over what the
// check ran, and where. A slack string that must stay taut is measured by its strain instead
// (mode "slack": resistance is the working strain sigma_w / E and demand that plus the strain
// the string lacks to be taut, so utilisation = 1 + lacking / working, SlackUtilisation of
// design/sizing.h).
struct MemberFinding {
  double utilisation = 0;             // 0: the check found nothing for this member
  double demand = 0;                  // [N], or the strain for "slack"
  double resistance = 0;              // [N], or the working strain for "slack"
  std::string governing_case;         // "uls_travelling at node 5", "dynamic: moving_load"
  LimitMode mode = LimitMode::kNone;  // yield, buckling, serviceability, dynamic or slack
};
// Keeps the larger of `f` and the finding (utilisation, demand, resistance, case, mode).
void RaiseFinding(MemberFinding& f, double demand, double resistance,
                  const std::string& governing_case, LimitMode mode);

// The finding of a string that must stay taut and is slack by `strain` (< 0), working at
// `working_stress` [Pa] with modulus `youngs_modulus` [Pa] (mode "slack").
void RaiseSlackFinding(MemberFinding& f, double strain, double working_stress,
                       double youngs_modulus, const std::string& governing_case);

// One load case solved as a nonlinear static problem (checks/static_check.h).
struct CaseResponse {
  std::string
      label;  // the case, with its station for a travelling family ("sls_travelling at node 5")
  int case_index = -1;
  int station = -1;
  bool converged = false;
  std::string message;       // why not, when not converged
  double deflection_m = 0;   // largest vertical deck-node displacement from the drawn geometry [m]
  int deflection_node = -1;  // 0-based
  Eigen::Matrix3Xd reactions;  // 3 x n_n [N], zero at free nodes
  double balance = 0;          // |sum reactions + sum loads| / sum |loads|
  int slack_strings = 0;
};

// One abutment's largest reactions over the converged ultimate cases of the static check, and
// the capacities it is held to (supports.*).
struct AbutmentFinding {
  std::vector<int> nodes;                   // 0-based support nodes
  double x_m = 0;                           // where it is along the span [m]
  double horizontal_n = 0, vertical_n = 0;  // the largest |H| (in-plan) and |V| [N]
  std::string horizontal_case, vertical_case;
  double horizontal_capacity_n = 0, vertical_capacity_n = 0;  // [N], 0: unlimited
  double HorizontalUtilisation() const {
    return horizontal_capacity_n > 0 ? horizontal_n / horizontal_capacity_n : 0.0;
  }
  double VerticalUtilisation() const {
    return vertical_capacity_n > 0 ? vertical_n / vertical_capacity_n : 0.0;
  }
};

struct StaticCheck {
  bool done = false;
  // Per member [bars; strings]: what the nonlinear ultimate and serviceability cases demand.
  std::vector<MemberFinding> members;
  // Per member: its largest force over the ultimate cases, and its smallest over every case
  // (bars: compression, strings: tension; a slack string 0) [N].
  std::vector<double> force_max, force_min;
  std::vector<CaseResponse> cases;
  double deflection_limit_m = 0;  // span / loads.deflection_limit
  double deflection_max_m = 0;    // over the serviceability cases
  std::string deflection_case;
  int stations = 0;          // deck stations of a travelling family, each solved linearly
  int nonlinear_solves = 0;  // cases and stations solved nonlinearly (each in `cases`)
  int mirrored = 0;          // stations in `cases` taken as the mirror image of their image's solve
  // The other states of the prestress the check also ran in (design/prestress_states.h: after
  // the loss, with the rest lengths off by their tolerance), by the suffix of their cases'
  // labels ("after the prestress loss"); their cases follow the design's own in `cases`, and
  // every finding is the largest over the states.
  std::vector<std::string> prestress_states;
  bool all_converged = true;
  std::vector<AbutmentFinding> abutments;  // x = 0 first
  // Not run when not done; failed when a case found no equilibrium, a deflection exceeds its
  // limit, or a member's finding or an abutment's reaction exceeds 1 of its resistance or
  // capacity (1e-9 allows for one sized exactly to it).
  CheckStatus Status() const;
};

// The dynamic check (checks/dynamic_check.h): each dynamic load run at service level.
struct GroupAmplification {
  MemberGroup group = MemberGroup::kNone;  // the members' family
  double static_peak = 0;    // largest force of the group's members over the static counterpart [N]
  double dynamic_peak = 0;   // largest in the run [N]
  double amplification = 0;  // the largest dynamic / static ratio of a member of the group
};

struct DynamicRun {
  std::string name;  // "paper_travelling", "moving_load" or "wind_gust"
  std::string load;  // what it applies, as an engineer writes it
  bool done = false;
  std::string note;        // why it was skipped, when not done
  std::string integrator;  // as resolved
  double dt = 0;           // [s]
  long steps = 0;
  double duration = 0;                // [s]
  double peak_deck_displacement = 0;  // [m], from the run's start (static equilibrium)
  // Per abutment (AbutmentsOf's order): its largest horizontal (in plan) and vertical reaction
  // over the run [N], characteristic (the run is at service level). Reported, not constrained.
  std::array<double, 2> peak_horizontal_reaction{}, peak_vertical_reaction{};
  std::vector<GroupAmplification> groups;
};

struct DynamicCheck {
  bool done = false;  // the check was carried out (it may have had no load to run)
  std::vector<DynamicRun> runs;
  // Per member [bars; strings]: the dynamic demand over the runs done.
  std::vector<MemberFinding> members;
  // The strings that must stay taut and went slack in a run, whether or not "slack" is their
  // governing finding (a higher tension elsewhere in the run may govern). Not in the design
  // file: a design read back has the findings only.
  std::vector<int> slack_strings;
  bool ran() const { return !runs.empty(); }
  // Not run when the check was not carried out or a run was not done (and nothing failed);
  // failed when a member's finding exceeds 1.
  CheckStatus Status() const;
  // The runs not done, with their notes ("moving_load skipped: ..."); empty when all were.
  std::string NotDone() const {
    std::string out;
    for (const DynamicRun& r : runs) {
      if (r.done) continue;
      if (!out.empty()) out.append("; ");
      out.append(r.name).append(" ").append(r.note);
    }
    return out;
  }
};

// What drives the verified sizing's mass (sizing/sizing_attribution.h).
// The kinds of constraint, in the order the outputs list them: each indexes kConstraintKinds,
// their texts, and the by-kind arrays below.
enum ConstraintKind : int {
  kStrengthKind,
  kBucklingKind,
  kYieldKind,
  kDeflectionKind,
  kTautKind,
  kMinimumKind,
  kDynamicsKind,
  kComfortKind,
  kSupportsKind,
  kServiceStressKind,
  kRobustnessKind,
  kNumConstraintKinds
};
inline constexpr const char* kConstraintKinds[kNumConstraintKinds] = {
    "strength",      "buckling", "yield",   "deflection", "taut_strings",
    "minimum_sizes", "dynamics", "comfort", "supports",   "serviceability_stress",
    "robustness"};

struct MemberBinding {
  // The constraint that costs its group most; none where nothing binds it.
  std::optional<ConstraintKind> kind;
  std::string case_label;  // its combination ("uls_travelling at node 3"), empty for a size
  double multiplier = 0;   // lambda of that constraint, in `unit`
  std::string
      unit;  // "kg per unit utilisation", "kg per unit deflection / limit", "kg/N", "kg/m^2"
};

struct MassAttribution {
  std::vector<MemberBinding> members;  // per member [bars; strings]
  double mass_by_kind_kg[kNumConstraintKinds] = {};
  // The same split of the change from the first design.
  double premium_by_kind_kg[kNumConstraintKinds] = {};
  double structure_kg = 0;           // the sized members' mass
  double stationarity_residual = 0;  // |grad f - J^T lambda - mu| / |grad f|
  int active_rows = 0;
  // lambda per posed row, then mu per variable at its floor, in the program's scaled units
  // (sizing/sizing_problem.h): the raw multipliers, for checks of the split.
  Eigen::VectorXd multipliers;
};

// One deck mode of the comfort check (checks/comfort_check.h): its motion, frequencies, modal
// mass and, in a range of resonance risk, its steady peak acceleration under the crowd load.
struct ComfortMode {
  int index = 0;  // 1-based, in ascending frequency with the pedestrians on the deck
  DeckMotion direction = DeckMotion::kVertical;  // never kLocal
  double share = 0;               // of the deck's motion in `direction` (DeckMotionReport)
  double frequency_hz = 0;        // with the class's pedestrians on the deck
  double frequency_empty_hz = 0;  // without them
  double modal_mass_kg =
      0;  // for the shape scaled to a largest deck displacement of 1 along its axis
  double load_weight_m2 = 0;  // sum of deck area x |shape| over the deck nodes, scaled shape [m^2]
  int range = 4;           // Sétra's frequency range (1-4), the riskiest between empty and crowded
  std::string load_model;  // the Sétra load case applied, or why none
  double psi = 0;          // Sétra's psi, the largest between the two frequencies
  double equivalent_pedestrians = 0;
  double modal_force_n = 0;      // F*, the crowd load's amplitude on the scaled shape [N]
  double acceleration_m_s2 = 0;  // steady peak a = F* / (2 xi M*) at `node`
  double limit_m_s2 = 0;
  int node = -1;                   // 0-based deck node of the largest displacement along the axis
  std::string comfort_class;       // Sétra's comfort level reached ("maximum" ... "unacceptable")
  double lock_in_pedestrians = 0;  // lateral: the critical number N_L (0 for the other motions)
  bool pass = true;  // acceleration within the limit (and, lateral, fewer pedestrians than N_L)
};

// The comfort check: plain data filled by checks/comfort_check.h.
struct ComfortCheck {
  bool done = false;      // carried out (not with the paper's switches or comfort.check false)
  bool required = false;  // a deck frequency below EN 1990 A2's trigger for its motion
  std::string note;       // why not done, or what it left out
  TrafficClass traffic_class = TrafficClass::kII;
  ComfortLevel comfort_level = ComfortLevel::kMean;
  double damping_ratio = 0;
  double density_per_m2 = 0;       // the class's crowd density d
  double pedestrians = 0;          // n = d x deck area
  double crowd_mass_kg = 0;        // their mass on the deck
  bool planar = false;             // a planar bridge: lateral and torsional motions not checked
  std::vector<ComfortMode> modes;  // the deck modes below their trigger
  // not_run when not done; not_required when done and no mode is below its trigger; failed
  // when a mode does not pass; else passed.
  CheckStatus Status() const;
  // The failing modes, as the verdict names them; empty when none.
  std::string Failures() const;
};

// The resizing loop's record (sizing/verified_design.h).
// The angle chosen where bridge.beta_deg is "auto" (sizing/angle_search.h).
struct AngleSearch {
  bool done = false;  // the angle was searched
  double low_deg = 0, high_deg = 0, chosen_deg = 0;
  struct Trial {
    double beta_deg = 0;
    double mass_kg = 0;  // the verified design's structure
    bool pass = false;
    double utilisation_max = 0;
  };
  std::vector<Trial> trials;  // in the order designed
  std::string note;  // where the angle ends at a range end, or no angle passed; "" when none
};

struct Resizing {
  int iterations = 0;  // designs run
  // A sizing from a passing design's corrections within `tolerance` of that design's mass.
  bool converged = false;
  double tolerance = 0;                   // relative, on the structure's mass
  std::vector<double> structure_mass_kg;  // per design: the start, then each sizing
  // Per checked sizing: the largest utilisation the checks found (a violation above 1). The
  // settling sizing of a converged run is not checked, so it has none.
  std::vector<double> utilisation_max;
  std::vector<std::string> changes;  // per sizing but the last: how its checks corrected the next
  double second_start_kg = 0;        // the last sizing from twice the first design's areas
  std::string optima;                // what that second start found, and which design was kept
  std::string why;                   // when not converged: the last verdict
  // The comfort rows of the sizing that gave the design (sizing/comfort_sizing.h): each deck
  // mode's bound on its frequency, and why.
  std::vector<std::string> comfort_rows;
  // The certificate of local optimality of the program whose solution is the design
  // (optim/kkt_certificate.h), in its scaled variables, every row of the whole program counted.
  // None where nothing was sized.
  std::optional<KktCertificate> kkt;
  // Wall time by part over every design of the loop (the first design, each sizing, the
  // second start) [s]: what a run's time goes to (`tbridge design --progress` prints it). Not a
  // result, and not in the design's JSON: it varies from run to run.
  struct Times {
    double first_design = 0, sizing = 0, static_check = 0, dynamic_check = 0, comfort_check = 0;
  } time_s;
};

}  // namespace tbridge
