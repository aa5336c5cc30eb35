#include "sweep/travelling_load.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "dynamics/simulation.h"
#include "verify/load_scenarios.h"

namespace tbridge {

DynamicsConfig TravellingLoadScenario(const Design& design, const TravellingLoadConfig& config) {
  return PaperTravellingScenario(design, config.duration, config.dt, config.integrator,
                                 config.load_factor * design.deck.station_load);
}

TravellingLoadResult RunTravellingLoad(const DynamicModel& model, const Design& design,
                                       const TravellingLoadConfig& config) {
  if (design.bars.size() != model.bars.size()) throw ModelError("travelling load: model and design bars differ");
  const DynamicsConfig run = TravellingLoadScenario(design, config);
  const SimulationSummary s = Simulate(model, run).summary;

  TravellingLoadResult r;
  r.peak_deck_displacement = s.peak_deck_displacement[1];
  r.peak_string_stress = s.max_string_stress;
  r.peak_stress_ratio = s.max_string_stress / model.allowed_stress;
  r.slack_strings = s.slack.ever_slack;
  for (int k = 0; k < static_cast<int>(design.strings.size()); ++k) {
    if (s.min_string_strain[k] < 0 && MustStayTaut(design, k)) ++r.slack_taut_strings;
  }
  r.steps = s.steps;
  r.dt = run.dt;
  r.integrator = s.substeps > 1 ? s.integrator + "x" + std::to_string(s.substeps) : s.integrator;
  r.engine = s.engine;
  // The design's own bar resistance (the column curve, or the paper's Euler load with its
  // switches): the capacity the sizing used.
  const BarRule rule = BarRuleOf(design.config);
  for (size_t k = 0; k < model.bars.size(); ++k) {
    const double area = design.bars[k].area;
    if (area <= 0) continue;  // a bar the design left out carries nothing
    const BarCapacity cap = BarResistance(area, model.bars[k].length, rule, BarMaterial(design.config).youngs_modulus);
    const double compression = s.peak_bar_compression[k] / std::min(cap.yield, cap.buckling);
    const double tension = s.peak_bar_tension[k] / cap.yield;
    r.peak_bar_capacity_ratio = std::max({r.peak_bar_capacity_ratio, compression, tension});
  }
  return r;
}

}  // namespace tbridge
