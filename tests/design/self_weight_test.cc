// The self-weight fixed point of the n = 1 planar bridge against its statics worked by hand.
//
// The paper's one case (G + Q_full, unfactored) with design.self_weight on: a single case, so
// the design's forces are those of that load alone, and the bar is sized by the paper's
// closed forms (yield, Euler), which the hand solution can write down.

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "design/design.h"
#include "test_support.h"

namespace tbridge {
namespace {

// The bridge: supports at x = 0 and L (y = 0), the deck node at (L/2, 0), the bottom node
// h = (L/2) tan(beta/2) below it. A vertical bar joins the two; two horizontal deck strings
// run from the supports to the deck node, two cables at beta/2 from the supports to the
// bottom node. Every member's weight goes half to each end.
struct HandBridge {
  double bar_force = 0, cable_force = 0, deck_force = 0;  // [N]
  double bar_mass = 0, cable_mass = 0, deck_mass = 0;     // one member each [kg]
};

HandBridge SolveByHand(const Config& c, double deck_beam_mass) {
  const double L = c.bridge.span, g = c.design.gravity, F = c.bridge.payload;
  const double half_beta = c.bridge.beta_deg * std::numbers::pi / 360.0;
  const double rho = c.material.density, E = c.material.youngs_modulus;
  const double sigma_w = c.material.yield_stress / c.design.yield_safety_factor;
  const double bar_length = 0.5 * L * std::tan(half_beta);
  const double cable_length = 0.5 * L / std::cos(half_beta);
  const double deck_length = 0.5 * L;
  HandBridge h;
  // Deck strings sit at their prestress floor: area pi r^2, tension sigma_w times that.
  const double deck_area = std::numbers::pi * std::pow(c.design.deck_string_min_radius, 2);
  h.deck_force = sigma_w * deck_area;
  h.deck_mass = rho * deck_area * deck_length;
  double previous = -1;
  for (int pass = 0; pass < 100; ++pass) {
    // Deck node: the strings are horizontal, so the bar alone holds the vertical load: the
    // two deck beams' halves (m_d g), the payload of the one inner station (F L/2 / L) and
    // the halves of the bar and both deck strings.
    h.bar_force = deck_beam_mass * g + 0.5 * F + 0.5 * g * (h.bar_mass + 2.0 * h.deck_mass);
    // Bottom node: the bar pushes down, with half the bar and both cables' halves; the two
    // cables pull up at beta/2 each.
    const double bottom = h.bar_force + 0.5 * g * (h.bar_mass + 2.0 * h.cable_mass);
    h.cable_force = bottom / (2.0 * std::sin(half_beta));
    // Areas: cable A = T / sigma_w; bar the larger of yield (C gamma / f_y) and Euler with SF
    // (pi^2 E (A^2 / 4 pi) / l^2 = SF C).
    const double cable_area = h.cable_force / sigma_w;
    const double yield_area = h.bar_force * c.design.yield_safety_factor / c.material.yield_stress;
    const double euler_area =
        2.0 * bar_length *
        std::sqrt(c.design.buckling_safety_factor * h.bar_force / (std::numbers::pi * E));
    h.cable_mass = rho * cable_area * cable_length;
    h.bar_mass = rho * std::max(yield_area, euler_area) * bar_length;
    const double total = h.bar_mass + 2.0 * (h.cable_mass + h.deck_mass);
    if (std::abs(total - previous) <= 1e-15 * total) break;
    previous = total;
  }
  return h;
}

TEST_CASE("the n = 1 self-weight fixed point matches the hand solution") {
  Config c = test::PaperConfig(1);
  c.design.self_weight = true;
  const Design d = RunDesign(c);
  REQUIRE(d.bars.size() == 1);
  REQUIRE(d.strings.size() == 4);
  CHECK(d.self_weight_iterations > 2);  // the fixed point really iterated
  // The deck beam mass is the deck's (eqs 6-9, tested in deck tests): an input here.
  const HandBridge h = SolveByHand(c, d.deck.section_mass);
  const MemberSizing* bar = FindMember(d, "1-2");
  const MemberSizing* cable = FindMember(d, "2-3");
  const MemberSizing* deck = FindMember(d, "1-3");
  REQUIRE(bar);
  REQUIRE(cable);
  REQUIRE(deck);
  CHECK(bar->kind == MemberKind::kBar);
  CHECK(cable->kind == MemberKind::kString);
  CHECK(deck->kind == MemberKind::kDeckString);
  // The design stops its fixed point at 1e-12 relative change of the total mass, which
  // converges geometrically with a ratio of about the weight fraction (well under 0.1), and
  // its equilibrium solve is exact to rounding: 1e-9 leaves three orders for both.
  CHECK(bar->force == Approx(h.bar_force).epsilon(1e-9));
  CHECK(cable->force == Approx(h.cable_force).epsilon(1e-9));
  CHECK(deck->force == Approx(h.deck_force).epsilon(1e-9));
  CHECK(bar->mass == Approx(h.bar_mass).epsilon(1e-9));
  CHECK(cable->mass == Approx(h.cable_mass).epsilon(1e-9));
  CHECK(deck->mass == Approx(h.deck_mass).epsilon(1e-9));
  // The members' weight is far above the 1e-9 above: it adds 0.48 % to the bar force (and
  // more to the cables), so a fixed point that dropped it would fail these checks.
  CHECK(h.bar_force > 1.004 * (d.deck.section_mass * c.design.gravity + 0.5 * c.bridge.payload));
}

}  // namespace
}  // namespace tbridge
