// The dynamic check's moving load (Q_t crossing the deck, deck inertia on) by each method
// against RK4 at the check's stable step, on the default bridge's first design at each n (or
// on design files): SDIRK3 at four steps, and the modal run (checks/modal_run.h) at five
// cutoffs, done whatever the bridge's nonlinearity (which its line names) so that its error
// can be read against it.
//
//   build/bench/bench_moving_load [n_min=3] [n_max=6] [config=configs/default.json] [stabilised=1]
//   [all|modal|reference] [cutoffs_hz=25,50,100,200,400]
//
// `config` may instead be a pattern of design files with %d for n (e.g. out/default_n%d.json,
// written by `tbridge design`): the runs are then of those designs (the verified ones).
//
// Per method and step: run time, the largest error of a member's peak force as a fraction of
// its resistance (bars: min(yield, buckling); strings: sigma_w A) and the error of the peak
// deck displacement relative to itself. The reference is RK4 at the step the check takes
// (loads.dynamic_dt_s divided into 0.9 of RK4's stability limit).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "bridge/design_model.h"
#include "checks/load_scenarios.h"
#include "checks/modal_run.h"
#include "core/config.h"
#include "design/design.h"
#include "design/sizing.h"
#include "design/static_model.h"
#include "dynamics/integrator_policy.h"
#include "dynamics/model.h"
#include "dynamics/simulation.h"
#include "io/design_reader.h"

namespace {

using namespace tbridge;
using Clock = std::chrono::steady_clock;

struct Run {
  SimulationSummary s;
  double seconds = 0;
};

Run Time(const DynamicModel& model, const DynamicsConfig& scene) {
  const auto start = Clock::now();
  Run r;
  r.s = Simulate(model, scene).summary;
  r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return r;
}

// Largest |peak - reference peak| / resistance over members.
double ForceError(const Design& d, const SimulationSummary& a, const SimulationSummary& ref) {
  const BarRule rule = BarRuleOf(d.config);
  const double E = BarMaterial(d.config).youngs_modulus;
  const double sigma_w = StringMaterial(d.config).DesignStress();
  double worst = 0;
  for (size_t j = 0; j < d.bars.size(); ++j) {
    const BarCapacity cap = BarResistance(d.bars[j].area, d.bars[j].length, rule, E);
    const double r = std::min(cap.yield, cap.buckling);
    if (r > 0)
      worst =
          std::max(worst, std::abs(a.peak_bar_compression[j] - ref.peak_bar_compression[j]) / r);
  }
  for (size_t j = 0; j < d.strings.size(); ++j) {
    const double r = d.strings[j].area * sigma_w;
    if (r > 0)
      worst = std::max(worst, std::abs(a.peak_string_tension[j] - ref.peak_string_tension[j]) / r);
  }
  return worst;
}

}  // namespace

