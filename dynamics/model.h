// The constant dynamic model of a tensegrity (paper eqs 16-27, SPEC.md §8). Built once (from a
// design in bridge/design_model.h, from a structure config in dynamics/structure_model.h), then
// only read by the engines, integrators and modal analysis.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/dynamics_choices.h"
#include "core/member_group.h"

namespace tbridge {

// One bar as the code past the model reads it (a row of BarColumns).
struct DynamicBar {
  int i = 0, j = 0;   // 0-based end nodes; bar vector b = n_j - n_i
  double mass = 0;    // bar mass plus its share of string mass (kOnBars) [kg]
  double length = 0;  // l, held constant [m]
};

// One string as the code past the model reads it (a row of StringColumns).
struct DynamicString {
  int i = 0, j = 0;        // 0-based end nodes
  double rest_length = 0;  // L0 [m]
  double stiffness = 0;    // k = E A / L0 [N/m]
  double damping = 0;      // c [N s/m]; force density term c (s . s_dot) / s^2
  double mass = 0;         // rho A L0 [kg]
  double area = 0;         // A [m^2], for stress reports; 0 when unknown (no stress)
};

// Iterates a column table row by row, each row a value (Row) read from the columns.
template <class Table, class Row>
class RowIterator {
 public:
  RowIterator(const Table* table, std::size_t k) : table_(table), k_(k) {}
  Row operator*() const { return (*table_)[k_]; }
  RowIterator& operator++() {
    ++k_;
    return *this;
  }
  bool operator!=(const RowIterator& other) const { return k_ != other.k_; }

 private:
  const Table* table_;
  std::size_t k_;
};

// The bars, one column per quantity (struct of arrays); bars[k] reads bar k.
struct BarColumns {
  std::vector<int> i, j;
  std::vector<double> mass;    // [kg]
  std::vector<double> length;  // [m]

  std::size_t size() const { return i.size(); }
  bool empty() const { return i.empty(); }
  DynamicBar operator[](std::size_t k) const { return {i[k], j[k], mass[k], length[k]}; }
  void push_back(const DynamicBar& b) {
    i.push_back(b.i);
    j.push_back(b.j);
    mass.push_back(b.mass);
    length.push_back(b.length);
  }
  RowIterator<BarColumns, DynamicBar> begin() const { return {this, 0}; }
  RowIterator<BarColumns, DynamicBar> end() const { return {this, size()}; }
};

// The strings, one column per quantity (struct of arrays); strings[k] reads string k. Add
// strings with DynamicModel::AddString, which keeps the names beside them.
struct StringColumns {
  std::vector<int> i, j;
  std::vector<double> rest_length;  // [m]
  std::vector<double> stiffness;    // [N/m]
  std::vector<double> damping;      // [N s/m]
  std::vector<double> mass;         // [kg]
  std::vector<double> area;         // [m^2]

  std::size_t size() const { return i.size(); }
  bool empty() const { return i.empty(); }
  DynamicString operator[](std::size_t k) const {
    return {i[k], j[k], rest_length[k], stiffness[k], damping[k], mass[k], area[k]};
  }
  void push_back(const DynamicString& s) {
    i.push_back(s.i);
    j.push_back(s.j);
    rest_length.push_back(s.rest_length);
    stiffness.push_back(s.stiffness);
    damping.push_back(s.damping);
    mass.push_back(s.mass);
    area.push_back(s.area);
  }
  RowIterator<StringColumns, DynamicString> begin() const { return {this, 0}; }
  RowIterator<StringColumns, DynamicString> end() const { return {this, size()}; }
};

// What only reports read: each string's name ("i-j", 1-based) and group (deck, substructure,
// transverse, or string in a structure scene), in the strings' order.
struct MemberNames {
  std::vector<std::string> string_name;
  std::vector<MemberGroup> string_group;
};

struct DynamicModel {
  int dim = 2;                 // 2: motion in the x-y plane; 3: full 3D
  Eigen::Matrix3Xd positions;  // equilibrium node positions N0 (3 x n_n) [m]
  std::vector<bool> fixed;     // pinned nodes are prescribed, not integrated
  BarColumns bars;
  StringColumns strings;
  MemberNames names;            // side table of the strings, for reports only
  Eigen::VectorXd node_mass;    // point masses at nodes [kg] (kAtNodes, free string nodes)
  Eigen::Matrix3Xd loads;       // constant external node loads W [N]
  double allowed_stress = 0;    // the strings' sigma_w [Pa], for stress reports
  double youngs_modulus = 0;    // the strings' E [Pa], for stress reports
  int tensegrity_class = 1;     // max bars at a node
  std::vector<int> deck_nodes;  // free deck nodes (0-based, in order of x), for the
                                // deck measurement of SPEC.md §9; may be empty
  double gravity = 9.81;        // g [m/s^2] used when gravity acts on the structure
  // alpha [1/s] of mass-proportional (Rayleigh) damping C = alpha M: every mode of frequency
  // omega is damped at alpha / (2 omega) of critical, so alpha = 2 xi omega gives one mode the
  // damping ratio xi exactly (the comfort check's time-history run). 0: none.
  double mass_damping_per_s = 0;
  // Groups of pinned nodes (0-based) whose summed support reaction a run reports, each its
  // largest over the run (a bridge's abutments); empty: none.
  std::vector<std::vector<int>> reaction_groups;

