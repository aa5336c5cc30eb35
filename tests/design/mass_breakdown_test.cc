// The mass breakdown (design/design.h MassesOf), the one every design's masses come from: each
// kind summed, and its parts summing to the structure and the total.
#include <catch2/catch.hpp>
#include <vector>

#include "design/design.h"

namespace tbridge {
namespace {

MemberSizing Member(MemberKind kind, double mass) {
  MemberSizing m;
  m.kind = kind;
  m.mass = mass;
  return m;
}

TEST_CASE("the mass breakdown sums each kind, and its parts sum to the structure and total",
          "[mass]") {
  // Masses that are exact in binary, so every sum is exact and compared with ==.
  const std::vector<MemberSizing> bars = {Member(MemberKind::kBar, 1.5),
                                          Member(MemberKind::kBar, 2.25)};
  const std::vector<MemberSizing> strings = {
      Member(MemberKind::kString, 0.5), Member(MemberKind::kDeckString, 4.0),
      Member(MemberKind::kString, 0.125), Member(MemberKind::kDeckString, 8.0)};
  const MassBreakdown m = MassesOf(bars, strings, 100.0);
  CHECK(m.bars == 3.75);
  CHECK(m.strings == 0.625);
  CHECK(m.deck_strings == 12.0);
  CHECK(m.deck_beams == 100.0);
  CHECK(m.structure == m.bars + m.strings + m.deck_strings);
  CHECK(m.structure == 16.375);
  CHECK(m.total == 116.375);
  const MassBreakdown none = MassesOf({}, {}, 0.0);
  CHECK(none.total == 0.0);
}

}  // namespace
}  // namespace tbridge
