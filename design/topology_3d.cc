// 3D bridge (paper Sect. 7.3): two planar p = 1 bridges at z = 0 (plane A) and z = deck_width
// (plane B), coupled into a class-2 tensegrity.
//
// Coupling (docs/topology.md has the pictures):
// - Transverse bars ("rungs"): every bar node of plane A is joined to its twin in plane B.
//   Each bar node then meets its own plane's bar and one rung: class 2, 2 (2^n - 1) rungs.
// - Transverse strings:
//   * X bracing of every in-plane member: the member and its twin are the long sides of a
//     flat rectangle whose short sides are rungs (or the two fixed supports); both
//     diagonals are strings. The two diagonals of a rectangle cross at its centre without
//     being joined there, as in ordinary cross bracing.
//   * Bay diagonals: for neighbouring deck stations k, k + 1, deck node k of each plane is
//     joined to bottom node k + 1 of the other plane, and deck node k + 1 to bottom node k,
//     unless that pair is already braced. These tie the deck nodes that have no substructure
//     cable of their own (for n = 2 the quarter points) to the neighbouring bottom nodes.
//   For n = 2: 6 rungs, 26 bracing diagonals and 4 bay diagonals, so 16 nodes, 12 bars and
//   50 strings, the paper's counts.
// - Under symmetric vertical loads the transverse members carry nothing; the design gives
//   the transverse strings a minimum radius prestressed at the working stress, and the
//   rungs and in-plane bars take that prestress in compression (rectangle self-stresses).
//
// Numbering: deck nodes of A then of B (x order), bottom nodes of A then of B, supports
// last (A at x = 0, A at x = span, B at x = 0, B at x = span).
#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>

#include "core/error.h"
#include "design/topology.h"

namespace tbridge {

BridgeTopology CoupledBridge3D(int n, double beta_deg, double span, double deck_width) {
  if (!(deck_width > 0.0) || !std::isfinite(deck_width)) {
    throw ConfigError("bridge.deck_width", NumberText(deck_width), "must be a positive number");
  }
  const BridgeTopology plane = PlanarSubstructure(n, 1, beta_deg, span);
  const Structure& ps = plane.structure;
  const int nb = ps.num_bars();   // bar nodes per plane: nb deck + nb bottom
  const int np = ps.num_nodes();  // 2 nb + 2 (supports last)

  // Planar node v of plane q (0 = A, 1 = B) -> 3D node.
  auto node3 = [&](int v, int q) {
    if (v < nb) return q * nb + v;                      // deck
    if (v < 2 * nb) return 2 * nb + q * nb + (v - nb);  // bottom
    return 4 * nb + 2 * q + (v - 2 * nb);               // supports
  };

  BridgeTopology topo;
  Structure& s = topo.structure;
  s.nodes.setZero(3, 2 * np);
  s.fixed.assign(2 * np, false);
  for (int q = 0; q < 2; ++q) {
    for (int v = 0; v < np; ++v) {
      s.nodes.col(node3(v, q)) = ps.nodes.col(v);
      s.nodes(2, node3(v, q)) = q * deck_width;
      s.fixed[node3(v, q)] = ps.fixed[v];
    }
  }
  for (int q = 0; q < 2; ++q) {
    for (const Member& m : ps.bars) s.bars.push_back({node3(m.i, q), node3(m.j, q), m.group});
  }
  for (int q = 0; q < 2; ++q) {
    for (const Member& m : ps.strings) {
      s.strings.push_back({node3(m.i, q), node3(m.j, q), m.group});
    }
  }
  for (int v = 0; v < 2 * nb; ++v)
    s.bars.push_back({node3(v, 0), node3(v, 1), MemberGroup::kTransverse});

  // Planar pairs already joined in-plane, to skip bay diagonals that would repeat a brace.
  std::set<std::pair<int, int>> in_plane;
  auto brace = [&](int u, int v) {
    s.strings.push_back({node3(u, 0), node3(v, 1), MemberGroup::kTransverse});
    s.strings.push_back({node3(u, 1), node3(v, 0), MemberGroup::kTransverse});
  };
  for (const auto* members : {&ps.bars, &ps.strings}) {
    for (const Member& m : *members) {
      in_plane.insert(std::minmax(m.i, m.j));
      brace(m.i, m.j);
    }
  }
  // Deck node k - 1 and bottom node k - 1 + nb sit at grid station k (SPEC.md §2 numbering).
  for (int k = 0; k + 1 < nb; ++k) {
    for (const auto& [d, b] : {std::pair{k, k + 1 + nb}, std::pair{k + 1, k + nb}}) {
      if (!in_plane.count(std::minmax(d, b))) brace(d, b);
    }
  }

  for (int q = 0; q < 2; ++q) {
    for (int v : plane.deck_nodes) topo.deck_nodes.push_back(node3(v, q));
  }
  topo.planes = 2;
  topo.loaded_stations = plane.loaded_stations;
  s.planar = false;
  s.Validate();
  return topo;
}

}  // namespace tbridge
