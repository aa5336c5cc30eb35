// The dynamic check's moving load (Q_t crossing the deck, deck inertia on) integrated by each
// method against RK4 at the check's stable step, on the default bridge's first design at each n.
//
//   build/bench/bench_moving_load [n_min=3] [n_max=6] [config=configs/default.json] [stabilised=1] [reference]
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
#include <string>

#include "bridge/design_model.h"
#include "core/config.h"
#include "design/design.h"
#include "design/sizing.h"
#include "dynamics/integrator_policy.h"
#include "dynamics/model.h"
#include "dynamics/simulation.h"
#include "verify/load_scenarios.h"

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
    if (r > 0) worst = std::max(worst, std::abs(a.peak_bar_compression[j] - ref.peak_bar_compression[j]) / r);
  }
  for (size_t j = 0; j < d.strings.size(); ++j) {
    const double r = d.strings[j].area * sigma_w;
    if (r > 0) worst = std::max(worst, std::abs(a.peak_string_tension[j] - ref.peak_string_tension[j]) / r);
  }
  return worst;
}

}  // namespace

int main(int argc, char** argv) {
  const int n_min = argc > 1 ? std::atoi(argv[1]) : 3;
  const int n_max = argc > 2 ? std::atoi(argv[2]) : 6;
  const std::string path = argc > 3 ? argv[3] : std::string(TBRIDGE_SOURCE_DIR) + "/configs/default.json";
  const bool stabilised = argc > 4 ? std::atoi(argv[4]) != 0 : true;
  const bool reference_only = argc > 5 && std::string(argv[5]) == "reference";
  std::printf("n,method,dt_s,steps,seconds,force_error_of_resistance,deck_peak_error,deck_peak_m\n");
  for (int n = n_min; n <= n_max; ++n) {
    Config config = LoadConfig(path);
    config.bridge.n = n;
    const Design d = RunDesign(config);
    ModelOptions options;
    options.gravity_on_structure = config.design.self_weight;
    options.deck_inertia = true;
    const DynamicModel model = BuildDynamicModel(d, options);
    const LoadsConfig& l = config.loads;
    DynamicsConfig scene = MovingLoadScenario(d, l.travelling_load_n, l.travelling_speed_m_s, l.dynamic_dt_s);
    // Stabilised bar lengths: over a crossing of 8 s or more, RK4's drift of the bar lengths
    // passes the guard's 1e-3 from n = 6.
    scene.stabilisation.enabled = stabilised;
    const double stable = Rk4StableStep(model, scene);
    DynamicsConfig ref_scene = scene;
    if (ref_scene.dt > stable) ref_scene.dt /= std::ceil(ref_scene.dt / stable);
    const Run ref = Time(model, ref_scene);
    const auto line = [&](const char* method, const DynamicsConfig& sc, const Run& r) {
      std::printf("%d,%s,%.4g,%ld,%.4g,%.3e,%.3e,%.6g\n", n, method, sc.dt, static_cast<long>(r.s.steps), r.seconds,
                  ForceError(d, r.s, ref.s),
                  std::abs(r.s.peak_deck_displacement[1] - ref.s.peak_deck_displacement[1]) /
                      ref.s.peak_deck_displacement[1],
                  r.s.peak_deck_displacement[1]);
      std::fflush(stdout);
    };
    line("rk4_reference", ref_scene, ref);
    for (const double dt : {4e-3, 2e-3, 1e-3, 5e-4}) {
      if (reference_only) break;
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
