#include "design/topology.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <utility>

#include "core/error.h"

namespace tbridge {

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

void CheckParameters(int n, int p, double beta_deg, double span) {
  if (n < 1 || n > kMaxComplexity) {
    throw ConfigError("bridge.n", std::to_string(n),
                      "must be an integer in [1, " + std::to_string(kMaxComplexity) + "]");
  }
  if (p < 1 || p > kMaxBarsPerModule) {
    throw ConfigError("bridge.p", std::to_string(p),
                      "must be an integer in [1, " + std::to_string(kMaxBarsPerModule) + "]");
  }
  if (!(beta_deg > 0.0 && beta_deg < 90.0)) {
    throw ConfigError("bridge.beta_deg", std::to_string(beta_deg), "must be in (0, 90)");
  }
  if (!(span > 0.0) || !std::isfinite(span)) {
    throw ConfigError("bridge.span", std::to_string(span), "must be a positive number");
  }
}

// p = 1, SPEC.md §2. Every dyadic sub-span [a, b] hangs a "V" of two cables sloping at
// beta/2 down to a node under its midpoint; a vertical bar props that node from the deck.
// A V arm passes exactly through the bottom nodes of the sub-spans that share its end
// point, so arms are split there and coinciding pieces merged.
BridgeTopology PlanarOneBar(int n, double beta_deg, double span) {
  const int stations = 1 << n;  // deck intervals
  const int nb = stations - 1;  // bars = interior deck nodes
  const double h = span / stations;
  const double slope = std::tan(0.5 * beta_deg * kDegToRad);

  BridgeTopology t;
  Structure& s = t.structure;
  s.nodes.setZero(3, 2 * nb + 2);
  s.fixed.assign(2 * nb + 2, false);
  // Grid index k = 0..stations; deck node of interior k is k-1, bottom node k-1+nb.
  auto deck_node = [&](int k) { return k == 0 ? 2 * nb : (k == stations ? 2 * nb + 1 : k - 1); };
  auto bottom_node = [&](int k) { return k - 1 + nb; };
  for (int k = 1; k < stations; ++k) {
    s.nodes(0, deck_node(k)) = k * h;
  }
  s.nodes(0, 2 * nb + 1) = span;
  s.fixed[2 * nb] = s.fixed[2 * nb + 1] = true;

  // Depth of the bottom node at grid index k: its sub-span has width 2^v2(k) h.
  std::vector<double> depth(stations + 1, 0.0);
  for (int k = 1; k < stations; ++k) {
    const int width = k & -k;  // 2^v2(k) grid intervals on each side
    depth[k] = width * h * slope;
    s.nodes(0, bottom_node(k)) = k * h;
    s.nodes(1, bottom_node(k)) = -depth[k];
  }

  for (int k = 1; k < stations; ++k) {
    s.bars.push_back({deck_node(k), bottom_node(k), "vertical"});
  }
  for (int k = 0; k < stations; ++k) {
    s.strings.push_back({deck_node(k), deck_node(k + 1), "deck"});
  }

  // Cable pieces as node pairs; a set merges the pieces that several arms share.
  std::set<std::pair<int, int>> pieces;  // node pairs, ordered
  auto add_piece = [&](int u, int v) { pieces.insert(std::minmax(u, v)); };
  for (int k = 1; k < stations; ++k) {
    const int width = k & -k;
    // Left arm from deck grid point k - width down to bottom node k; right arm likewise.
    for (int dir : {-1, +1}) {
      const int end = k + dir * width;
      // Bottom nodes strictly between lie on the arm when their depth matches the line.
      int prev_node = deck_node(end);
      for (int m = end - dir; m != k; m -= dir) {
        const double line_depth = std::abs(m - end) * h * slope;
        if (std::abs(depth[m] - line_depth) <= 1e-12 * span) {
          add_piece(prev_node, bottom_node(m));
          prev_node = bottom_node(m);
        }
      }
      add_piece(prev_node, bottom_node(k));
    }
  }
  for (const auto& [u, v] : pieces) s.strings.push_back({u, v, "substructure"});

  for (int k = 1; k < stations; ++k) t.deck_nodes.push_back(deck_node(k));
  t.planes = 1;
  t.loaded_stations = nb;
  s.planar = true;
  s.Validate();
  return t;
}

}  // namespace

BridgeTopology PlanarSubstructure(int n, int p, double beta_deg, double span) {
  CheckParameters(n, p, beta_deg, span);
  if (p == 1) return PlanarOneBar(n, beta_deg, span);
  return PlanarMultiBar(n, p, beta_deg, span);
}

BridgeTopology MakeBridge(const BridgeConfig& c) {
  if (c.planes == 2) {
    if (c.p != 1) {
      throw ConfigError("bridge.p", std::to_string(c.p), "must be 1 when bridge.planes = 2");
    }
    CheckParameters(c.n, c.p, c.beta_deg, c.span);
    return CoupledBridge3D(c.n, c.beta_deg, c.span, c.deck_width);
  }
  return PlanarSubstructure(c.n, c.p, c.beta_deg, c.span);
}

}  // namespace tbridge
