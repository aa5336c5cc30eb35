#include "checks/dynamic_check.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

#include "bridge/design_model.h"
#include "checks/load_scenarios.h"
#include "checks/modal_run.h"
#include "core/error.h"
#include "design/static_model.h"
#include "dynamics/model.h"
#include "dynamics/simulation.h"

namespace tbridge {

namespace {

// One dynamic load: its scenario, the static loads it is compared with (each on top of the
// model's standing loads), and the factor on what it adds to the permanent forces. The static
// loads are described, not formed: `station_force` [N] standing at each deck station in turn,
// or with 0 the full wind; StaticPeaks forms one at a time, and only for a run that is done.
struct LoadRun {
  DynamicRun record;
  DynamicsConfig scenario;
  double station_force = 0;
  double gamma = 1.0;
  bool walking = false;  // the walking load: the one a modal run may take
  Crossing crossing;     // a travelling load's timing: when it stands at each station
};

LoadRun MakeRun(const char* name, std::string load, DynamicsConfig scenario, double station_force,
                double gamma) {
  LoadRun run;
  run.record.name = name;
  run.record.load = std::move(load);
  run.scenario = std::move(scenario);
  // RK4 lets the bar lengths drift: over a crossing of 8 s at n = 6 the drift reaches the
  // guard's 1e-3 and the run fails. The stabilisation holds them (eqs 24-26; its term is a
  // force on the length error alone, zero on the exact motion): the peaks agree with an
  // unstabilised run to 1e-9 relative where that completes (n = 3;
  // tests/verify/dynamic_check_test.cc).
  run.scenario.stabilisation.enabled = true;
  run.station_force = station_force;
  run.gamma = gamma;
  return run;
}

std::string Describe(const char* what, double value, const char* unit) {
  std::ostringstream os;
  os << what << value << unit;
  return os.str();
}

// The loads a design is checked under: the paper's travelling load with its switches or the
// "paper_travelling" case; Q_t at walking speed with the "travelling" case; the wind gust with
// the "wind" case on a 3D bridge.
std::vector<LoadRun> LoadRuns(const Design& d, bool paper) {
  const LoadsConfig& l = d.config.loads;
  const double gamma_g_q = paper ? 1.0 : l.gamma_q;
  std::vector<LoadRun> runs;
  if (paper || l.Asks(LoadFamily::kPaperTravelling)) {
    const double paper_duration = 0.25 * static_cast<double>(d.actions.station_nodes.size());
    runs.push_back(
        MakeRun("paper_travelling",
                Describe("f = ", d.deck.station_load, " N per station for 0.25 s (eqs 50-51)"),
                PaperTravellingScenario(d, paper_duration, l.dynamic_dt_s, IntegratorKind::kRk4,
                                        d.deck.station_load),
                d.deck.station_load, gamma_g_q));
    const double span = d.config.bridge.span;
    runs.back().crossing = {span, span / paper_duration, 0.0};
  }
  if (l.Asks(LoadFamily::kTravelling) && l.travelling_load_n > 0) {
    const Crossing crossing = TravellingCrossing(d);
    runs.push_back(MakeRun("moving_load",
                           Describe("Q_t = ", l.travelling_load_n, " N") +
                               Describe(" on ", l.travelling_contact_length_m, " m") +
                               Describe(" crossing at ", l.travelling_speed_m_s, " m/s"),
                           MovingLoadScenario(d, l.travelling_load_n, crossing, l.dynamic_dt_s),
                           l.travelling_load_n, gamma_g_q));
    runs.back().walking = true;
    runs.back().crossing = crossing;
  }
  if (l.Asks(LoadFamily::kWind) && d.topology.planes == 2 && l.wind_n_per_m > 0) {
    runs.push_back(MakeRun("wind_gust",
                           Describe("W = ", l.wind_n_per_m, " N/m") +
                               Describe(" rising over ", l.wind_rise_s, " s, then held"),
                           WindGustScenario(d, l.wind_rise_s, l.dynamic_dt_s), 0.0, l.gamma_w));
  }
  return runs;
}

// Whether `run` at its present step stays within `max_member_steps`; if not, says so in its
// note, with `why_dt` after the step.
bool WithinBudget(double members, double max_member_steps, const char* why_dt, LoadRun& run) {
  const double steps = run.scenario.duration / run.scenario.dt;
  if (steps * members <= max_member_steps) return true;
  std::ostringstream os;
  if (!run.record.note.empty()) os << run.record.note << "; ";
  os << "skipped: " << steps << " RK4 steps of " << members
     << " members at dt = " << run.scenario.dt << " s" << why_dt << " exceed the "
     << max_member_steps << " member-steps the check allows";
  run.record.note = os.str();
  return false;
}

// Runs `run` on `model`. Its step is first brought within RK4's stability limit for this
// bridge, `stable_dt` (Rk4StableStep), as a whole fraction of the asked step so that the
// paper's stations still fall on step boundaries; a run that still blows up (a motion far
// from the linearised one) is tried at a quarter of the step, twice. Fills the record's run
// fields, or its note when skipped or failed.
bool Run(const DynamicModel& model, double stable_dt, double members, double max_member_steps,
         LoadRun& run, SimulationSummary& summary, ProgressReporter* progress) {
  DynamicRun& r = run.record;
  if (run.scenario.dt > stable_dt) run.scenario.dt /= std::ceil(run.scenario.dt / stable_dt);
  for (int attempt = 0;; ++attempt) {
    if (!WithinBudget(members, max_member_steps, "", run)) return false;
    try {
      RunHooks hooks;
      hooks.progress = progress;
      if (progress != nullptr) progress->Stage("dynamic check: " + run.record.name);
      summary = Simulate(model, run.scenario, {}, hooks).summary;
      break;
    } catch (const ModelError& e) {
      if (attempt == 2) {
        r.note = "not done: the run failed at every step tried down to " +
                 std::to_string(run.scenario.dt) + " s (" + e.what() + ")";
        return false;
      }
      run.scenario.dt /= 4;
    }
  }
  r.done = true;
  r.dt = run.scenario.dt;
  r.duration = run.scenario.duration;
  r.steps = summary.steps;
  r.integrator = summary.substeps > 1 ? summary.integrator + "x" + std::to_string(summary.substeps)
                                      : summary.integrator;
  r.peak_deck_displacement = summary.peak_deck_displacement[1];
  return true;
}

// Each member's largest force [C_bars; T_strings] over the static counterparts of a run (its
// `stations`, or with none the full wind) and the standing loads alone, where every run
// starts [N].
Eigen::VectorXd StaticPeaks(const Design& d, const DynamicModel& model, const StaticModel& statics,
                            const StationResponses* stations) {
  if (stations != nullptr) {
    Eigen::VectorXd peak = stations->standing_forces.cwiseMax(0.0);
    for (const Eigen::VectorXd& f : stations->forces) peak = peak.cwiseMax(f);
    return peak;
  }
  // The full wind.
  const StaticState start = ReferenceState(statics, d);
  const int nb = d.topology.structure.num_bars(), ns = d.topology.structure.num_strings();
  Eigen::VectorXd peak = Eigen::VectorXd::Zero(nb + ns);
  for (const Eigen::Matrix3Xd& loads :
       {Eigen::Matrix3Xd(model.loads + d.actions.base[kWind]), model.loads}) {
    const StaticResult r = SolveStatic(statics, start, d.loads, loads);
    if (!r.converged) continue;
    peak.head(nb) = peak.head(nb).cwiseMax(r.state.bar_compression);
    peak.tail(ns) = peak.tail(ns).cwiseMax(r.state.string_tension);
  }
  return peak;
}

// Whether `run` is tried by modal superposition first: the walking load, where the config
// asks for it.
bool Modal(const LoadRun& run, const LoadsConfig& l) {
  return run.walking && l.dynamic_method == DynamicMethod::kModal;
}

// The walking load by modal superposition (checks/modal_run.h), into the summary the
// nonlinear run would give; false, with the reason in the run's note, where it is not done.
bool RunModal(const Design& d, const DynamicModel& model, const StaticModel& statics, LoadRun& run,
              const StationResponses& stations, const StaticState& standing,
              SimulationSummary& summary) {
  const ModalRunResult r =
      RunModalMovingLoad(model, statics, standing, stations, ModalRunOptionsOf(d));
  if (!r.done) {
    run.record.note = "modal run not done (" + r.note + "): the nonlinear run instead";
    return false;
  }
  summary.peak_bar_compression = r.peak_bar_compression;
  summary.peak_string_tension = r.peak_string_tension;
  summary.min_string_strain = r.min_string_strain;
  summary.peak_reactions = r.peak_reactions;
  DynamicRun& record = run.record;
  record.done = true;
  record.dt = r.sample_dt_s;
  record.duration = stations.crossing.DurationS();
  record.steps = r.samples;
  std::ostringstream os;
  os << "modal (" << r.modes << " modes to " << r.highest_mode_hz << " Hz)";
  record.integrator = os.str();
  record.peak_deck_displacement = r.peak_deck_displacement_m;
  return true;
}

// Whether a run is left to do: a modal one, or one within the budget at its asked step (a run
// over it is noted as skipped).
bool AnyRunToDo(std::vector<LoadRun>& runs, const LoadsConfig& l, double members,
                double max_member_steps) {
  bool any = false;
  for (LoadRun& run : runs) {
    any = Modal(run, l) ||
          WithinBudget(members, max_member_steps, " (the asked step; a stable one is no longer)",
                       run) ||
          any;
  }
  return any;
}

// The static solves take the strings as the run has them (a prestrain changes them).
StaticModel StaticModelOfRun(const Design& d, const DynamicModel& model) {
  StaticModel statics = StaticModelOf(d);
  for (size_t k = 0; k < d.strings.size(); ++k) {
    statics.string_rest_length[k] = model.strings.rest_length[k];
    statics.string_stiffness[k] = model.strings.stiffness[k];
  }
  return statics;
}

// Member j's (`m`'s) finding under a run's `demand`: a bar against its yield and buckling, a
// string against its yield and, where it must stay taut, going slack (listed in
// out.slack_strings).
void RaiseDynamicFinding(const Design& d, int j, const MemberSizing& m, double demand,
                         const SimulationSummary& summary, const std::string& label,
                         const BarRule& rule, double E, const MemberMaterial& strings,
                         double sigma_w, DynamicCheck& out) {
  const int nb = d.topology.structure.num_bars();
  const bool bar = j < nb;
  MemberFinding& f = out.members[j];
  if (bar) {
    const BarCapacity cap = BarResistance(m.area, m.length, rule, E);
    RaiseFinding(f, demand, std::min(cap.yield, cap.buckling), label, LimitMode::kDynamic);
  } else {
    if (m.area > 0) RaiseFinding(f, demand, m.area * sigma_w, label, LimitMode::kDynamic);
    const double strain = summary.min_string_strain[j - nb];
    if (strain < 0 && MustStayTaut(d, j - nb)) {
      RaiseSlackFinding(f, strain, sigma_w, strings.youngs_modulus, label);
      if (std::find(out.slack_strings.begin(), out.slack_strings.end(), j - nb) ==
          out.slack_strings.end()) {
        out.slack_strings.push_back(j - nb);
      }
    }
  }
}

// The member's group: its static and dynamic peaks and the largest member's amplification.
void TakeGroupPeak(std::map<MemberGroup, GroupAmplification>& groups, MemberGroup group,
                   const Eigen::VectorXd& static_peak, int j, double peak) {
  GroupAmplification& g = groups[group];
  g.group = group;
  g.static_peak = std::max(g.static_peak, static_peak[j]);
  g.dynamic_peak = std::max(g.dynamic_peak, peak);
  if (static_peak[j] > 0) g.amplification = std::max(g.amplification, peak / static_peak[j]);
}

// A bridge that has no static equilibrium under the runs' standing loads (strings slack, a
// mechanism) has no run to start from: each run says so and the check is not complete, which
// the verdict reads as INCOMPLETE, where the exception stopped the whole design with no file
// written (the 30 m footbridge at n = 5 fixed at 10 deg, its abutments over their capacity).
// Returns the runs' model, or none where it cannot be built: then every run's record, saying why,
// is in out.runs.
std::optional<DynamicModel> BuildRunModel(const Design& d,
                                          const std::vector<StringPrestrain>& prestrain,
                                          std::vector<LoadRun>& runs, DynamicCheck& out) {
  std::optional<DynamicModel> built;
  try {
    built = BuildDynamicModel(d, DynamicCheckModelOptions(d, prestrain));
  } catch (const ModelError& e) {
    for (LoadRun& run : runs) {
      run.record.note =
          std::string("not done: ") + e.what() +
          " (under the run's standing loads; stiffen the bridge or raise its prestress)";
      out.runs.push_back(std::move(run.record));
    }
    return std::nullopt;
  }
  return built;
}

// The run's peak reactions at the first two abutments, from its summary.
void TakePeakReactions(const SimulationSummary& summary, LoadRun& run) {
  for (size_t a = 0; a < summary.peak_reactions.size() && a < 2; ++a) {
    run.record.peak_horizontal_reaction[a] = summary.peak_reactions[a].horizontal;
    run.record.peak_vertical_reaction[a] = summary.peak_reactions[a].vertical;
  }
}

}  // namespace

ModelOptions DynamicCheckModelOptions(const Design& d,
                                      const std::vector<StringPrestrain>& prestrain) {
  // The model a run of this design gets (tbridge simulate with the defaults): the design
  // loads, permanent and payload, with the deck's inertia (not with the paper's switches).
  ModelOptions options;
  options.gravity_on_structure = d.config.design.self_weight;
  options.deck_inertia = !KeepsPaperSwitches(d.config);
  options.prestrain = prestrain;
  return options;
}

DynamicCheck DynamicCheckNotRun(const Design& d, const std::string& why) {
  DynamicCheck out;
  out.members.resize(d.bars.size() + d.strings.size());
  for (LoadRun& run : LoadRuns(d, KeepsPaperSwitches(d.config))) {
    run.record.note = why;
    out.runs.push_back(std::move(run.record));
  }
  return out;
}

DynamicCheck CheckDynamics(const Design& d, std::optional<double> max_steps,
                           ProgressReporter* progress,
                           const std::vector<StringPrestrain>& prestrain) {
  const double max_member_steps = max_steps ? *max_steps : d.config.loads.dynamic_max_member_steps;
  DynamicCheck out;
  out.done = true;
  const Structure& s = d.topology.structure;
  const int nb = s.num_bars();
  out.members.resize(nb + s.num_strings());
  const bool paper = KeepsPaperSwitches(d.config);
  std::vector<LoadRun> runs = LoadRuns(d, paper);
  if (runs.empty()) return out;
  const LoadsConfig& l = d.config.loads;
  // A run over the budget at its asked step is over it at any stable one (no longer): it is
  // skipped before anything is built for it, and with no run left nothing is.
  const double members = static_cast<double>(d.bars.size() + d.strings.size());
  if (!AnyRunToDo(runs, l, members, max_member_steps)) {
    for (LoadRun& run : runs) out.runs.push_back(std::move(run.record));
    return out;
  }
  const std::optional<DynamicModel> built = BuildRunModel(d, prestrain, runs, out);
  if (!built) return out;
  const DynamicModel& model = *built;

  const double gamma_g_sup = paper ? 1.0 : l.gamma_g_sup, gamma_g_inf = paper ? 1.0 : l.gamma_g_inf;
  const BarRule rule = BarRuleOf(d.config);
  const double E = BarMaterial(d.config).youngs_modulus;
  const MemberMaterial strings = StringMaterial(d.config);
  const double sigma_w = strings.DesignStress();
  // The prestress is not factored (EN 1990 6.4.3.2 takes gamma_P = 1 for prestress that
  // favours and disfavours alike); the permanent load's share of the reference force is.
  const Eigen::VectorXd prestress = PrestressForces(d);
  StaticModel statics = StaticModelOfRun(d, model);
  // The nonlinear runs share the model, the engine and its stabilisation: one stability limit
  // serves all, found when the first of them needs it.
  double stable_dt = 0;
  for (LoadRun& run : runs) {
    SimulationSummary summary;
    // The run's static counterparts (a travelling load's stations), solved once, when the modal
    // run or the amplification first needs them.
    std::optional<StationResponses> stations;
    StaticState standing;
    bool converged = false;
    const auto solve_stations = [&]() {
      if (stations || run.station_force == 0) return;
      stations = MovingLoadStations(d, model, statics, run.station_force, run.crossing, standing,
                                    converged);
    };
    bool done = false;
    const bool modal = Modal(run, l);
    if (modal) {
      solve_stations();
      if (converged) {
        done = RunModal(d, model, statics, run, *stations, standing, summary);
      } else {
        run.record.note =
            "modal run not done (a static solve at a station did not converge): the nonlinear run "
            "instead";
      }
    }
    // A nonlinear run skipped before (over the budget at its asked step) has its note.
    if (!done &&
        (modal ? WithinBudget(members, max_member_steps, "", run) : run.record.note.empty())) {
      if (stable_dt == 0) stable_dt = Rk4StableStep(model, run.scenario);
      done = Run(model, stable_dt, members, max_member_steps, run, summary, progress);
    }
    if (done) {
      TakePeakReactions(summary, run);
      const std::string label = "dynamic: " + run.record.name;
      solve_stations();
      const Eigen::VectorXd static_peak =
          StaticPeaks(d, model, statics, stations ? &*stations : nullptr);
      std::map<MemberGroup, GroupAmplification> groups;
      for (int j = 0; j < nb + s.num_strings(); ++j) {
        const bool bar = j < nb;
        const MemberSizing& m = d.MemberAt(j);
        const MemberGroup group = s.MemberAt(j).group;
        const double peak =
            bar ? summary.peak_bar_compression[j] : summary.peak_string_tension[j - nb];
        // The prestress as it is, gamma_G on the permanent load's share of the reference
        // force (sup where it adds to the force, inf where it relieves it), gamma on what the
        // standing payload and the run add.
        const double permanent = m.reference_force - prestress[j];
        const double demand = prestress[j] +
                              (permanent > 0 ? gamma_g_sup : gamma_g_inf) * permanent +
                              run.gamma * std::max(peak - m.reference_force, 0.0);
        RaiseDynamicFinding(d, j, m, demand, summary, label, rule, E, strings, sigma_w, out);
        TakeGroupPeak(groups, group, static_peak, j, peak);
      }
      for (auto& [name, g] : groups) run.record.groups.push_back(g);
    }
    out.runs.push_back(std::move(run.record));
  }
  return out;
}

}  // namespace tbridge
