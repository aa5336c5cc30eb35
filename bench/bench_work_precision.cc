// Run time against error for the paper's bridges: RK4 at a ladder of dt, DOPRI5 at a ladder of
// tolerances, SDIRK3 (implicit) at a ladder of dt.
//
//   build/bench/bench_work_precision [min_n] [max_n] [3d_config|-] > wp.csv
//   python3 tools/plot_work_precision.py wp.csv docs/work_precision.png > table.md
//
// Scenes: the designed planar bridge (p = 1) with its longest bars pushed down by
// delta = 1e-4 m ("small", n = min_n..max_n) and by the paper's delta = 0.1 m ("table5",
// n <= 3); then the 3D bridge of the given config (default configs/paper_3d.json, relative to
// the working directory; "-" leaves it out), pushed by 1e-4 m ("3d"). The 3D bridge is
// class 2 (every bar node meets a plane bar and a rung), so it runs on the class-k engine;
// the planar ones on the class-1 closed form. Outputs over 0.5 s, sampled every 1e-3 s:
//  (a) the deck-node vertical (y) displacement history, error = max over samples and deck
//      nodes of |u - u_ref|, divided by max |u_ref|;
//  (b) the period of the summed deck displacement (dominant spectral peak, as SPEC.md §9
//      measures Table 5), error relative to the reference period.
//
// The reference. First a sensitivity probe: RK4 at the largest ladder step 1e-3 / 2^k below
// the linear stability limit 2 sqrt(2)/omega_max, run twice, the second time with the push
// larger by 1e-10 relative (1e-14 m on the small scenes). "sensitivity" is their difference
// as in (a). Where it exceeds kChaotic, the motion is chaotic on this horizon (a rounding-
// sized change grows to a visible one) and no step, however small, gives a history that
// converges over 0.5 s. The reference is RK4 at the largest ladder step at most 1e-3 / 2^9
// and at most a sixteenth of the limit, or, on a chaotic scene, at most half the probe's
// step (a smaller one costs more and converges no better). "ref_floor" is its difference
// from RK4 at twice its step (an upper bound of its own error for a method of order >= 1).
//
// Rungs predicted to take more than kBudget (kBudgetLargest for the n = 10 bridge, the only
// one where no rung but RK4's fits a minute) are skipped. The predictions: RK4 from the
// reference's cost per evaluation; SDIRK3 from its last completed rung; DOPRI5 from its last
// rung, the first from a step set by the stiffness alone (1.1 x the RK4 limit), which the
// slack chatter of n >= 9 makes several times too low. DOPRI5 stops once its error is within
// twice the reference floor (tighter rungs would measure the reference); where stiffness
// sets its step only every third tolerance is run (they cost the same). Each line of the
// output is
//   n,scene,method,parameter,wall_s,evaluations,disp_error,period_error,status
// status "ok", "unstable" (a deck node left by more than 1 m or not finite) or "failed: ..."
// (the integrator's own message, commas replaced); wall_s is given for every run, the
// errors only for "ok". '#' lines carry omega_max, the RK4 limit and the reference per scene.

#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "bridge/design_model.h"
#include "core/config.h"
#include "design/design.h"
#include "dynamics/class1.h"
#include "dynamics/classk.h"
#include "dynamics/coupling.h"
#include "dynamics/integrators.h"
#include "dynamics/model.h"
#include "dynamics/response.h"
#include "dynamics/sdirk.h"
#include "dynamics/simulation.h"
#include "dynamics/step_size.h"

