// The p = 1 planar topology (SPEC §2): counts, numbering and geometry.
#include "design/topology.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

namespace tbridge {
namespace {

TEST_CASE("p = 1 counts follow SPEC §2 for n = 1..12", "[topology]") {
  for (int n = 1; n <= 12; ++n) {
    const BridgeTopology t = PlanarSubstructure(n, 1, 10.0, 12.0);
    const int nb = (1 << n) - 1;
    INFO("n = " << n);
    CHECK(t.structure.num_bars() == nb);
    CHECK(t.structure.num_strings() == 3 * (1 << n) - 2);
    CHECK(t.structure.num_nodes() == 2 * nb + 2);
    CHECK(t.structure.TensegrityClass() == 1);
    CHECK(static_cast<int>(t.deck_nodes.size()) == nb);
  }
}

TEST_CASE("p = 1 numbering and geometry", "[topology]") {
  const int n = 3, nb = 7;
  const BridgeTopology t = PlanarSubstructure(n, 1, 10.0, 12.0);
  const Structure& s = t.structure;
  const double slope = std::tan(5.0 * std::numbers::pi / 180.0);
  for (int k = 0; k < nb; ++k) {
    // Deck node k+1 at x = (k+1) L / 2^n, y = 0; bar k+1 joins it to node k+1+n_b below.
    CHECK(s.nodes(0, k) == Approx(1.5 * (k + 1)).epsilon(1e-15));
    CHECK(s.nodes(1, k) == 0.0);
    CHECK(s.bars[k].i == k);
    CHECK(s.bars[k].j == k + nb);
    CHECK(s.nodes(0, k + nb) == Approx(s.nodes(0, k)).epsilon(1e-15));
    CHECK(s.nodes(1, k + nb) < 0.0);
  }
  // The supports are the last two nodes, at x = 0 and x = L.
  CHECK(s.fixed[2 * nb]);
  CHECK(s.fixed[2 * nb + 1]);
  CHECK(s.nodes(0, 2 * nb) == 0.0);
  CHECK(s.nodes(0, 2 * nb + 1) == 12.0);
  // Every cable segment slopes at beta/2 (or is a horizontal deck cable).
  for (const Member& m : s.strings) {
    const Eigen::Vector3d d = s.nodes.col(m.j) - s.nodes.col(m.i);
    if (m.group == MemberGroup::kDeck) {
      CHECK(d.y() == 0.0);
    } else {
      CHECK(std::abs(d.y() / d.x()) == Approx(slope).epsilon(1e-12));
    }
  }
  // The central bottom node hangs (L/2) tan(beta/2) below the deck.
  CHECK(s.nodes(1, 3 + nb) == Approx(-6.0 * slope).epsilon(1e-15));
}

}  // namespace
}  // namespace tbridge
