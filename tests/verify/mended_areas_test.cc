// Mending a failing design member by member (MendedAreas) against the resistances' closed
// forms: a string's area in proportion to its demand, a bar's by its column-curve resistance.

#include <algorithm>
#include <catch2/catch.hpp>

#include "design/design.h"
#include "design/sizing.h"
#include "sizing/sizing_problem.h"
#include "sizing/verified_design.h"

namespace tbridge {
namespace {

// The other member of j's group (its mirror image), or -1.
int ImageOf(const std::vector<int>& group_of, int j) {
  for (int k = 0; k < static_cast<int>(group_of.size()); ++k) {
    if (k != j && group_of[k] == group_of[j]) return k;
  }
  return -1;
}

TEST_CASE("mending gives a failing member the area its checked demand asks, its image alike",
          "[verify]") {
  Config config;  // the engineering defaults at n = 2: column-curve bars, steel strings
  config.bridge.n = 2;
  Design d = RunDesign(config);
  const int nb = static_cast<int>(d.bars.size());
  const std::vector<int> group_of = MirrorGroups(d.topology.structure, config.bridge.span);
  for (auto* list : {&d.bars, &d.strings}) {
    for (MemberSizing& m : *list) m.utilisation = 0.5;
  }
  // A string over its yield resistance by 1 %: its demand 1.01 sigma_w A.
  const int s = nb + static_cast<int>(d.strings.size()) - 1;
  MemberSizing& string = d.strings.back();
  const double sigma_w = StringMaterial(config).DesignStress();
  Govern(string, 1.01 * sigma_w * string.area, sigma_w * string.area, LimitMode::kYield);
  // A bar over its buckling resistance by 2 %.
  const int b = 0;
  MemberSizing& bar = d.bars[b];
  const BarRule rule = BarRuleOf(config);
  const double E = BarMaterial(config).youngs_modulus;
  const BarCapacity c = BarResistance(bar.area, bar.length, rule, E);
  const double resistance = std::min(c.yield, c.buckling);
  Govern(bar, 1.02 * resistance, resistance, LimitMode::kBuckling);
  const double string_area = string.area, bar_area = bar.area, bar_demand = bar.demand;

  int mended = 0;
  const std::vector<double> areas = MendedAreas(d, group_of, &mended);
  REQUIRE(areas.size() == group_of.size());
  CHECK(mended == 2);
  // The string: its area times 1.01 and the margin 2e-4, exactly but for rounding.
  CHECK(areas[s] == Approx(string_area * 1.01 * 1.0002).epsilon(1e-14));
  // The bar: the area whose resistance is the demand and the margin. Sixty halvings of an
  // interval 3 % of the area wide leave it 1e-18 of the area wide, so the resistance (at most
  // quadratic in the area) to 1e-12 holds with room.
  const BarCapacity mended_bar = BarResistance(areas[b], bar.length, rule, E);
  CHECK(std::min(mended_bar.yield, mended_bar.buckling) ==
        Approx(bar_demand * 1.0002).epsilon(1e-12));
  CHECK(areas[b] > bar_area);
  CHECK(areas[b] < bar_area * 1.02 * 1.0002);  // buckling grows faster than the area
  // Mirror images take the same area; every other member keeps its own.
  for (const int j : {s, b}) {
    const int image = ImageOf(group_of, j);
    if (image >= 0) CHECK(areas[image] == areas[j]);
  }
  for (int j = 0; j < static_cast<int>(areas.size()); ++j) {
    if (group_of[j] == group_of[s] || group_of[j] == group_of[b]) continue;
    const MemberSizing& m = d.MemberAt(j);
    // Its group's largest: mirror images of the equilibrium design agree to rounding (1e-12).
    CHECK(areas[j] == Approx(m.area).epsilon(1e-12));
  }
  // A taut string gone slack is no matter of area: nothing is mended.
  Govern(string, 2e-4, 1e-4, LimitMode::kSlack);
  CHECK(MendedAreas(d, group_of, &mended).empty());
}

}  // namespace
}  // namespace tbridge
