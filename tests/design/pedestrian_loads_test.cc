// The footbridge comfort guides' constants (design/pedestrian_loads.h) at the points the
// guides tabulate: Sétra 2006 and HiVoSS 2008, typed here from their tables and figures.
#include "design/pedestrian_loads.h"

#include <catch2/catch.hpp>
#include <cmath>

namespace tbridge {

TEST_CASE("psi(f) at the corners of Sétra's figures, and half-way up each flank", "[comfort]") {
  // The corners are the guide's own numbers (Sétra 2006, Stage 4, the figures of psi for load
  // cases 1 and 3): exact (0 and 1). Half-way along a flank the trapezoid is 1/2; 1e-12
  // allows for the division. Each plateau is Stage 3's range 1 (of the harmonic), each flank
  // its range 2: psi is 1 wherever the risk is greatest.
  for (const LoadAxis axis : {LoadAxis::kVertical, LoadAxis::kLongitudinal}) {
    CHECK(Psi(axis, 1, 1.0) == 0.0);
    CHECK(Psi(axis, 1, 1.7) == 1.0);
    CHECK(Psi(axis, 1, 1.9) == 1.0);
    CHECK(Psi(axis, 1, 2.1) == 1.0);
    CHECK(Psi(axis, 1, 2.6) == 0.0);
    CHECK(Psi(axis, 1, 1.35) == Approx(0.5).margin(1e-12));
    CHECK(Psi(axis, 1, 2.35) == Approx(0.5).margin(1e-12));
    CHECK(Psi(axis, 1, 3.0) == 0.0);
    CHECK(Psi(axis, 2, 2.6) == 0.0);
    CHECK(Psi(axis, 2, 3.4) == 1.0);
    CHECK(Psi(axis, 2, 4.2) == 1.0);
    CHECK(Psi(axis, 2, 5.0) == 0.0);
    CHECK(Psi(axis, 2, 3.0) == Approx(0.5).margin(1e-12));
    CHECK(Psi(axis, 2, 4.6) == Approx(0.5).margin(1e-12));
  }
  CHECK(Psi(LoadAxis::kLateral, 1, 0.3) == 0.0);
  CHECK(Psi(LoadAxis::kLateral, 1, 0.5) == 1.0);
  CHECK(Psi(LoadAxis::kLateral, 1, 1.1) == 1.0);
  CHECK(Psi(LoadAxis::kLateral, 1, 1.3) == 0.0);
  CHECK(Psi(LoadAxis::kLateral, 1, 0.4) == Approx(0.5).margin(1e-12));
  CHECK(Psi(LoadAxis::kLateral, 1, 1.2) == Approx(0.5).margin(1e-12));
  CHECK(Psi(LoadAxis::kLateral, 2, 1.3) == 0.0);
  CHECK(Psi(LoadAxis::kLateral, 2, 1.9) == 1.0);
  CHECK(Psi(LoadAxis::kLateral, 2, 2.3) == Approx(0.5).margin(1e-12));
  CHECK(Psi(LoadAxis::kLateral, 2, 2.5) == 0.0);
  // psi is 1 over all of range 1 and above 0 inside range 2 (Stage 3's table), per axis.
  for (const LoadAxis axis : {LoadAxis::kVertical, LoadAxis::kLateral}) {
    for (double f = 0.05; f < 6.0; f += 0.01) {
      const int range = RiskRange(axis, f);
      if (range == 1) CHECK(Psi(axis, 1, f) == 1.0);
      if (range == 2) CHECK(Psi(axis, 1, f) > 0.0);
    }
  }
  // The largest over a band: the plateau when the band crosses it, else the higher end.
  CHECK(PsiOver(LoadAxis::kVertical, 1, 1.5, 2.5) == 1.0);
  CHECK(PsiOver(LoadAxis::kVertical, 2, 2.6, 3.05) ==
        Approx(Psi(LoadAxis::kVertical, 2, 3.05)).margin(1e-15));
  CHECK(PsiOver(LoadAxis::kVertical, 1, 2.6, 3.0) == 0.0);
}

TEST_CASE("the equivalent pedestrian numbers at the guide's worked values", "[comfort]") {
  // Sétra load case 1: 10.8 sqrt(xi n); case 2: 1.85 sqrt(n). Hand values: xi = 0.004, n = 100
  // gives 10.8 x 0.6324555 = 6.8305197; n = 100 very dense gives 18.5; xi = 0.01, n = 64 gives
  // 10.8 x 0.8 = 8.64. 1e-12 relative: one square root.
  CHECK(EquivalentPedestrians(0.004, 100, false) == Approx(6.8305197).epsilon(1e-7));
  CHECK(EquivalentPedestrians(0.01, 64, false) == Approx(8.64).epsilon(1e-12));
  CHECK(EquivalentPedestrians(0.004, 100, true) == Approx(18.5).epsilon(1e-12));
  // One pedestrian's forces: 280, 140, 35 N (first harmonic); 70, 35, 7 N (second).
  CHECK(PedestrianForceN(LoadAxis::kVertical, 1) == 280.0);
  CHECK(PedestrianForceN(LoadAxis::kLongitudinal, 1) == 140.0);
  CHECK(PedestrianForceN(LoadAxis::kLateral, 1) == 35.0);
  CHECK(PedestrianForceN(LoadAxis::kVertical, 2) == 70.0);
  CHECK(PedestrianForceN(LoadAxis::kLongitudinal, 2) == 35.0);
  CHECK(PedestrianForceN(LoadAxis::kLateral, 2) == 7.0);
  // Lock-in: 8 pi xi f M / 300 for xi = 0.004, f = 1 Hz, M = 10 t: 3.351032.
  CHECK(LockInPedestrians(0.004, 1.0, 1e4) == Approx(3.3510322).epsilon(1e-7));
}

TEST_CASE("classes, ranges, load cases, comfort levels and damping as the guide tabulates them",
          "[comfort]") {
  CHECK(TrafficDensity(TrafficClass::kI) == 1.0);
  CHECK(TrafficDensity(TrafficClass::kII) == 0.8);
  CHECK(TrafficDensity(TrafficClass::kIII) == 0.5);
  CHECK(TrafficDensity(TrafficClass::kIV) == 0.0);
  CHECK_THROWS_AS(TrafficDensity(static_cast<TrafficClass>(-1)),
                  std::invalid_argument);  // outside the enum
  // Vertical ranges: 1 [1.7, 2.1]; 2 [1, 1.7) and (2.1, 2.6]; 3 (2.6, 5]; 4 else.
  CHECK(RiskRange(LoadAxis::kVertical, 1.9) == 1);
  CHECK(RiskRange(LoadAxis::kVertical, 1.2) == 2);
  CHECK(RiskRange(LoadAxis::kVertical, 2.4) == 2);
  CHECK(RiskRange(LoadAxis::kVertical, 3.5) == 3);
  CHECK(RiskRange(LoadAxis::kVertical, 5.5) == 4);
  CHECK(RiskRange(LoadAxis::kVertical, 0.8) == 4);
  // Lateral: 1 [0.5, 1.1]; 2 [0.3, 0.5) and (1.1, 1.3]; 3 (1.3, 2.5]; 4 else.
  CHECK(RiskRange(LoadAxis::kLateral, 0.8) == 1);
  CHECK(RiskRange(LoadAxis::kLateral, 1.2) == 2);
  CHECK(RiskRange(LoadAxis::kLateral, 2.0) == 3);
  CHECK(RiskRange(LoadAxis::kLateral, 2.7) == 4);
  CHECK(RiskRangeOver(LoadAxis::kVertical, 2.3, 3.0) == 2);
  CHECK(RiskRangeOver(LoadAxis::kVertical, 1.5, 2.5) == 1);
  // Sétra's table of load cases.
  CHECK(LoadCaseFor(TrafficClass::kIII, 1)->number == 1);
  CHECK(!LoadCaseFor(TrafficClass::kIII, 2));
  CHECK(!LoadCaseFor(TrafficClass::kIII, 3));
  CHECK(LoadCaseFor(TrafficClass::kII, 2)->number == 1);
  CHECK(LoadCaseFor(TrafficClass::kII, 3)->number == 3);
  CHECK(LoadCaseFor(TrafficClass::kII, 3)->harmonic == 2);
  CHECK(LoadCaseFor(TrafficClass::kI, 1)->number == 2);
  CHECK(LoadCaseFor(TrafficClass::kI, 1)->very_dense);
  CHECK(!LoadCaseFor(TrafficClass::kI, 4));
  CHECK(!LoadCaseFor(TrafficClass::kIV, 1));
  // Comfort levels: vertical 0.5 / 1 / 2.5 m/s^2, horizontal 0.15 / 0.3 / 0.8.
  CHECK(ComfortLevelReached(LoadAxis::kVertical, 0.4) == 1);
  CHECK(ComfortLevelReached(LoadAxis::kVertical, 0.7) == 2);
  CHECK(ComfortLevelReached(LoadAxis::kVertical, 2.0) == 3);
  CHECK(ComfortLevelReached(LoadAxis::kVertical, 3.0) == 4);
  CHECK(ComfortLevelReached(LoadAxis::kLateral, 0.2) == 2);
  CHECK(ComfortLevelBound(LoadAxis::kLateral, ComfortLevel::kMinimum) == 0.8);
  CHECK(std::string(ComfortLevelName(4)) == "unacceptable");
  CHECK(ConstructionDamping(Construction::kSteel) == 0.004);
  CHECK(ConstructionDamping(Construction::kReinforcedConcrete) == 0.013);
  CHECK_THROWS_AS(ConstructionDamping(static_cast<Construction>(-1)), std::invalid_argument);
}

}  // namespace tbridge
