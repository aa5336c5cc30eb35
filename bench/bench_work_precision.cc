// Run time against error for the class-1 bridges: RK4 at a ladder of dt, DOPRI5 at a ladder of
// tolerances, SDIRK3 (implicit) at a ladder of dt.
//
//   build/bench/bench_work_precision [min_n] [max_n] > wp.csv
//   python3 tools/plot_work_precision.py wp.csv docs/work_precision.png > table.md
//
// Scenes: the designed bridge of the paper (p = 1) with its longest bar pushed down by
// delta = 1e-4 m ("small", every n) and by the paper's delta = 0.1 m ("table5", n <= 3).
// Outputs over 0.5 s, sampled every 1e-3 s:
//  (a) the deck-node vertical displacement history, error = max over samples and deck nodes
//      of |u - u_ref|, divided by max |u_ref|;
//  (b) the period of the summed deck displacement (dominant spectral peak, as SPEC.md §9
//      measures Table 5), error relative to the reference period.
// The reference is RK4 at the largest step 1e-3 / 2^k below a quarter of its stability limit
// 2 sqrt(2)/omega_max (and at most 1e-3 / 2^9); its own error is printed as ref_floor (the
// same with a twice larger step). Rungs predicted to take more than a minute are skipped;
// where stiffness sets DOPRI5's step, only every third tolerance is run (they cost the same). Each line of the output is
//   n,scene,method,parameter,wall_s,evaluations,disp_error,period_error,status
// with '#' lines carrying omega_max, the RK4 limit and the reference per scene.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>

#include "core/config.h"
#include "design/design.h"
#include "dynamics/class1.h"
#include "dynamics/coupling.h"
#include "dynamics/integrators.h"
#include "dynamics/model.h"
#include "dynamics/response.h"
#include "dynamics/sdirk.h"
#include "dynamics/simulation.h"
#include "dynamics/step_size.h"

namespace {

using namespace tbridge;

constexpr double kDuration = 0.5;  // [s]
constexpr double kSample = 1e-3;   // [s]
constexpr double kRunaway = 1.0;   // a deck node 1 m off: the run has blown up [m]
constexpr double kBudget = 60.0;   // skip rungs predicted to take longer than this [s]

struct Run {
  bool ok = false;
  std::string note;
  double wall = 0;
  long evaluations = 0;
  Eigen::MatrixXd deck;  // samples x deck nodes [m]
};

class Scene {
 public:
  Scene(const DynamicModel& model, double delta) : model_(model), system_(model), ode_(system_) {
    DynamicsConfig c;
    c.perturbation = {1, delta};
    y0_ = InitialState(model, c);
  }

  const DynamicModel& model() const { return model_; }
  const Class1System& system() const { return system_; }
  Class1Ode& ode() { return ode_; }
  const Eigen::VectorXd& y0() const { return y0_; }

  // Deck vertical displacement of state y into row `row` of `deck`.
  void Take(const Eigen::VectorXd& y, Eigen::MatrixXd& deck, Eigen::Index row) const {
    for (size_t k = 0; k < model_.deck_nodes.size(); ++k) {
      const int a = model_.deck_nodes[k];
      deck(row, static_cast<Eigen::Index>(k)) = y(a * model_.dim + 1) - model_.positions(1, a);
    }
  }

  // A fixed-step run with `step(t, dt, y)`; dt must divide kSample.
  Run FixedStep(double dt, const std::function<void(double, double, Eigen::VectorXd&)>& step, long evals_per_step) {
    Run r;
    const long per_sample = std::lround(kSample / dt);
    const long samples = std::lround(kDuration / kSample);
    r.deck.resize(samples + 1, static_cast<Eigen::Index>(model_.deck_nodes.size()));
    Eigen::VectorXd y = y0_;
    Take(y, r.deck, 0);
    const auto start = std::chrono::steady_clock::now();
    try {
      for (long s = 1; s <= samples; ++s) {
        for (long k = 0; k < per_sample; ++k) step(((s - 1) * per_sample + k) * dt, dt, y);
        Take(y, r.deck, s);
        if (!r.deck.row(s).allFinite() || r.deck.row(s).cwiseAbs().maxCoeff() > kRunaway) {
          r.note = "unstable";
          return r;
        }
      }
    } catch (const std::exception& e) {
      r.note = std::string("failed: ") + e.what();
      return r;
    }
    r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.evaluations = evals_per_step * per_sample * samples;
    r.ok = true;
    return r;
  }

  Run Rk4(double dt) {
    Rk4Workspace ws(system_.state_size());
    return FixedStep(dt, [&](double t, double h, Eigen::VectorXd& y) { Rk4Step(ode_, t, h, y, ws); }, 4);
  }

  Run Sdirk(double dt, long* evaluations) {
    Sdirk3 sdirk(CouplingOf(model_), system_.state_size());
    Run r = FixedStep(dt, [&](double t, double h, Eigen::VectorXd& y) { sdirk.Step(ode_, t, h, y); }, 0);
    r.evaluations = sdirk.stats().evaluations;
    if (evaluations != nullptr) *evaluations = sdirk.stats().jacobians;
    return r;
  }

