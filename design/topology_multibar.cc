// Planar substructure bridge with p >= 1 bars per module (class k for p >= 2).
//
// Every dyadic sub-span [a, b] of width W is a module. Its deck node sits at the midpoint and
// props, with p bars, the p vertices of a cable polygon of p + 1 segments hanging from (a, 0)
// to (b, 0). In module coordinates (xi along the span from a, eta down, both in units of W):
//
//   xi_i  = 1/4 + (2 i - 1) / (4 p),          i = 1..p   (cell centres of [1/4, 3/4])
//   eta_i = 2 tan(beta / 2) xi_i (1 - xi_i)               (parabola through a and b)
//
// Why this placement (docs/topology.md has the pictures):
// - p = 1 gives the vertex (1/2, tan(beta/2)/2): the paper's V with arms at beta/2.
// - Vertices on a parabola form a strictly convex polygon, so the direction from every
//   vertex to the deck node lies strictly inside the angle of its two cables: each module
//   alone carries its deck load with every bar compressed and every cable taut.
// - Every module is the same polygon scaled by its width, so a child module's end segment
//   runs along its parent's end segment and its end vertex lies on it (at the middle). The
//   parent's segment is split there and the coinciding pieces merge, exactly as for p = 1:
//   the counts follow eq. (2).
// - Keeping the vertices inside [1/4, 3/4] keeps the half-scale child polygons inside the
//   triangle (a, v_1, deck node) left free by the parent's outermost bar, so no member crosses
//   another and no node falls on a bar (a vertex at xi = 1/4 would put the child's last
//   vertex exactly on the parent's outer bar).
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"
#include "design/cable_pieces.h"
#include "design/topology.h"

namespace tbridge {

BridgeTopology PlanarMultiBar(int n, int p, double beta_deg, double span) {
  // PlanarSubstructure checks the config values and names the keys; this guards direct
  // calls against shifts and sizes out of range.
  if (n < 1 || n > kMaxComplexity || p < 1 || p > kMaxBarsPerModule) {
    throw ModelError("PlanarMultiBar: n = " + std::to_string(n) + ", p = " + std::to_string(p) +
                     " out of range; call PlanarSubstructure");
  }
  const int stations = 1 << n;       // deck intervals
  const int modules = stations - 1;  // = interior deck nodes
  const int free_nodes = (p + 1) * modules;
  const double h = span / stations;
  const double t = std::tan(0.5 * beta_deg * std::numbers::pi / 180.0);

  BridgeTopology topo;
  Structure& s = topo.structure;
  s.nodes.setZero(3, free_nodes + 2);
  s.fixed.assign(free_nodes + 2, false);
  // Numbering: deck nodes 0..modules-1 in x order, then the p vertices of each module in
  // module (deck x) order, supports last (x = 0, then x = span). p = 1 is SPEC.md §2.
  auto deck_node = [&](int k) {
    return k == 0 ? free_nodes : (k == stations ? free_nodes + 1 : k - 1);
  };
  auto vertex_node = [&](int k, int i) { return modules + (k - 1) * p + i; };
  for (int k = 1; k < stations; ++k) s.nodes(0, deck_node(k)) = k * h;
  s.nodes(0, free_nodes + 1) = span;
  s.fixed[free_nodes] = s.fixed[free_nodes + 1] = true;

  std::vector<std::pair<int, int>> runs;
  for (int k = 1; k < stations; ++k) {
    const int half = k & -k;  // module k spans grid points [k - half, k + half]
    const double a = (k - half) * h;
    const double width = 2 * half * h;
    int prev = deck_node(k - half);
    for (int i = 0; i < p; ++i) {
      const double xi = 0.25 + (2.0 * i + 1.0) / (4.0 * p);
      const int v = vertex_node(k, i);
      s.nodes(0, v) = a + width * xi;
      s.nodes(1, v) = -width * 2.0 * t * xi * (1.0 - xi);
      // An odd p has its middle bar vertical, as p = 1; the others lean.
      s.bars.push_back(
          {deck_node(k), v, 2 * i + 1 == p ? MemberGroup::kVertical : MemberGroup::kSubstructure});
      runs.emplace_back(prev, v);
      prev = v;
    }
    runs.emplace_back(prev, deck_node(k + half));
  }
  for (int k = 0; k < stations; ++k)
    s.strings.push_back({deck_node(k), deck_node(k + 1), MemberGroup::kDeck});
  // Tolerance 1e-9 span: nodes that lie on a run do so to rounding (~1e-15 span); nodes off
  // a run are a fixed fraction of a module's depth W tan(beta/2) away from it.
  for (const auto& [u, v] : SplitAndMergeCables(s.nodes, runs, 1e-9 * span)) {
    s.strings.push_back({u, v, MemberGroup::kSubstructure});
  }

  for (int k = 1; k < stations; ++k) topo.deck_nodes.push_back(deck_node(k));
  topo.planes = 1;
  topo.loaded_stations = modules;
  s.planar = true;
  s.Validate();
  return topo;
}

}  // namespace tbridge
