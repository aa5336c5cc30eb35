#include "verify/dynamic_check.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "core/error.h"
#include "design/static_model.h"
#include "dynamics/model.h"
#include "dynamics/simulation.h"
#include "sweep/travelling_load.h"

namespace tbridge {

namespace {

const char* const kCase = "dynamic: paper_travelling";  // where a member's dynamic utilisation comes from

}  // namespace

DynamicCheck CheckDynamics(Design& d, double max_member_steps) {
  DynamicCheck out;
  const bool paper = KeepsPaperSwitches(d.config);
  // The model a run of this design gets (tbridge simulate with the defaults): the design
  // loads, permanent and payload, with the deck's inertia (not with the paper's switches).
  ModelOptions options;
  options.gravity_on_structure = d.config.design.self_weight;
  options.deck_inertia = !paper;
  const DynamicModel model = BuildDynamicModel(d, options);

  const int stations = static_cast<int>(d.actions.station_nodes.size());
  TravellingLoadConfig run;
  run.duration = 0.25 * stations;
  run.integrator = "rk4";
  run.load_factor = 1.0;
  run.dt = 1e-4;
  const double members = static_cast<double>(d.bars.size() + d.strings.size());
  if (run.duration / run.dt * members > max_member_steps) {
    std::ostringstream os;
    os << "skipped: " << run.duration / run.dt << " RK4 steps of " << members << " members exceed the "
       << max_member_steps << " member-steps the check allows";
    out.note = os.str();
    return out;
  }
  // A step that is not stable for this bridge blows up; a quarter of it is tried, twice.
  SimulationSummary summary;
  for (int attempt = 0;; ++attempt) {
    const DynamicsConfig scenario = TravellingLoadScenario(model, d, run);
    try {
      summary = Simulate(model, scenario).summary;
      out.dt = scenario.dt;
      break;
    } catch (const ModelError& e) {
      if (attempt == 2) {
        out.note = std::string("not done: the run failed at every step tried down to ") + std::to_string(run.dt) +
                   " s (" + e.what() + ")";
        return out;
      }
      run.dt /= 4;
      if (run.duration / run.dt * members > max_member_steps) {
        out.note = "skipped: RK4 needs a step below " + std::to_string(run.dt * 4) + " s, too many member-steps";
        return out;
      }
    }
  }
  out.done = true;
  out.duration = run.duration;
  out.steps = summary.steps;
  out.integrator = summary.substeps > 1 ? summary.integrator + "x" + std::to_string(summary.substeps) : summary.integrator;
  out.peak_deck_displacement = summary.peak_deck_displacement[1];

  // The static counterpart: the same loads with f standing at each station.
  const StaticModel statics = StaticModelOf(d);
  const StaticState start = ReferenceState(statics, d);
  const Structure& s = d.topology.structure;
  const int nb = s.num_bars();
  Eigen::VectorXd static_peak = Eigen::VectorXd::Zero(nb + s.num_strings());
  for (int k = 0; k < stations; ++k) {
    const Eigen::Matrix3Xd loads = model.loads + d.actions.StationLoad(k, d.deck.station_load);
    const StaticResult r = SolveStatic(statics, start, d.loads, loads);
    if (!r.converged) continue;
    for (int b = 0; b < nb; ++b) static_peak[b] = std::max(static_peak[b], r.state.bar_compression[b]);
    for (int j = 0; j < s.num_strings(); ++j) static_peak[nb + j] = std::max(static_peak[nb + j], r.state.string_tension[j]);
  }

  const double gamma_g = paper ? 1.0 : d.config.loads.gamma_g_sup;
  const double gamma_q = paper ? 1.0 : d.config.loads.gamma_q;
  const BarRule rule = BarRuleOf(d.config);
  const double E = d.config.material.youngs_modulus;
  const double sigma_w = d.config.material.yield_stress / d.config.design.yield_safety_factor;
  std::map<std::string, GroupAmplification> groups;
  for (int j = 0; j < nb + s.num_strings(); ++j) {
    const bool bar = j < nb;
    MemberSizing& m = bar ? d.bars[j] : d.strings[j - nb];
    const std::string& group = bar ? s.bars[j].group : s.strings[j - nb].group;
    const double peak = bar ? summary.peak_bar_compression[j] : summary.peak_string_tension[j - nb];
    const double demand = gamma_g * m.reference_force + gamma_q * std::max(peak - m.reference_force, 0.0);
    if (bar) {
      const BarCapacity cap = BarResistance(m.area, m.length, rule, E);
      RaiseUtilisation(m, demand / std::min(cap.yield, cap.buckling), kCase, "dynamic");
    } else {
      if (m.area > 0) RaiseUtilisation(m, demand / (m.area * sigma_w), kCase, "dynamic");
      const double strain = summary.min_string_strain[j - nb];
      if (strain < 0) RaiseUtilisation(m, SlackUtilisation(strain, sigma_w, E), kCase, "slack");
    }
    GroupAmplification& g = groups[group];
    g.group = group;
    g.static_peak = std::max(g.static_peak, static_peak[j]);
    g.dynamic_peak = std::max(g.dynamic_peak, peak);
    if (static_peak[j] > 0) g.amplification = std::max(g.amplification, peak / static_peak[j]);
  }
  for (auto& [name, g] : groups) out.groups.push_back(g);
  return out;
}

}  // namespace tbridge
