// The design pipeline: config -> topology -> deck and loads -> minimum mass -> sizing.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/config.h"
#include "core/progress.h"
#include "design/deck.h"
#include "design/deck_beams.h"
#include "design/load_cases.h"
#include "design/min_mass.h"
#include "design/sizing.h"
#include "design/stability.h"
#include "design/topology.h"
#include "design/verification.h"

namespace tbridge {

struct MassBreakdown {
  double bars = 0;          // [kg]
  double strings = 0;       // non-deck strings [kg]; bars + strings = paper eq. (49)
  double deck_strings = 0;  // deck strings at their minimum radius [kg]
  double deck_beams = 0;    // 2^n m_d [kg]
  double structure = 0;     // bars + strings + deck strings [kg]
  double total = 0;         // structure + deck beams [kg]
};

// The breakdown of the members' masses: `bars`' and `strings`' masses summed by kind in member
// order, with `deck_beams` [kg], the structure and the total from them. Every design's
// breakdown is made here, so its parts always sum to its structure and total.
MassBreakdown MassesOf(const std::vector<MemberSizing>& bars,
                       const std::vector<MemberSizing>& strings, double deck_beams);

// Design::solver_form of a design read back from its file (io/design_reader.h).
inline constexpr const char* kReadFromFile = "read from file";

// What was re-derived of a design whose members are not what it was sized with (an edited file,
// io/design_reader.h; a tolerance or a temperature, design/as_built.h): the reference state the
// members carry as built.
struct AsBuilt {
  bool re_derived = false;
  // The members whose reference force in the file is not what they carry as read (an edited
  // area or rest length), in the file's order; empty when only the weight changed.
  std::vector<std::string> edited;
  double node_move_m = 0;     // the largest move of a node from the drawn geometry [m]
  int node = -1;              // 0-based, where it is
  double force_change_n = 0;  // the largest change of a member's reference force [N]
  std::string force_member;   // where it is
  int slack_strings = 0;      // strings slack in the re-derived reference state
};

struct Design {
  Config config;  // resolved
  BridgeTopology topology;
  Deck deck;
  // 3 x n_n node loads of the reference state [N]: the drawn geometry is in equilibrium under
  // them with the member forces of `reference_forces`. The paper's design load (deck and
  // payload) with its switches; else the permanent load G (deck beams, superimposed dead load
  // and, with design.self_weight, the members' weight).
  Eigen::Matrix3Xd loads;
  LoadCase reference;                // the factors of `loads` on the base actions
  Actions actions;                   // characteristic base actions and deck stations
  std::vector<LoadCase> cases;       // the load cases sized and checked for
  std::vector<std::string> notes;    // cases left out, and why
  Eigen::VectorXd reference_forces;  // [C; T] of the reference state [N]
  Eigen::VectorXd alpha;             // self-stress coefficients [N]; empty when not computed
  int self_weight_iterations = 0;    // sizings of the self-weight fixed point
  bool unchecked_cases = false;      // some asked-for cases were left out (notes say which)
  StaticCheck statics;               // the nonlinear static check, when it was run (checks/)
  Resizing resizing;                 // the verification's resizing, when it was run (sizing/)
  AngleSearch angle;      // the angle's search, where bridge.beta_deg is "auto" (sizing/)
  DynamicCheck dynamics;  // the dynamic check, when it was run (checks/)
  MassAttribution
      attribution;       // what drives the verified sizing's mass; members empty when not sized
  ComfortCheck comfort;  // the footbridge comfort check, when it was run (checks/)
  std::vector<MemberSizing> bars;     // in structure bar order
  std::vector<MemberSizing> strings;  // in structure string order
  // Member j's sizing in the members' one order, [bars; strings] (Structure::MemberAt).
  const MemberSizing& MemberAt(int j) const {
    const int nb = static_cast<int>(bars.size());
    return j < nb ? bars[j] : strings[j - nb];
  }
  MemberSizing& MemberAt(int j) {
    const int nb = static_cast<int>(bars.size());
    return j < nb ? bars[j] : strings[j - nb];
  }
  MassBreakdown mass;
  SolverOutcome solver;
  std::string solver_form;          // "self-stress" (the reduced problem), "full", or kReadFromFile
  double equilibrium_residual = 0;  // max |A x + w| over free DOFs [N]
  int self_stress_states = -1;      // n_b + n_s - rank(A); -1 when not computed (large n)
  // Static stability at the design state (design/stability.h); the critical load factor is
  // computed for n <= 6.
  StabilityVerdict stability;
  // 3 x n_n support reactions [N], zero at free nodes: with the applied loads they balance
  // the whole structure (SupportReactions, design/equilibrium.h).
  Eigen::Matrix3Xd reactions;
  AsBuilt as_built;  // what check re-derived, when it did
  // The config the bridge was designed under where `tbridge check` reads it under other loads
  // (io/design_loads.h: `config` holds the loads checked, this the loads designed for, and
  // the deck plates sized for them); unset where they are `config`'s own.
  std::optional<Config> designed_for;
};

// What the minimum-mass problem of a bridge config is made of: the drawn bridge, its deck and
// design loads, and the per-member floors. Throws ConfigError for bad parameters.
struct DesignInputs {
  BridgeTopology topology;
  Deck deck;
  Actions actions;  // the characteristic base actions (self-weight still zero)
  // The paper's one design load, deck and payload at the deck nodes [N] (3 x n_n), its
  // kPaperLoad action: the load of a one-case design, and of the solver cross-checks.
  Eigen::Matrix3Xd loads;
  MinMassSettings settings;             // sigma_w, buckling factor, tension and area floors
  std::vector<double> string_min_area;  // per string [m^2]: deck and transverse minimum sections
};
DesignInputs PrepareDesign(const Config& config);

// Runs the whole design. Throws ConfigError for bad parameters and ModelError when no
// design is found (the message carries the solver's status).
// `progress` (may be null) is told the fraction done at each stage: topology, equilibrium
// factorisation, solve, sizing.
// `area_floor` (may be null) gives each member [bars; strings] an area it may not go below
// [m^2]: the verification's resizing (sizing/verified_design.h). A member held there reports
// `governed_by` = "resized".
Design RunDesign(const Config& config, ProgressReporter* progress = nullptr,
                 const std::vector<double>* area_floor = nullptr);

// The design of `config` with given member areas [m^2] ([bars; strings]) and self-stress
// coefficients `alpha` [N] on the equilibrium's orthonormal self-stress basis: the reference
// state is G (with the members' weight from these areas) carried by the particular forces
// plus the prestress N alpha, and each string's rest length makes it carry its reference
// force at the drawn geometry. The members' force, utilisation and governing case are the
// reference state's; the caller's analysis sets them. A string in compression in the
// reference state gets the rest length of zero tension (its drawn length): such a design is
// a start for the sizing, whose reference-taut rows mend it, not a bridge (its stability
// verdict says so).
Design SizedDesign(const Config& config, const std::vector<double>& areas,
                   const Eigen::VectorXd& alpha);

// `design` after the loss of `loss` of its prestress (design.prestress_loss): its reference
// forces less that share of the self-stress part (PrestressForces; the forces carrying its
// reference loads kept), each string's rest length and stiffness those that carry its new force
// at its length. The geometry, areas and loads are the design's.
Design WithPrestressLoss(const Design& design, double loss);

// The verdicts that follow from a design's reference state, set again after it changed: its
// stability (at its reference forces and its strings' stiffnesses) and its support reactions.
void AssessReferenceState(Design& design);

// The bar rule of a config: the column curve or the paper's Euler check, with its factors.
BarRule BarRuleOf(const Config& config);

// Throws ModelError, saying why, when the design's stability verdict is not stable: a
// structure that buckles under its own design load is no design.
void RequireStable(const Design& design);

// The load case of the reference state: the paper's one case with its switches, else the
// permanent load G (PermanentCase: deck dead load, and the members' weight when it is on).
LoadCase PermanentCase(const Config& config);
LoadCase ReferenceCase(const Config& config, const std::vector<LoadCase>& cases);

// Whether string k must stay taut in service: the strings whose prestress the design sets (the
// deck chain, the planar bridge's one self-stress; the 3D bridge's transverse strings, which
// couple the planes only through it). Any other string may go slack: the checks then find the
// bridge's equilibrium (statically, or its motion) without it, and check the rest.
bool MustStayTaut(const Design& design, int k);

// The prestress in the reference forces [C; T] [N]: what is left of them once the share of the
// reference loads is taken off, that share being the equilibrium's particular solution, as
// every load case of the design takes it (design/case_envelope.h: x_c = P f_c + N alpha, so
// this is N alpha). Zero for a statically determinate bridge.
Eigen::VectorXd PrestressForces(const Design& design);

// A string's kind: a deck string (group "deck") or any other.
MemberKind StringKind(const Member& string);

// The members' areas [m^2], [bars; strings].
std::vector<double> MemberAreas(const Design& design);

// Member forces as one vector [C_bars; T_strings] in N (equilibrium unknown order).
Eigen::VectorXd MemberForces(const Design& design);

// The sized member called "i-j" (1-based nodes, either order, as the paper writes them);
// nullptr when the design has no such member.
const MemberSizing* FindMember(const Design& design, const std::string& name);

}  // namespace tbridge