namespace {

using namespace tbridge;

constexpr double kDuration = 0.5;         // [s]
constexpr double kSample = 1e-3;          // [s]
constexpr double kRunaway = 1.0;          // a deck node 1 m off: the run has blown up [m]
constexpr double kBudget = 60.0;          // skip rungs predicted to take longer than this [s]
constexpr double kBudgetLargest = 150.0;  // the same for n = 10 [s]
constexpr double kNudge = 1e-10;          // relative change of the push for the sensitivity probe
constexpr double kChaotic = 1e-3;         // sensitivity above this: the history does not converge

struct Run {
  bool ok = false;
  std::string note;
  double wall = 0;
  long evaluations = 0;
  Eigen::MatrixXd deck;  // samples x deck nodes [m]
};

class Scene {
 public:
  // Class 1 on the closed form, anything else on the class-k engine: the same OdeSystem.
  Scene(const DynamicModel& model, double delta) : model_(model) {
    if (model.tensegrity_class <= 1) {
      class1_ = std::make_unique<Class1System>(model);
      ode_ = std::make_unique<Class1Ode>(*class1_);
    } else {
      classk_ = std::make_unique<ClassKSystem>(model);
      ode_ = std::make_unique<ClassKOde>(*classk_);
    }
    DynamicsConfig c;
    c.perturbation = {1, delta};
    y0_ = InitialState(model, c);
    c.perturbation = {1, delta * (1 + kNudge)};
    nudged_ = InitialState(model, c);
  }

  const char* engine() const { return class1_ ? "class1" : "classk"; }
  OdeSystem& ode() { return *ode_; }
  const Eigen::VectorXd& y0() const { return y0_; }
  const Eigen::VectorXd& nudged() const { return nudged_; }

  // Deck vertical displacement of state y into row `row` of `deck`.
  void Take(const Eigen::VectorXd& y, Eigen::MatrixXd& deck, Eigen::Index row) const {
    for (size_t k = 0; k < model_.deck_nodes.size(); ++k) {
      const int a = model_.deck_nodes[k];
      deck(row, static_cast<Eigen::Index>(k)) = y(a * model_.dim + 1) - model_.positions(1, a);
    }
  }

  // A fixed-step run from `start` with `step(t, dt, y)`; dt must divide kSample.
  Run FixedStep(double dt, const std::function<void(double, double, Eigen::VectorXd&)>& step,
                long evals_per_step, const Eigen::VectorXd& start) {
    Run r;
    const long per_sample = std::lround(kSample / dt);
    const long samples = std::lround(kDuration / kSample);
    r.deck.resize(samples + 1, static_cast<Eigen::Index>(model_.deck_nodes.size()));
    Eigen::VectorXd y = start;
    Take(y, r.deck, 0);
    const auto begin = std::chrono::steady_clock::now();
    auto elapsed = [&] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    };
    try {
      for (long s = 1; s <= samples; ++s) {
        for (long k = 0; k < per_sample; ++k) step(((s - 1) * per_sample + k) * dt, dt, y);
        Take(y, r.deck, s);
        if (!r.deck.row(s).allFinite() || r.deck.row(s).cwiseAbs().maxCoeff() > kRunaway) {
          r.note = "unstable";
          r.wall = elapsed();
          return r;
        }
      }
    } catch (const std::exception& e) {
      r.note = std::string("failed: ") + e.what();
      r.wall = elapsed();
      return r;
    }
    r.wall = elapsed();
    r.evaluations = evals_per_step * per_sample * samples;
    r.ok = true;
    return r;
  }

  Run Rk4(double dt, const Eigen::VectorXd& start) {
    Rk4Workspace ws(ode_->size());
    return FixedStep(
        dt, [&](double t, double h, Eigen::VectorXd& y) { Rk4Step(*ode_, t, h, y, ws); }, 4, start);
  }

  // `wall_per_step`: wall time per accepted step (for the budget).
  Run Sdirk(double dt, double* wall_per_step) {
    Sdirk3 sdirk(CouplingOf(model_), ode_->size());
    Run r = FixedStep(
        dt, [&](double t, double h, Eigen::VectorXd& y) { sdirk.Step(*ode_, t, h, y); }, 0, y0_);
    r.evaluations = sdirk.stats().evaluations;
    *wall_per_step = r.wall / static_cast<double>(std::max(sdirk.stats().steps, 1L));
    return r;
  }

