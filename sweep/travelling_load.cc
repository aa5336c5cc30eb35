#include "sweep/travelling_load.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "dynamics/simulation.h"

namespace tbridge {

DynamicsConfig TravellingLoadScenario(const DynamicModel& model, const Design& design,
                                      const TravellingLoadConfig& config) {
  if (model.deck_nodes.empty()) throw ModelError("travelling load: the model has no deck nodes");
  const int planes = std::max(1, design.topology.planes);
  const int stations = static_cast<int>(model.deck_nodes.size()) / planes;
  const double station_time = config.duration / stations;
  const double per_station = std::max(1.0, std::ceil(station_time / config.dt - 1e-9));
  const double force = config.load_factor * design.deck.node_load;

  DynamicsConfig run;
  run.duration = config.duration;
  run.dt = station_time / per_station;
  run.integrator = config.integrator;
  run.frequency.enabled = false;
  run.record.bar_forces = true;  // the capacity check
  for (int k = 0; k < stations; ++k) {
    for (int plane = 0; plane < planes; ++plane) {
      run.loads.push_back({k * station_time, (k + 1) * station_time, model.deck_nodes[k + plane * stations] + 1,
                           {0, -force, 0}});
    }
  }
  return run;
}

TravellingLoadResult RunTravellingLoad(const DynamicModel& model, const Design& design,
                                       const TravellingLoadConfig& config) {
  if (design.bars.size() != model.bars.size()) throw ModelError("travelling load: model and design bars differ");
  const DynamicsConfig run = TravellingLoadScenario(model, design, config);
  const SimulationSummary s = Simulate(model, run).summary;

  TravellingLoadResult r;
  r.peak_deck_displacement = s.peak_deck_displacement[1];
  r.peak_string_stress = s.max_string_stress;
  r.peak_stress_ratio = s.max_string_stress / model.allowed_stress;
  r.slack_strings = s.slack.ever_slack;
  r.steps = s.steps;
  r.dt = run.dt;
  r.integrator = s.substeps > 1 ? s.integrator + "x" + std::to_string(s.substeps) : s.integrator;
  r.engine = s.engine;
  const double sigma_w = model.allowed_stress;
  const double sf_buckling = design.config.design.buckling_safety_factor;
  for (size_t k = 0; k < model.bars.size(); ++k) {
    const double area = design.bars[k].area;
    if (area <= 0) continue;  // a bar the design left out carries nothing
    const double l = model.bars[k].length;
    const double euler = std::numbers::pi * model.youngs_modulus * area * area / (4 * l * l * sf_buckling);
    const double compression = s.peak_bar_compression[k] / std::min(sigma_w * area, euler);
    const double tension = s.peak_bar_tension[k] / (sigma_w * area);
    r.peak_bar_capacity_ratio = std::max({r.peak_bar_capacity_ratio, compression, tension});
  }
  return r;
}

}  // namespace tbridge
