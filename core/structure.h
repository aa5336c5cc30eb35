// The tensegrity structure model: nodes, bars and strings as index pairs, fixed nodes.
//
// Coordinates: x along the span, y vertical (up, deck at y = 0), z transverse (out of the
// planar bridge's plane). Node indices are 0-based in code and 1-based in every name and
// output ("i-j"), following SPEC numbering.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/member_group.h"

namespace tbridge {

// A bar or string between nodes i and j (0-based). `group` is its family (core/member_group.h):
// strings deck, substructure, transverse; bars vertical, substructure (leaning bars of p >= 2
// modules), transverse. A string of the deck group is a deck string.
struct Member {
  int i = 0;
  int j = 0;
  MemberGroup group = MemberGroup::kNone;
};

// The representative node of each node's component, the nodes joined by `edges` (a range of
// any type with int members i and j; bars give the bar-connected clusters), by union-find:
// nodes a and b are in one component iff the returned entries are equal. Indices are assumed
// valid.
template <class Edges>
std::vector<int> ComponentOf(int num_nodes, const Edges& edges) {
  std::vector<int> parent(static_cast<size_t>(num_nodes));
  for (int v = 0; v < num_nodes; ++v) parent[v] = v;
  auto find = [&parent](int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  for (const auto& e : edges) parent[find(e.i)] = find(e.j);
  for (int v = 0; v < num_nodes; ++v) parent[v] = find(v);
  return parent;
}

struct Structure {
  Eigen::Matrix3Xd nodes;       // 3 x n_n node positions [m]
  std::vector<Member> bars;     // compressive members (rigid in the dynamics)
  std::vector<Member> strings;  // tensile members (elastic, may go slack)
  std::vector<bool> fixed;      // per node: true for a pinned support
  bool planar = true;           // all nodes and motion in the x-y plane

  int num_nodes() const { return static_cast<int>(nodes.cols()); }
  int num_bars() const { return static_cast<int>(bars.size()); }
  int num_strings() const { return static_cast<int>(strings.size()); }
  int num_members() const { return num_bars() + num_strings(); }
  // Member j of the members' one order, [bars; strings], which every member vector follows.
  const Member& MemberAt(int j) const { return j < num_bars() ? bars[j] : strings[j - num_bars()]; }
  int num_free_nodes() const;
  // Spatial dimension of the motion: 2 for planar structures, 3 otherwise.
  int dim() const { return planar ? 2 : 3; }

  // Name "i-j" with 1-based node numbers, in the order stored.
  static std::string Name(const Member& m);
  // Member length in the current node positions [m].
  double Length(const Member& m) const { return (nodes.col(m.j) - nodes.col(m.i)).norm(); }
  // Number of bars meeting at each node (class-k index of the node).
  std::vector<int> BarsPerNode() const;
  // Largest number of bars at any node: 1 for class 1 (bars never share a node).
  int TensegrityClass() const;

  // Throws ModelError if an index is out of range, a member has zero length, or a member is
  // listed twice.
  void Validate() const;
};

}  // namespace tbridge