int main(int argc, char** argv) {
  const int n_min = argc > 1 ? std::atoi(argv[1]) : 3;
  const int n_max = argc > 2 ? std::atoi(argv[2]) : 6;
  const std::string path =
      argc > 3 ? argv[3] : std::string(TBRIDGE_SOURCE_DIR) + "/configs/default.json";
  const bool stabilised = argc > 4 ? std::atoi(argv[4]) != 0 : true;
  // "reference": RK4 alone; "modal": RK4 and the modal runs; "all" (or none): SDIRK3 as well.
  const std::string methods = argc > 5 ? argv[5] : "all";
  const bool reference_only = methods == "reference";
  const bool no_sdirk = reference_only || methods == "modal";
  // The modal run's cutoffs [Hz]: argv[6] as a comma-separated list, or five from 25 to 400 Hz.
  std::vector<double> cutoffs = {25.0, 50.0, 100.0, 200.0, 400.0};
  if (argc > 6) {
    cutoffs.clear();
    std::stringstream list(argv[6]);
    for (std::string item; std::getline(list, item, ',');) cutoffs.push_back(std::stod(item));
  }
  std::printf(
      "n,method,dt_s,steps,seconds,force_error_of_resistance,deck_peak_error,deck_peak_m\n");
  for (int n = n_min; n <= n_max; ++n) {
    Design d;
    if (path.find("%d") != std::string::npos) {
      char file[4096];
      std::snprintf(file, sizeof file, path.c_str(), n);
      std::ifstream in(file);
      d = ReadDesign(nlohmann::json::parse(in));
    } else {
      Config config = LoadConfig(path);
      config.bridge.n = n;
      d = RunDesign(config);
    }
    const Config& config = d.config;
    ModelOptions options;
    options.gravity_on_structure = config.design.self_weight;
    options.deck_inertia = true;
    const DynamicModel model = BuildDynamicModel(d, options);
    const LoadsConfig& l = config.loads;
    DynamicsConfig scene =
        MovingLoadScenario(d, l.travelling_load_n, TravellingCrossing(d), l.dynamic_dt_s);
    // Stabilised bar lengths: over a crossing of 8 s or more, RK4's drift of the bar lengths
    // passes the guard's 1e-3 from n = 6.
    scene.stabilisation.enabled = stabilised;
    const double stable = Rk4StableStep(model, scene);
    DynamicsConfig ref_scene = scene;
    if (ref_scene.dt > stable) ref_scene.dt /= std::ceil(ref_scene.dt / stable);
    const Run ref = Time(model, ref_scene);
    const auto line = [&](const char* method, const DynamicsConfig& sc, const Run& r) {
      std::printf("%d,%s,%.4g,%ld,%.4g,%.3e,%.3e,%.6g\n", n, method, sc.dt,
                  static_cast<long>(r.s.steps), r.seconds, ForceError(d, r.s, ref.s),
                  std::abs(r.s.peak_deck_displacement[1] - ref.s.peak_deck_displacement[1]) /
                      ref.s.peak_deck_displacement[1],
                  r.s.peak_deck_displacement[1]);
      std::fflush(stdout);
    };
    line("rk4_reference", ref_scene, ref);
    // The modal run (checks/modal_run.h) at each cutoff, its station solves timed apart: the
    // check does them for its static counterparts whichever way the run goes.
    const StaticModel statics = StaticModelOf(d);
    StaticState standing;
    bool converged = false;
    const auto stations_start = Clock::now();
    const StationResponses stations = MovingLoadStations(
        d, model, statics, l.travelling_load_n, TravellingCrossing(d), standing, converged);
    const double stations_s = std::chrono::duration<double>(Clock::now() - stations_start).count();
    std::printf("%d,station_solves,,%zu,%.4g,,,\n", n, stations.forces.size(), stations_s);
    for (const double cutoff : cutoffs) {
      if (reference_only) break;
      const auto start = Clock::now();
      ModalRunOptions modal = ModalRunOptionsOf(d);
      modal.cutoff_hz = cutoff;
      modal.max_nonlinearity = 1.0;  // done whatever it is: the error is what is measured
      const ModalRunResult m = RunModalMovingLoad(model, statics, standing, stations, modal);
      Run r;
      r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
      if (!m.done) {
        std::printf("%d,modal_%g_hz,,not done: %s\n", n, cutoff, m.note.c_str());
        continue;
      }
      r.s.steps = m.samples;
      r.s.peak_bar_compression = m.peak_bar_compression;
      r.s.peak_string_tension = m.peak_string_tension;
      r.s.peak_deck_displacement[1] = m.peak_deck_displacement_m;
      DynamicsConfig sc = scene;
      sc.dt = m.sample_dt_s;
      char name[64];
      std::snprintf(name, sizeof name, "modal_%d_modes_to_%.0f_hz_nonlinearity_%.3g", m.modes,
                    m.highest_mode_hz, m.nonlinearity);
      line(name, sc, r);
    }
    for (const double dt : {4e-3, 2e-3, 1e-3, 5e-4}) {
      if (no_sdirk) break;
      DynamicsConfig sc = scene;
      sc.dt = dt;
      sc.integrator = IntegratorKind::kSdirk3;
      try {
        line("sdirk3", sc, Time(model, sc));
      } catch (const std::exception& e) {
        std::printf("%d,sdirk3,%.4g,failed: %s\n", n, dt, e.what());
      }
    }
  }
  return 0;
}