  Run Dopri(double rtol) {
    Run r;
    Dopri5Options o;
    o.rtol = rtol;
    o.atol = rtol * 1e-3;  // positions ~10 m, displacements ~1e-4..1e-1 m
    Dopri5 dp(o);
    Dopri5Workspace ws(ode_->size());
    const long samples = std::lround(kDuration / kSample);
    r.deck.resize(samples + 1, static_cast<Eigen::Index>(model_.deck_nodes.size()));
    Eigen::VectorXd y = y0_, out(y0_.size());
    Take(y, r.deck, 0);
    double t = 0, h = 1e-6;
    long next = 1;
    const auto begin = std::chrono::steady_clock::now();
    try {
      dp.Start(*ode_, t, y, ws);
      while (t < kDuration) {
        dp.Step(*ode_, t, y, h, kDuration, ws);
        for (; next <= samples && next * kSample <= t * (1 + 1e-12); ++next) {
          dp.Interpolate(next * kSample, ws, out);
          Take(out, r.deck, next);
        }
      }
    } catch (const std::exception& e) {
      r.note = std::string("failed: ") + e.what();
    }
    r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    r.evaluations = dp.evaluations();
    r.ok = r.note.empty() && next > samples;
    if (r.note.empty() && !r.ok) r.note = "short";
    return r;
  }

 private:
  const DynamicModel& model_;
  std::unique_ptr<Class1System> class1_;
  std::unique_ptr<ClassKSystem> classk_;
  std::unique_ptr<OdeSystem> ode_;
  Eigen::VectorXd y0_, nudged_;
};

double Period(const Eigen::MatrixXd& deck) {
  try {
    return DeckFrequency(deck, kSample, kDuration).period_s;
  } catch (const std::exception&) {
    return std::nan("");
  }
}

