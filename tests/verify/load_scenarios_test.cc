// The dynamic loads of the check: the moving point load against the lever rule's closed form,
// and the moving load and the wind gust, run slowly, against their static counterparts (the
// quasi-static limit of a dynamic run).

#include "checks/load_scenarios.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "bridge/design_model.h"
#include "checks/dynamic_check.h"
#include "dynamics/model.h"
#include "dynamics/node_forces.h"
#include "sweep/first_frequency.h"

namespace tbridge {
namespace {

// The vertical load the scenario puts on the deck at time t, and its first moment about x = 0.
struct DeckLoad {
  double total = 0;   // [N], upward positive
  double moment = 0;  // [N m]
};
DeckLoad LoadAt(const Design& d, const DynamicsConfig& run, double t) {
  DeckLoad out;
  for (const LoadStepConfig& l : run.loads) {
    const double f = LoadShape(t, l.t_start, l.t_end, l.rise_s, l.fall_s, l.spread_s) * l.force[1];
    out.total += f;
    out.moment += f * d.topology.structure.nodes(0, l.node - 1);
  }
  return out;
}

TEST_CASE("a load crossing the deck is shared between deck nodes by the lever rule",
          "[verify][dynamics]") {
  Config config;
  config.bridge.n = 3;
  const Design d = RunDesign(config);
  const double q = 10000, v = 1.5, span = config.bridge.span;
  const DynamicsConfig run = MovingLoadScenario(d, q, Crossing{span, v, 0.0}, 1e-4);
  REQUIRE(run.duration == Approx(span / v).epsilon(1e-15));
  const std::vector<double>& x = d.actions.station_x;
  // 1e-12 relative: sums of a few products of ramps computed in double precision.
  for (int k = 0; k <= 200; ++k) {
    const double t = run.duration * k / 200.0, at = v * t;
    const DeckLoad load = LoadAt(d, run, t);
    INFO("t = " << t << " s, load at x = " << at << " m");
    if (at >= x.front() && at <= x.back()) {
      // Between the first and the last station the deck nodes carry all of it, centred on v t.
      CHECK(-load.total == Approx(q).epsilon(1e-12));
      CHECK(load.moment / load.total == Approx(at).margin(1e-12 * span));
    } else {
      // Between a support and its nearest station that station carries the lever rule's share,
      // the support the rest: q (distance from the support) / (station's distance from it).
      const double share = at < x.front() ? at / x.front() : (span - at) / (span - x.back());
      CHECK(-load.total == Approx(q * share).margin(1e-12 * q));
    }
  }
}

// A dynamic run whose load changes over times T_r much longer than the bridge's periods
// follows the static response: on each mode a ramp overshoots its static value by at most
// 2 / (omega T_r) of the change (the undamped one-degree-of-freedom ramp response), and the
// lowest frequency bounds that for every mode.
double QuasiStaticBound(const Design& d, double ramp_s) {
  ModelOptions options;  // the model the dynamic check runs: weight on, the deck's inertia
  options.gravity_on_structure = true;
  options.deck_inertia = true;
  const DynamicModel model = BuildDynamicModel(d, options);
  return 2.0 / (LowestFrequency(model).omega_rad_s * ramp_s);
}

TEST_CASE("a spread ramp is the mean of the ramp over the spread", "[verify][dynamics]") {
  // A trapezoid (rise 0.3 s, fall 0.5 s over [1, 2) s) and a hat (rise 0.25 s, fall 0.75 s),
  // spread over 0.2 s and over 1.1 s (more than a ramp), against the midpoint rule's mean of
  // the unspread shape over 200 000 points: the shape is piecewise linear, so the rule's error
  // is from its few kinks, below 1e-9 of the shape's scale at this resolution.
  struct Shape {
    double t_start, t_end, rise, fall;
  };
  for (const Shape& shape : {Shape{1, 2, 0.3, 0.5}, Shape{1, 2, 0.25, 0.75}}) {
    for (const double spread : {0.2, 1.1}) {
      for (double t = 0; t <= 3.2; t += 0.0137) {
        const int points = 200000;
        double sum = 0;
        for (int i = 0; i < points; ++i) {
          const double u = t - 0.5 * spread + (i + 0.5) * spread / points;
          sum += LoadShape(u, shape.t_start, shape.t_end, shape.rise, shape.fall);
        }
        INFO("spread " << spread << " s at t = " << t << " s");
        CHECK(LoadShape(t, shape.t_start, shape.t_end, shape.rise, shape.fall, spread) ==
              Approx(sum / points).margin(1e-9));
      }
    }
  }
}

TEST_CASE("a load spread over its contact length crossing the deck keeps its force and centre",
          "[verify][dynamics]") {
  Config config;
  config.bridge.n = 3;
  const Design d = RunDesign(config);
  const double q = 10000, v = 1.5, c = 0.1, span = config.bridge.span;
  const DynamicsConfig run = MovingLoadScenario(d, q, Crossing{span, v, c}, 1e-4);
  // The crossing lasts until the load has left the deck: (span + c) / v.
  REQUIRE(run.duration == Approx((span + c) / v).epsilon(1e-15));
  const std::vector<double>& x = d.actions.station_x;
  // Before it reaches the deck and after it has left, no load on a deck node.
  CHECK(LoadAt(d, run, 0.0).total == 0.0);
  CHECK(LoadAt(d, run, run.duration).total == 0.0);
  // A uniform load of length c centred at v t - c / 2, wholly between the first and the last
  // station, is shared so that the nodes carry all of it with its centroid (the lever rule is
  // linear in each part of it); 1e-12 relative: sums of a few products in double precision.
  for (int k = 0; k <= 400; ++k) {
    const double t = run.duration * k / 400.0, centre = v * t - 0.5 * c;
    if (centre - 0.5 * c < x.front() || centre + 0.5 * c > x.back()) continue;
    const DeckLoad load = LoadAt(d, run, t);
    INFO("t = " << t << " s, load centred at x = " << centre << " m");
    CHECK(-load.total == Approx(q).epsilon(1e-12));
    CHECK(load.moment / load.total == Approx(centre).margin(1e-12 * span));
  }
  // Each node's force has no corner: its slope changes over c / v as the load passes (by at
  // most its ramps' slope change 2 q / ramp over c / v), not at once as a point load's does.
  // Over steps of h the slope then changes by at most 2 q / ramp x h v / c; the point load's
  // changes by 2 q / ramp in one step, which this bound (1.05: the rounding of the slopes'
  // differences) would fail.
  const double h = 1e-5;
  for (const LoadStepConfig& l : run.loads) {
    const auto f = [&](double t) {
      return LoadShape(t, l.t_start, l.t_end, l.rise_s, l.fall_s, l.spread_s) * q;
    };
    const double ramp = std::min(l.rise_s, l.fall_s), bound = 2 * q / ramp * h * v / c;
    double largest = 0;
    for (double t = l.t_start - c / v; t < l.t_end + c / v; t += h) {
      const double change = (f(t + h) - f(t)) / h - (f(t) - f(t - h)) / h;
      largest = std::max(largest, std::abs(change));
    }
    INFO("node " << l.node);
    CHECK(largest <= 1.05 * bound);
  }
}

TEST_CASE("a load crossing slowly gives its static peaks", "[verify][dynamics]") {
  Config config;
  config.bridge.n = 2;
  config.loads.travelling_speed_m_s = 0.15;  // 3 m between stations: 20 s ramps
  Design d = RunDesign(config);
  const DynamicCheck check = CheckDynamics(d);
  REQUIRE(check.runs.size() == 1);  // the default cases ask for one dynamic load on a planar bridge
  const DynamicRun& run = check.runs.front();
  REQUIRE(run.name == "moving_load");
  REQUIRE(run.done);
  const double ramp_s = config.bridge.span / 4 / config.loads.travelling_speed_m_s;
  const double bound = QuasiStaticBound(d, ramp_s);
  INFO("quasi-static bound " << bound);
  REQUIRE(bound < 0.01);
  // Each group's dynamic peak against its static peak with Q_t standing at each station: equal
  // but for the overshoot bound (on the whole force, which the standing loads only dilute).
  for (const GroupAmplification& g : run.groups) {
    INFO("group " << NameOf(g.group));
    CHECK(g.amplification <= 1 + bound);
    CHECK(g.amplification >= 1 - bound);
  }
}

TEST_CASE("a slowly rising wind gives the static wind's forces", "[verify][dynamics]") {
  Config config;
  config.bridge.n = 2;
  config.bridge.planes = 2;
  config.bridge.beta_deg = 20;
  config.bridge.deck_width = 1.5;
  // The 3D design found with the paper's factors (SPEC's 3D bridge) and every engineering case.
  config.design.yield_safety_factor = 10;
  config.design.buckling_safety_factor = 1;
  config.design.bar_resistance = BarResistanceRule::kEuler;
  config.loads.wind_rise_s = 20;
  Design d = RunDesign(config);
  const DynamicCheck check = CheckDynamics(d);
  const DynamicRun& run = check.runs.back();
  REQUIRE(run.name == "wind_gust");
  REQUIRE(run.done);
  const double bound = QuasiStaticBound(d, config.loads.wind_rise_s);
  INFO("quasi-static bound " << bound);
  REQUIRE(bound < 0.01);
  for (const GroupAmplification& g : run.groups) {
    INFO("group " << NameOf(g.group) << ": static " << g.static_peak << " N, dynamic "
                  << g.dynamic_peak << " N");
    CHECK(g.amplification <= 1 + bound);
    CHECK(g.amplification >= 1 - bound);
  }
}

}  // namespace
}  // namespace tbridge
