// The constant dynamic model of a tensegrity (paper eqs 16-27, SPEC.md §8). Built once (from a
// design in bridge/design_model.h, from a structure config in dynamics/structure_model.h), then
// only read by the engines, integrators and modal analysis.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/dynamics_choices.h"


namespace tbridge {

struct DynamicBar {
  int i = 0, j = 0;    // 0-based end nodes; bar vector b = n_j - n_i
  double mass = 0;     // bar mass plus its share of string mass (kOnBars) [kg]
  double length = 0;   // l, held constant [m]
};

struct DynamicString {
  int i = 0, j = 0;          // 0-based end nodes
  double rest_length = 0;    // L0 [m]
  double stiffness = 0;      // k = E A / L0 [N/m]
  double damping = 0;        // c [N s/m]; force density term c (s . s_dot) / s^2
  double mass = 0;           // rho A L0 [kg]
  std::string group;         // "deck", "substructure", "transverse"
  std::string name;          // "i-j", 1-based
};

struct DynamicModel {
  int dim = 2;                        // 2: motion in the x-y plane; 3: full 3D
  Eigen::Matrix3Xd positions;         // equilibrium node positions N0 (3 x n_n) [m]
  std::vector<bool> fixed;            // pinned nodes are prescribed, not integrated
  std::vector<DynamicBar> bars;
  std::vector<DynamicString> strings;
  Eigen::VectorXd node_mass;          // point masses at nodes [kg] (kAtNodes, free string nodes)
  Eigen::Matrix3Xd loads;             // constant external node loads W [N]
  double allowed_stress = 0;          // sigma_w [Pa], for stress reports
  double youngs_modulus = 0;          // E [Pa]
  std::vector<double> string_area;    // A per string [m^2], for stress reports
  int tensegrity_class = 1;           // max bars at a node
  std::vector<int> deck_nodes;        // free deck nodes (0-based, in order of x), for the
                                      // deck measurement of SPEC.md §9; may be empty
  double gravity = 9.81;              // g [m/s^2] used when gravity acts on the structure

  int num_nodes() const { return static_cast<int>(positions.cols()); }
};

// Rest length = ratio x stretched (design) length for every string of `group`, with
// k = E A / L0 recomputed (SPEC.md §7).
struct StringPrestrain {
  std::string group;
  double ratio = 1.0;  // (0, 1.5]
};

struct ModelOptions {
  StringMassMode string_mass = StringMassMode::kOnBars;
  double damping = 0;                      // c for every string [N s/m], >= 0
  std::vector<StringPrestrain> prestrain;  // at most one entry per group
  bool gravity_on_structure = false;       // add -m g (y) of bars and node masses to the loads
  bool deck_inertia = false;               // deck beams (and payload in the loads) as deck-node masses
};

// What a prestrain implies (SPEC.md §7): the stress E (s - L0) / L0 at the design length s.
struct PrestrainReport {
  std::string group;
  double ratio = 1.0;
  int strings = 0;              // strings in the group
  double max_stress = 0;        // [Pa], over the group's strings
  double allowed_stress = 0;    // sigma_w [Pa]
  double yield_stress = 0;      // [Pa]
  bool exceeds_allowed = false; // max_stress > allowed_stress
};

// Shares the mass of every string of `model` out as BuildDynamicModel describes for `mode`
// (eq 27 for kOnBars), adding to the bar masses and node_mass; nothing at pinned nodes.
void ShareStringMass(DynamicModel& model, StringMassMode mode);

// Adds the weight -m g (along y, g = model.gravity) of the bars (half at each end) and the
// node masses to model.loads.
void AddStructureWeight(DynamicModel& model);

// The largest number of bars meeting at a node (0 without bars); end indices out of range
// are skipped (the engines reject them with a message).
int MaxBarsAtANode(const DynamicModel& model);

// Mass that moves: bars (with their string share) plus node point masses [kg]. For the
// paper's n = 1 bridge with kOnBars this is 141.94 kg (SPEC.md §8).
double MovingMass(const DynamicModel& model);

}  // namespace tbridge
