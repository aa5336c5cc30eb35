// The static check at every deck station of every travelling family: its findings against a
// brute-force nonlinear solve of every case at every station, with every station solved
// nonlinearly (the default) and with the linear pass screening them.

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "checks/static_check.h"
#include "core/config.h"
#include "design/sizing.h"
#include "design/static_model.h"
#include "sizing/verified_design.h"

namespace tbridge {
namespace {

// What the check must find, found here by solving every case at every station: each member's
// largest utilisation [bars; strings] (yield and buckling of bars and yield of strings under
// the ultimate cases, slack taut strings under the serviceability ones) and the largest deck
// deflection under the serviceability cases.
struct BruteForce {
  std::vector<double> utilisation;
  double deflection = 0;
  int solves = 0;
};

BruteForce Solve(const Design& d) {
  const StaticModel model = StaticModelOf(d);
  const StaticState start = ReferenceState(model, d);
  const Structure& s = d.topology.structure;
  const int nb = s.num_bars(), ns = s.num_strings();
  const BarRule rule = BarRuleOf(d.config);
  const double E = d.config.material.youngs_modulus;
  const double sigma_w = d.config.material.yield_stress / d.config.design.yield_safety_factor;
  BruteForce out;
  out.utilisation.assign(nb + ns, 0.0);
  for (const LoadCase& c : d.cases) {
    const int stations = c.station_load != 0 ? static_cast<int>(d.actions.station_nodes.size()) : 1;
    for (int k = 0; k < stations; ++k) {
      const StaticResult r =
          SolveStatic(model, start, d.loads, d.actions.Loads(c, c.station_load != 0 ? k : -1));
      REQUIRE(r.converged);
      ++out.solves;
      if (c.state == LimitState::kUltimate) {
        for (int b = 0; b < nb; ++b) {
          const BarCapacity cap = BarResistance(d.bars[b].area, d.bars[b].length, rule, E);
          const double f = r.state.bar_compression[b];
          out.utilisation[b] =
              std::max({out.utilisation[b], std::abs(f) / cap.yield, f / cap.buckling});
        }
        for (int j = 0; j < ns; ++j) {
          if (d.strings[j].area > 0) {
            out.utilisation[nb + j] = std::max(
                out.utilisation[nb + j], r.state.string_tension[j] / (d.strings[j].area * sigma_w));
          }
        }
        continue;
      }
      for (int j = 0; j < ns; ++j) {
        const Member& e = s.strings[j];
        const double length = (r.state.nodes.col(e.j) - r.state.nodes.col(e.i)).norm();
        const double strain = (length - d.strings[j].rest_length) / d.strings[j].rest_length;
        if (strain < 0 && MustStayTaut(d, j)) {
          out.utilisation[nb + j] = std::max(out.utilisation[nb + j], 1 - strain / (sigma_w / E));
        }
      }
      for (int v : d.topology.deck_nodes)
        out.deflection = std::max(out.deflection, std::abs(r.state.nodes(1, v) - s.nodes(1, v)));
    }
  }
  return out;
}

// The check's findings are the brute force's. The check solves each station from the last
// station's equilibrium, the brute force from the reference state: two Newton solves of the
// same loads from different starts, each stopped where the forces balance to 1e-10 of the
// largest force, which leaves a member's utilisation within a few 1e-9 (3.4e-9 the most on
// this design). 1e-8: that, with room for rounding, and four orders below the sizing's margin
// of 1e-4 on every row, so no verdict can turn on it.
void RequireSameFindings(const StaticCheck& check, const BruteForce& truth) {
  REQUIRE(check.members.size() == truth.utilisation.size());
  for (size_t j = 0; j < truth.utilisation.size(); ++j) {
    INFO("member " << j << ", governed by " << check.members[j].governing_case);
    CHECK(check.members[j].utilisation == Approx(truth.utilisation[j]).epsilon(0).margin(1e-8));
  }
  // The deflection likewise: within 1e-8 of itself (1e-8 of 24 mm is 0.24 nm).
  CHECK(check.deflection_max_m == Approx(truth.deflection).epsilon(1e-8));
}

TEST_CASE("the static check finds what every station's nonlinear solve finds", "[verify]") {
  Config config = LoadConfig(TBRIDGE_SOURCE_DIR "/configs/default.json");
  config.bridge.n = 4;
  const Design d = DesignAndVerify(config);
  const BruteForce truth = Solve(d);
  const int stations = static_cast<int>(d.actions.station_nodes.size());
  REQUIRE(stations == 15);
  REQUIRE(truth.deflection > 0);

  // Every station nonlinearly (loads.station_margin = 1, the default).
  REQUIRE(d.config.loads.station_margin == 1.0);
  // The bridge is symmetric: of each travelling family's 15 stations, the 7 past mid-span are
  // the mirror images of the 7 before it, and 8 are solved.
  const StaticCheck every = CheckStatics(d);
  CHECK(every.stations == stations);
  CHECK(every.mirrored == 7 * 3);
  CHECK(every.nonlinear_solves + every.mirrored == truth.solves);
  RequireSameFindings(every, truth);

  // One string a hundredth larger and stiffer on one side: no mirror, every station solved.
  Design lopsided = d;
  lopsided.strings.front().area *= 1.01;
  lopsided.strings.front().stiffness *= 1.01;
  const StaticCheck one_sided = CheckStatics(lopsided);
  CHECK(one_sided.mirrored == 0);
  CHECK(one_sided.nonlinear_solves == truth.solves);
  RequireSameFindings(one_sided, Solve(lopsided));

  // Screened by the linear pass at a margin of 0.3: on this design the station that governs
  // a member nonlinearly lies at most 0.12 of the largest below it in the linear pass.
  Design screened = d;
  screened.config.loads.station_margin = 0.3;
  const StaticCheck within = CheckStatics(screened);
  INFO("nonlinear solves at margin 0.3: " << within.nonlinear_solves << " of " << truth.solves);
  RequireSameFindings(within, truth);

  // The screen does leave stations out: at margin 0 only the stations of each largest and
  // those at a limit are solved nonlinearly.
  screened.config.loads.station_margin = 0.0;
  const StaticCheck tight = CheckStatics(screened);
  CHECK(tight.nonlinear_solves < within.nonlinear_solves);
  CHECK(within.nonlinear_solves <= truth.solves);
}

}  // namespace
}  // namespace tbridge
