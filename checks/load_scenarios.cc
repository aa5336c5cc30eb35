#include "checks/load_scenarios.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace tbridge {

namespace {

// A run that records peaks only: bar forces for the capacity check, no frequency, no history.
DynamicsConfig PeaksOnly(double duration_s, double dt_s, IntegratorKind integrator) {
  DynamicsConfig run;
  run.duration = duration_s;
  run.dt = dt_s;
  run.integrator = integrator;
  run.frequency.enabled = false;
  run.record.bar_forces = true;
  return run;
}

void RequireStations(const Design& design, const char* what) {
  if (design.actions.station_nodes.empty())
    throw ModelError(std::string(what) + ": the bridge has no deck stations");
}

}  // namespace

DynamicsConfig PaperTravellingScenario(const Design& design, double duration_s, double dt_s,
                                       IntegratorKind integrator, double force_n) {
  RequireStations(design, "travelling load");
  const std::vector<std::vector<int>>& stations = design.actions.station_nodes;
  const int count = static_cast<int>(stations.size());
  const double station_time = duration_s / count;
  const double per_station = std::max(1.0, std::ceil(station_time / dt_s - 1e-9));
  DynamicsConfig run = PeaksOnly(duration_s, station_time / per_station, integrator);
  for (int k = 0; k < count; ++k) {
    const double share = force_n / static_cast<double>(stations[k].size());
    for (const int v : stations[k]) {
      run.loads.push_back({k * station_time, (k + 1) * station_time, v + 1, {0, -share, 0}});
    }
  }
  return run;
}

Crossing TravellingCrossing(const Design& design) {
  const LoadsConfig& l = design.config.loads;
  return {design.config.bridge.span, l.travelling_speed_m_s, l.travelling_contact_length_m};
}

DynamicsConfig MovingLoadScenario(const Design& design, double force_n, const Crossing& crossing,
                                  double dt_s) {
  RequireStations(design, "moving load");
  const Actions& a = design.actions;
  const double span = crossing.span_m;
  DynamicsConfig run = PeaksOnly(crossing.DurationS(), dt_s, IntegratorKind::kRk4);
  const int count = static_cast<int>(a.station_nodes.size());
  for (int k = 0; k < count; ++k) {
    // The deck points either side: the previous station (or the support at 0), the next (or
    // the support at the span). The load reaches this station at x_k / v.
    const double before = crossing.TimeAtS(k == 0 ? 0.0 : a.station_x[k - 1]);
    const double at = crossing.TimeAtS(a.station_x[k]);
    const double after = crossing.TimeAtS(k + 1 == count ? span : a.station_x[k + 1]);
    const double share = force_n / static_cast<double>(a.station_nodes[k].size());
    for (const int v : a.station_nodes[k]) {
      LoadStepConfig l;
      l.t_start = before;
      l.t_end = after;
      l.rise_s = at - before;
      l.fall_s = after - at;
      l.spread_s = crossing.SpreadS();
      l.node = v + 1;
      l.force = {0, -share, 0};
      run.loads.push_back(l);
    }
  }
  return run;
}

DynamicsConfig WindGustScenario(const Design& design, double rise_s, double dt_s) {
  const Eigen::Matrix3Xd& wind = design.actions.base[kWind];
  DynamicsConfig run = PeaksOnly(2 * rise_s, dt_s, IntegratorKind::kRk4);
  for (int v = 0; v < wind.cols(); ++v) {
    if (wind.col(v).isZero(0.0)) continue;
    LoadStepConfig l;
    l.t_start = 0;
    l.t_end = 2 * run.duration;  // past the run's end, so its last stage still sees the wind
    l.rise_s = rise_s;
    l.node = v + 1;
    l.force = {wind(0, v), wind(1, v), wind(2, v)};
    run.loads.push_back(l);
  }
  if (run.loads.empty())
    throw ModelError("wind gust: the bridge has no wind action (a planar bridge)");
  return run;
}

}  // namespace tbridge