// max |a - b| relative to max |b|.
double DispError(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

struct Errors {
  double disp = NAN, period = NAN;
};

Errors Report(int n, const char* scene, const char* method, double parameter, const Run& r,
              const Eigen::MatrixXd& reference, double ref_period) {
  Errors e;
  if (!r.ok) {
    std::string note = r.note.substr(0, 160);
    std::replace(note.begin(), note.end(), ',', ';');
    std::printf("%d,%s,%s,%g,%.6g,,,,%s\n", n, scene, method, parameter, r.wall, note.c_str());
  } else {
    e.disp = DispError(r.deck, reference);
    e.period = std::abs(Period(r.deck) - ref_period) / ref_period;
    std::printf("%d,%s,%s,%g,%.6g,%ld,%.3e,%.3e,ok\n", n, scene, method, parameter, r.wall,
                r.evaluations, e.disp, e.period);
  }
  std::fflush(stdout);
  return e;
}

void RunScene(int n, const char* scene, const DynamicModel& model, double delta, double budget) {
  Scene s(model, delta);
  const FrequencyBound bound = HighestFrequency(s.ode(), s.y0());
  const double limit = Rk4StepLimit(bound.omega_max);
  std::map<double, Run> rk4;  // by step: runs made for the reference, reported as rungs too
  auto rk4_at = [&](double dt) -> const Run& {
    auto it = rk4.find(dt);
    if (it == rk4.end()) it = rk4.emplace(dt, s.Rk4(dt, s.y0())).first;
    return it->second;
  };
  // Sensitivity probe at the largest ladder step below the limit that runs (nonlinear motion
  // can need a smaller one).
  double probe_dt = kSample;
  while (probe_dt > limit) probe_dt /= 2;
  while (!rk4_at(probe_dt).ok && probe_dt > kSample / 4096) probe_dt /= 2;
  const Run& probe = rk4_at(probe_dt);
  const Run nudged = s.Rk4(probe_dt, s.nudged());
  if (!probe.ok || !nudged.ok) {
    std::printf("# n=%d %s: sensitivity probe failed (%s)\n", n, scene,
                probe.ok ? nudged.note.c_str() : probe.note.c_str());
    return;
  }
  const double sensitivity = DispError(nudged.deck, probe.deck);
  const bool chaotic = sensitivity > kChaotic;
  double ref_dt = kSample;
  while (ref_dt > (chaotic ? probe_dt / 2 : limit / 16) || ref_dt > kSample / 512) ref_dt /= 2;
  const Run& ref = rk4_at(ref_dt);
  const Run& ref2 = rk4_at(2 * ref_dt);
  if (!ref.ok || !ref2.ok) {
    std::printf("# n=%d %s: reference failed (%s)\n", n, scene,
                ref.ok ? ref2.note.c_str() : ref.note.c_str());
    return;
  }
  const double ref_period = Period(ref.deck);
  const double floor_disp = DispError(ref2.deck, ref.deck);
  const double floor_period = std::abs(Period(ref2.deck) - ref_period) / ref_period;
  const double ns_per_eval = 1e9 * ref.wall / static_cast<double>(ref.evaluations);
  std::printf(
      "# n=%d scene=%s engine=%s nodes=%d members=%zu omega_max=%.6g rk4_limit=%.4g probe_dt=%.4g "
      "sensitivity=%.3e chaotic=%d ref_dt=%.4g ref_wall=%.3g ref_period=%.6g ref_floor_disp=%.3e "
      "ref_floor_period=%.3e peak_disp=%.4g\n",
      n, scene, s.engine(), model.num_nodes(), model.bars.size() + model.strings.size(),
      bound.omega_max, limit, probe_dt, sensitivity, chaotic ? 1 : 0, ref_dt, ref.wall, ref_period,
      floor_disp, floor_period, ref.deck.cwiseAbs().maxCoeff());
  std::fflush(stdout);
  // RK4: from 1e-3 down to 4 ref_dt (and the probe's step), beyond the limit included (they
  // show the blow-up).
  for (double dt = kSample; dt >= std::min(4 * ref_dt, probe_dt); dt /= 2) {
    if (dt > 4 * limit) continue;  // certain blow-up, nothing to learn
    if (!rk4.count(dt) && 4.0 * (kDuration / dt) * ns_per_eval * 1e-9 > budget) break;
    Report(n, scene, "rk4", dt, rk4_at(dt), ref.deck, ref_period);
  }
  // DOPRI5: rtol 1e-3 .. 1e-10; the next rung predicted at twice the last one's time.
  double predicted = 6.0 * (kDuration / (1.1 * limit)) * ns_per_eval * 1e-9;
  const bool stiff = predicted > 5;
  for (double rtol = 1e-3; rtol >= 1e-10; rtol /= 10) {
    if (predicted > budget) break;
    if (stiff && std::lround(std::log10(rtol)) % 3 != 0) continue;
    const Run r = s.Dopri(rtol);
    const Errors e = Report(n, scene, "dopri5", rtol, r, ref.deck, ref_period);
    if (r.ok) predicted = std::max(predicted, 2 * r.wall);
    if (e.disp <= 2 * floor_disp || e.period <= 2 * floor_period) break;
  }
  // SDIRK3: 1e-3 down to the largest stable RK4 rung (below it RK4 runs too, at a fraction of
  // the cost per step). A step costs ~100 evaluations (n = 8, 9), until a completed run
  // measures it; a failed run says nothing of the cost of a complete one.
  double wall_per_step = 100 * ns_per_eval * 1e-9;
  for (double dt = kSample; dt >= std::max(probe_dt, 4 * ref_dt); dt /= 2) {
    if (wall_per_step * (kDuration / dt) > budget) break;
    double per_step = 0;
    const Run r = s.Sdirk(dt, &per_step);
    Report(n, scene, "sdirk3", dt, r, ref.deck, ref_period);
    if (r.ok) wall_per_step = per_step;
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int min_n = argc > 1 ? std::atoi(argv[1]) : 1;
  const int max_n = argc > 2 ? std::atoi(argv[2]) : 10;
  const std::string config_3d = argc > 3 ? argv[3] : "configs/paper_3d.json";
  std::printf("n,scene,method,parameter,wall_s,evaluations,disp_error,period_error,status\n");
  for (int n = min_n; n <= max_n; ++n) {
    Config config;
    config.bridge.n = n;
    const DynamicModel model = BuildDynamicModel(RunDesign(config));
    const double budget = n >= 10 ? kBudgetLargest : kBudget;
    RunScene(n, "small", model, 1e-4, budget);
    if (n <= 3) RunScene(n, "table5", model, 0.1, budget);
  }
  if (config_3d != "-") {
    try {
      const Config config = LoadConfig(config_3d);
      const DynamicModel model = BuildDynamicModel(RunDesign(config));
      RunScene(config.bridge.n, "3d", model, 1e-4, kBudget);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bench_work_precision: 3D scene from %s: %s\n", config_3d.c_str(),
                   e.what());
      return 1;
    }
  }
  return 0;
}