  Run Dopri(double rtol) {
    Run r;
    Dopri5Options o;
    o.rtol = rtol;
    o.atol = rtol * 1e-3;  // positions ~10 m, displacements ~1e-4..1e-1 m
    Dopri5 dp(o);
    Dopri5Workspace ws(system_.state_size());
    const long samples = std::lround(kDuration / kSample);
    r.deck.resize(samples + 1, static_cast<Eigen::Index>(model_.deck_nodes.size()));
    Eigen::VectorXd y = y0_, out(y0_.size());
    Take(y, r.deck, 0);
    double t = 0, h = 1e-6;
    long next = 1;
    const auto start = std::chrono::steady_clock::now();
    try {
      dp.Start(ode_, t, y, ws);
      while (t < kDuration) {
        dp.Step(ode_, t, y, h, kDuration, ws);
        for (; next <= samples && next * kSample <= t * (1 + 1e-12); ++next) {
          dp.Interpolate(next * kSample, ws, out);
          Take(out, r.deck, next);
        }
      }
    } catch (const std::exception& e) {
      r.note = std::string("failed: ") + e.what();
      return r;
    }
    r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.evaluations = dp.evaluations();
    r.ok = next > samples;
    if (!r.ok) r.note = "short";
    return r;
  }

 private:
  const DynamicModel& model_;
  Class1System system_;
  Class1Ode ode_;
  Eigen::VectorXd y0_;
};

double Period(const Eigen::MatrixXd& deck) {
  try {
    return DeckFrequency(deck, kSample, kDuration).period_s;
  } catch (const std::exception&) {
    return std::nan("");
  }
}

void Report(int n, const char* scene, const char* method, double parameter, const Run& r,
            const Eigen::MatrixXd& reference, double ref_period) {
  if (!r.ok) {
    std::printf("%d,%s,%s,%g,,,,,%s\n", n, scene, method, parameter, r.note.substr(0, 120).c_str());
  } else {
    const double scale = reference.cwiseAbs().maxCoeff();
    const double disp = (r.deck - reference).cwiseAbs().maxCoeff() / scale;
    const double period = std::abs(Period(r.deck) - ref_period) / ref_period;
    std::printf("%d,%s,%s,%g,%.6g,%ld,%.3e,%.3e,ok\n", n, scene, method, parameter, r.wall, r.evaluations, disp,
                period);
  }
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const int min_n = argc > 1 ? std::atoi(argv[1]) : 1;
  const int max_n = argc > 2 ? std::atoi(argv[2]) : 10;
  std::printf("n,scene,method,parameter,wall_s,evaluations,disp_error,period_error,status\n");
  for (int n = min_n; n <= max_n; ++n) {
    Config config;
    config.bridge.n = n;
    const Design design = RunDesign(config);
    const DynamicModel model = BuildDynamicModel(design);
    for (const double delta : {1e-4, 0.1}) {
      if (delta > 0.01 && n > 3) continue;
      const char* scene = delta > 0.01 ? "table5" : "small";
      Scene s(model, delta);
      const FrequencyBound bound = HighestFrequency(s.ode(), s.y0());
      const double limit = Rk4StepLimit(bound.omega_max);
      // Reference: RK4 at 1e-3/2^k <= limit/20, at most 1e-3/2^9; its floor from 2x that step.
      double ref_dt = kSample;
      while (ref_dt > limit / 4 || ref_dt > kSample / 512) ref_dt /= 2;
      const Run ref = s.Rk4(ref_dt);
      const Run ref2 = s.Rk4(2 * ref_dt);
      if (!ref.ok || !ref2.ok) {
        std::printf("# n=%d %s: reference failed (%s)\n", n, scene, ref.note.c_str());
        continue;
      }
      const double ref_period = Period(ref.deck);
      const double ns_per_eval = 1e9 * ref.wall / static_cast<double>(ref.evaluations);
      std::printf("# n=%d scene=%s nodes=%d members=%zu omega_max=%.6g rk4_limit=%.4g ref_dt=%.4g ref_wall=%.3g "
                  "ref_period=%.6g ref_floor_disp=%.3e ref_floor_period=%.3e peak_disp=%.4g\n",
                  n, scene, model.num_nodes(), model.bars.size() + model.strings.size(), bound.omega_max, limit,
                  ref_dt, ref.wall, ref_period,
                  (ref2.deck - ref.deck).cwiseAbs().maxCoeff() / ref.deck.cwiseAbs().maxCoeff(),
                  std::abs(Period(ref2.deck) - ref_period) / ref_period, ref.deck.cwiseAbs().maxCoeff());
      std::fflush(stdout);
      // RK4: from 1e-3 down to ref_dt x 4, beyond the limit included (they show the blow-up).
      for (double dt = kSample; dt >= 4 * ref_dt; dt /= 2) {
        if (dt > 4 * limit) continue;  // certain blow-up, nothing to learn
        if (4.0 * (kDuration / dt) * ns_per_eval * 1e-9 > kBudget) break;
        Report(n, scene, "rk4", dt, s.Rk4(dt), ref.deck, ref_period);
      }
      // DOPRI5: rtol 1e-3 .. 1e-10, skipping what the stiffness makes too slow.
      const double dopri_predicted = 6.0 * (kDuration / (1.1 * limit)) * ns_per_eval * 1e-9;
      for (double rtol = 1e-3; rtol >= 1e-10; rtol /= 10) {
        if (dopri_predicted > kBudget) break;
        if (dopri_predicted > 5 && std::lround(std::log10(rtol)) % 3 != 0) continue;
        Report(n, scene, "dopri5", rtol, s.Dopri(rtol), ref.deck, ref_period);
      }
      // SDIRK3: 1e-3 down to a quarter of the RK4 limit (smaller steps cannot beat RK4).
      double wall_per_step = 0;
      for (double dt = kSample; dt >= std::max(limit / 4, 4 * ref_dt); dt /= 2) {
        if (wall_per_step * (kDuration / dt) > kBudget) break;
        long jacobians = 0;
        const Run r = s.Sdirk(dt, &jacobians);
        Report(n, scene, "sdirk3", dt, r, ref.deck, ref_period);
        if (r.ok) wall_per_step = r.wall / (kDuration / dt);
      }
    }
  }
  return 0;
}