  int num_nodes() const { return static_cast<int>(positions.cols()); }
  // Adds a string with its name and group.
  void AddString(const DynamicString& s, std::string name, MemberGroup group) {
    strings.push_back(s);
    names.string_name.push_back(std::move(name));
    names.string_group.push_back(group);
  }
};

// Throws ModelError, prefixed by `where`, unless `model` is consistent: dim 2 or 3; fixed,
// node_mass (>= 0) and loads sized for its nodes; every column and name sized for its members;
// every member joining two distinct nodes in range; bars with mass >= 0 and length > 0; strings
// with L0 > 0, k >= 0, c >= 0, mass >= 0 and area >= 0. The one check of a model: the builders, the
// engines and the modal analysis call it.
void CheckModel(const DynamicModel& model, const std::string& where);

// Rest length = ratio x stretched (design) length for every string of `group`, with
// k = E A / L0 recomputed (SPEC.md §7).
struct StringPrestrain {
  MemberGroup group = MemberGroup::kDeck;
  double ratio = 1.0;  // (0, 1.5]
};

struct ModelOptions {
  StringMassMode string_mass = StringMassMode::kOnBars;
  double damping = 0;                      // c for every string [N s/m], >= 0
  std::vector<StringPrestrain> prestrain;  // at most one entry per group
  bool gravity_on_structure = false;       // add -m g (y) of bars and node masses to the loads
  bool deck_inertia = false;  // deck beams (and payload in the loads) as deck-node masses
  // The share of a designed bridge's payload the model carries as load and, with deck_inertia,
  // as mass (bridge/design_model.h): 1 for a run under the design loads; the comfort check
  // puts the pedestrians' weight there instead (0 for the empty deck).
  double payload_share = 1.0;
};

// What a prestrain implies (SPEC.md §7): the stress E (s - L0) / L0 at the design length s.
struct PrestrainReport {
  MemberGroup group = MemberGroup::kDeck;
  double ratio = 1.0;
  int strings = 0;               // strings in the group
  double max_stress = 0;         // [Pa], over the group's strings
  double allowed_stress = 0;     // sigma_w [Pa]
  double yield_stress = 0;       // [Pa]
  bool exceeds_allowed = false;  // max_stress > allowed_stress
};

// Shares the mass of every string of `model` out as BuildDynamicModel describes for `mode`
// (eq 27 for kOnBars), adding to the bar masses and node_mass; nothing at pinned nodes.
void ShareStringMass(DynamicModel& model, StringMassMode mode);
// Where ShareStringMass puts string mass, the one statement of the rule: for each string, half
// its mass at each unpinned end, on that node (`bar` -1, `count` 1) or split evenly over the
// `count` bars meeting there, one call per bar. Pinned ends call nothing.
void ForEachStringMassShare(
    const DynamicModel& model, StringMassMode mode,
    const std::function<void(int string, int node, int bar, int count)>& share);

// Adds the weight -m g (along y, g = model.gravity) of the bars (half at each end) and the
// node masses to model.loads.
void AddStructureWeight(DynamicModel& model);

// The largest number of bars meeting at a node (0 without bars); end indices out of range
// are skipped (CheckModel rejects them with a message).
int MaxBarsAtANode(const DynamicModel& model);

// A member's end at a node of a reaction group: the member ([bars; strings] index) and +1 at
// its end i, -1 at its end j.
struct ReactionEnd {
  int member = 0;
  double sign = 1;
};
// Per reaction group of `model`, the member ends at its nodes.
std::vector<std::vector<ReactionEnd>> ReactionEnds(const DynamicModel& model);
// Per reaction group, the constant loads on its nodes [N].
std::vector<Eigen::Vector3d> ReactionGroupLoads(const DynamicModel& model);
// A group's support reaction [N]: what balances the members' forces on its nodes and `loads`
// on them. `position(node)` gives a node's position [m], `force(member)` a member's force
// ([C_bars; T_strings]: compression of a bar, tension of a string [N]).
template <class Position, class Force>
Eigen::Vector3d GroupReaction(const DynamicModel& model, const std::vector<ReactionEnd>& ends,
                              const Eigen::Vector3d& loads, Position position, Force force) {
  const int nb = static_cast<int>(model.bars.size());
  Eigen::Vector3d r = -loads;
  for (const ReactionEnd& e : ends) {
    const bool bar = e.member < nb;
    const int i = bar ? model.bars.i[e.member] : model.strings.i[e.member - nb];
    const int j = bar ? model.bars.j[e.member] : model.strings.j[e.member - nb];
    const Eigen::Vector3d d = position(j) - position(i);
    // A string pulls its end i toward j; a bar in compression pushes it away.
    const double pull = bar ? -force(e.member) : force(e.member);
    r -= e.sign * pull / d.norm() * d;
  }
  return r;
}

// Mass that moves: bars (with their string share) plus node point masses [kg]. For the
// paper's n = 1 bridge with kOnBars this is 141.94 kg (SPEC.md §8).
double MovingMass(const DynamicModel& model);

}  // namespace tbridge
