// The class-k engine (Lagrange multipliers for shared bar nodes) against the class-1 closed
// form, closed-form frequencies, conservation laws, symmetry and statics.
#include "dynamics/classk.h"

#include <suitesparse/SuiteSparse_config.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include "bridge/design_model.h"
#include "core/config.h"
#include "core/structure.h"
#include "design/design.h"
#include "dynamics/class1.h"
#include "dynamics/integrators.h"
#include "dynamics/modal.h"
#include "dynamics/model.h"
#include "dynamics/rk4_support.h"
#include "dynamics/simulation.h"

namespace tbridge {
namespace {

const Design& DesignOf(int n, int p, int planes = 1) {
  static std::map<std::tuple<int, int, int>, Design> cache;
  const auto key = std::make_tuple(n, p, planes);
  auto it = cache.find(key);
  if (it == cache.end()) {
    Config c;
    c.bridge.n = n;
    c.bridge.p = p;
    if (planes == 2) c = LoadConfig(std::string(TBRIDGE_SOURCE_DIR) + "/configs/paper_3d.json");
    it = cache.emplace(key, RunDesign(c)).first;
  }
  return it->second;
}

using test::RunRk4;

TEST_CASE("eq. 27 shares a string's half mass among the bars at its end node") {
  // The 3D bridge: every bar node meets two bars (its plane's bar and a rung), so each bar
  // gets a quarter of the mass of every string at its ends, and the total is unchanged.
  const Design& design = DesignOf(2, 1, 2);
  const DynamicModel model = BuildDynamicModel(design);
  const Structure& st = design.topology.structure;
  const std::vector<int> bars_at = st.BarsPerNode();
  double expected_total = 0;
  for (size_t k = 0; k < model.bars.size(); ++k) {
    double expected = design.bars[k].mass;
    for (const DynamicString& s : model.strings) {
      for (const int end : {s.i, s.j}) {
        if (!model.fixed[end] && (end == model.bars[k].i || end == model.bars[k].j)) {
          expected += 0.5 * s.mass / bars_at[end];
        }
      }
    }
    CHECK(model.bars[k].mass == Approx(expected).epsilon(1e-14));  // the same sums, reordered
    expected_total += expected;
  }
  double string_share = 0;  // string mass not carried by the supports
  for (const DynamicString& s : model.strings) {
    for (const int end : {s.i, s.j}) string_share += model.fixed[end] ? 0.0 : 0.5 * s.mass;
  }
  double bar_mass = 0;
  for (const MemberSizing& b : design.bars) bar_mass += b.mass;
  CHECK(MovingMass(model) == Approx(bar_mass + string_share).epsilon(1e-14));
  CHECK(*std::max_element(bars_at.begin(), bars_at.end()) == 2);
}

TEST_CASE("class-1 and class-k engines give the same trajectory on a class-1 bridge") {
  const DynamicModel model = BuildDynamicModel(DesignOf(2, 1));
  DynamicsConfig scenario;
  scenario.perturbation.bar_class = 1;
  // Small enough that no string goes slack: with slack bouncing (delta = 0.01 m) the motion
  // amplifies a 1e-15 change of the initial state to 3e-6 m within 1 s, in either engine.
  scenario.perturbation.delta = 0.002;
  const Eigen::VectorXd y0 = InitialState(model, scenario);
  const Class1System one(model);
  const ClassKSystem k(model);
  Class1Ode ode1(one);
  ClassKOde odek(k);
  const double dt = 1e-5;  // well inside RK4's stable step for n = 2 (SPEC §9)
  double worst = 0, largest = 0;
  Eigen::VectorXd yk = y0;

  Rk4Workspace wsk(odek.size());
  RunRk4(ode1, y0, dt, 100000, [&](long step, double t, const Eigen::VectorXd& y1) {
    Rk4Step(odek, t - dt, dt, yk, wsk);
    if (step % 100 != 0) return;
    worst = std::max(worst,
                     (yk.head(k.coordinates()) - y1.head(k.coordinates())).cwiseAbs().maxCoeff());
    largest = std::max(largest,
                       (y1.head(k.coordinates()) - y0.head(k.coordinates())).cwiseAbs().maxCoeff());
  });
  INFO("max position difference " << worst << " m, largest displacement " << largest << " m");
  // The two engines do the same arithmetic in a different order: round-off only (about
  // 2e-13 m, a few ulps of the 12 m coordinates, against a 2e-3 m motion).
  CHECK(worst <= 1e-9 * largest);
  CHECK(largest > 1e-3);  // the run does move
}

// The paper's 3D bridge with the dynamics section of configs/paper_3d_<name>.json.
const Config& Paper3d(const std::string& name) {
  static std::map<std::string, Config> cache;
  auto it = cache.find(name);
  if (it == cache.end()) {
    it = cache
             .emplace(name, LoadConfig(std::string(TBRIDGE_SOURCE_DIR) + "/configs/paper_3d_" +
                                       name + ".json"))
             .first;
  }
  return it->second;
}

// Index of the node at the mirror image (x -> x_min + x_max - x) of node a.
int MirrorNode(const DynamicModel& model, int a) {
  const double x_min = model.positions.row(0).minCoeff(), x_max = model.positions.row(0).maxCoeff();
  Eigen::Vector3d target = model.positions.col(a);
  target.x() = x_min + x_max - target.x();
  for (int b = 0; b < model.num_nodes(); ++b) {
    if ((model.positions.col(b) - target).norm() < 1e-9 * x_max) return b;
  }
  FAIL("node " << a + 1 << " has no mirror image");
  return -1;
}

// Kinetic + elastic energy + potential of the constant loads, -W . (x - x0) [J].
double MechanicalEnergy(const DynamicModel& model, const ClassKSystem& system,
                        const Eigen::VectorXd& y) {
  const int dim = model.dim;
  double e = system.KineticEnergy(y.data());
  for (const DynamicString& s : model.strings) {
    const double len = (y.segment(s.j * dim, dim) - y.segment(s.i * dim, dim)).norm();
    if (len > s.rest_length) e += 0.5 * s.stiffness * (len - s.rest_length) * (len - s.rest_length);
  }
  for (int a = 0; a < model.num_nodes(); ++a) {
    for (int d = 0; d < dim; ++d) e -= model.loads(d, a) * (y(a * dim + d) - model.positions(d, a));
  }
  return e;
}

TEST_CASE("the paper's 3D runs hold every bar length to 1e-9") {
  for (const std::string name : {"travelling", "wind"}) {
    const DynamicsConfig& dc = *Paper3d(name).dynamics;
    const DynamicModel model = BuildDynamicModel(DesignOf(2, 1, 2), ModelOptionsOf(dc));
    REQUIRE(model.tensegrity_class == 2);
    const SimulationResult r = Simulate(model, dc);
    const SimulationSummary& s = r.summary;
    INFO(name << ": engine " << s.engine << ", bar-length error " << s.max_bar_length_error
              << ", peak deck displacement x " << s.peak_deck_displacement[0] << " y "
              << s.peak_deck_displacement[1] << " z " << s.peak_deck_displacement[2]
              << " m, max string stress " << s.max_string_stress << " Pa of " << s.allowed_stress
              << ", slack transitions " << s.slack.total);
    CHECK(s.engine == "classk");
    // The acceptance bound; Baumgarte stabilisation keeps it near 1e-14 at this dt.
    CHECK(s.max_bar_length_error <= 1e-9);
    CHECK(s.peak_deck_displacement[name == "wind" ? 2 : 1] > 0);
  }
}

TEST_CASE("a damped class-k run loses energy at every step") {
  // The 3D bridge at rest under its design loads, its central station (both planes' deck
  // and bottom nodes) thrown sideways: a rigid translation, so every bar keeps its length.
  ModelOptions options;
  options.damping = 25000;  // the paper's c [N s/m]
  const DynamicModel model = BuildDynamicModel(DesignOf(2, 1, 2), options);
  const ClassKSystem system(model);
  ClassKOde ode(system);
  Eigen::VectorXd y0 = system.RestState();
  for (const int node : {2, 5, 8, 11})
    y0(system.coordinates() + 3 * (node - 1) + 2) = 0.05;  // [m/s] in z
  const double dt = 2e-5;                                  // the paper configs' step
  // Measured above the energy at rest (the prestress stores ~280 J, the throw adds ~0.08 J).
  const double rest = MechanicalEnergy(model, system, system.RestState());
  const double initial = MechanicalEnergy(model, system, y0) - rest;
  double previous = initial, worst_rise = -1e300;
  REQUIRE(initial > 0);
  RunRk4(ode, y0, dt, 10000, [&](long, double, const Eigen::VectorXd& y) {
    const double e = MechanicalEnergy(model, system, y) - rest;
    worst_rise = std::max(worst_rise, e - previous);
    previous = e;
  });
  INFO("energy above rest " << initial << " J -> " << previous << " J, largest step change "
                            << worst_rise << " J");
  // No step may gain energy beyond the round-off of the energy sum (~1e-13 J: 1e-16 of the
  // 280 J stored at rest, over 50 strings).
  CHECK(worst_rise <= 1e-11);
  CHECK(previous < 0.1 * initial);  // and the damping does take most of it out in 0.2 s
}

TEST_CASE("the travelling load's response mirrors when its schedule is mirrored") {
  // With f1 -> f2 -> f3 the bridge is not loaded symmetrically, and damping makes the motion
  // irreversible, so no node mirrors another within one run and "mirrored times" t and
  // 0.75 - t do not correspond. What the symmetry x -> L - x gives exactly: the run with the
  // schedule mirrored (f3 -> f2 -> f1) moves the mirror node the same way at the same time,
  // with the x displacement reversed.
  DynamicsConfig forward = *Paper3d("travelling").dynamics;
  const DynamicModel model = BuildDynamicModel(DesignOf(2, 1, 2), ModelOptionsOf(forward));
  forward.duration = 0.5;  // two stations: enough to see the load move
  DynamicsConfig mirrored = forward;
  for (LoadStepConfig& l : mirrored.loads) l.node = MirrorNode(model, l.node - 1) + 1;
  const SimulationResult a = Simulate(model, forward);
  const SimulationResult b = Simulate(model, mirrored);
  REQUIRE(a.history.rows() == b.history.rows());
  REQUIRE(a.recorded_nodes.size() == 16);
  double mismatch = 0, asymmetry = 0, largest = 0;
  for (Eigen::Index row = 0; row < a.history.rows(); ++row) {
    for (int node = 0; node < 16; ++node) {
      const int m = MirrorNode(model, node);
      for (int d = 0; d < 3; ++d) {
        const double sign = d == 0 ? -1.0 : 1.0;
        const double ua = a.history(row, 1 + 3 * node + d) - model.positions(d, node);
        const double ub = b.history(row, 1 + 3 * m + d) - model.positions(d, m);
        const double ua_m = a.history(row, 1 + 3 * m + d) - model.positions(d, m);
        mismatch = std::max(mismatch, std::abs(ua - sign * ub));
        asymmetry = std::max(asymmetry, std::abs(ua - sign * ua_m));
        largest = std::max(largest, std::abs(ua));
      }
    }
  }
  INFO("mirror mismatch " << mismatch << " m, in-run asymmetry " << asymmetry
                          << " m, largest displacement " << largest << " m");
  // Round-off: the design comes out mirror-symmetric to round-off (5e-12 of the motion seen);
  // 1e-9 leaves room for an optimiser that is symmetric only to its tolerance.
  CHECK(mismatch <= 1e-9 * largest);
  CHECK(asymmetry > 0.1 * largest);  // the test can tell: one run alone is far from symmetric
}

// Reactions at the supports from the engine's bar forces and the string tensions at rest.
Eigen::Vector3d SupportReactions(const DynamicModel& model, const Eigen::VectorXd& lambda) {
  Eigen::Matrix3Xd member = Eigen::Matrix3Xd::Zero(3, model.num_nodes());  // member forces on nodes
  for (const DynamicString& s : model.strings) {
    const Eigen::Vector3d v = model.positions.col(s.j) - model.positions.col(s.i);
    const double len = v.norm();
    if (len <= s.rest_length) continue;
    const Eigen::Vector3d pull = s.stiffness * (len - s.rest_length) / len * v;
    member.col(s.i) += pull;
    member.col(s.j) -= pull;
  }
  for (size_t k = 0; k < model.bars.size(); ++k) {
    const DynamicBar& b = model.bars[k];
    const Eigen::Vector3d push = lambda(static_cast<Eigen::Index>(k)) *
                                 (model.positions.col(b.j) - model.positions.col(b.i));
    member.col(b.i) -= push;
    member.col(b.j) += push;
  }
  Eigen::Vector3d reaction = Eigen::Vector3d::Zero();
  for (int a = 0; a < model.num_nodes(); ++a) {
    if (model.fixed[a]) reaction -= member.col(a) + model.loads.col(a);
  }
  return reaction;
}

TEST_CASE("at rest the support reactions carry the applied load") {
  for (const auto& [n, p, planes] :
       {std::tuple{2, 1, 2}, std::tuple{2, 2, 1}, std::tuple{2, 3, 1}}) {
    const DynamicModel model = BuildDynamicModel(DesignOf(n, p, planes));
    const ClassKSystem system(model);
    ClassKWorkspace ws(system);
    const Eigen::VectorXd y = system.RestState();
    Eigen::VectorXd dy(y.size());
    system.Derivative(0, y.data(), dy.data(), ws);
    Eigen::VectorXd lambda;
    system.BarForceDensities(ws, lambda);
    const Eigen::Vector3d reaction = SupportReactions(model, lambda);
    const Eigen::Vector3d applied = model.loads.rowwise().sum();
    INFO("n " << n << " p " << p << " planes " << planes << ": reactions " << reaction.transpose()
              << " N, applied " << applied.transpose() << " N, largest acceleration "
              << dy.tail(system.coordinates()).cwiseAbs().maxCoeff());
    // Equilibrium holds to the design optimiser's residual (~1e-8 N per node).
    CHECK((reaction + applied).norm() <= 1e-9 * applied.norm());
    // At rest: each node's unbalanced force is at most what the design's solve leaves,
    // design.tolerance of the largest member force r. A force r at one end of a free rod of
    // mass m accelerates that end by 4 r / m (r / m in translation, 3 r / m in rotation); both
    // ends may carry one: 8 r / m for the lightest bar.
    double lightest_bar_kg = std::numeric_limits<double>::infinity();
    for (const DynamicBar& b : model.bars) lightest_bar_kg = std::min(lightest_bar_kg, b.mass);
    const Design& design = DesignOf(n, p, planes);
    const double residual_n =
        design.config.design.tolerance * design.reference_forces.cwiseAbs().maxCoeff();
    CHECK(dy.tail(system.coordinates()).cwiseAbs().maxCoeff() <=
          8.0 * residual_n / lightest_bar_kg);  // [m/s^2]
    if (planes == 2) {
      // Independently: six deck nodes at f = F_tot / (2^n 2) = 3701.43 N (docs/topology.md).
      CHECK(reaction.y() == Approx(6 * 3701.4338721644413).epsilon(1e-12));
    }
  }
}

// Two uniform bars of length l and mass m hinged together, the first pinned at its top:
// gravity acts as half of each bar's weight at its ends (exact for a rigid uniform bar).
DynamicModel DoublePendulum(double l, double m, double g) {
  DynamicModel model;
  model.dim = 2;
  model.positions = Eigen::Matrix3Xd::Zero(3, 3);
  model.positions.col(1) = Eigen::Vector3d(0, -l, 0);
  model.positions.col(2) = Eigen::Vector3d(0, -2 * l, 0);
  model.fixed = {true, false, false};
  model.bars.push_back({0, 1, m, l});
  model.bars.push_back({1, 2, m, l});
  model.node_mass = Eigen::VectorXd::Zero(3);
  model.loads = Eigen::Matrix3Xd::Zero(3, 3);
  model.loads(1, 1) = -m * g;  // half of each bar
  model.loads(1, 2) = -0.5 * m * g;
  model.tensegrity_class = 2;
  return model;
}

TEST_CASE("two hinged bars swing at the closed-form double-pendulum frequencies") {
  // Linearised: M = m l^2 [4/3 1/2; 1/2 1/3], K = m g l [3/2 0; 0 1/2] in the bar angles, so
  // omega^2 = (g/l)(3 -+ 6/sqrt 7).
  const double l = 2.0, m = 5.0, g = 9.81;
  const double w_slow = std::sqrt(g / l * (3 - 6 / std::sqrt(7.0)));
  const double w_fast = std::sqrt(g / l * (3 + 6 / std::sqrt(7.0)));
  const DynamicModel model = DoublePendulum(l, m, g);

  SECTION("modal analysis") {
    const ModalResult modes = ComputeModes(model);
    REQUIRE(modes.modes.size() == 2);
    CHECK(modes.constraints == 2);
    // Dense symmetric eigensolver: round-off only.
    CHECK(modes.modes[0].omega_rad_s == Approx(w_slow).epsilon(1e-10));
    CHECK(modes.modes[1].omega_rad_s == Approx(w_fast).epsilon(1e-10));
  }
  SECTION("time history of the slow mode") {
    // Start in the slow mode shape: theta2/theta1 = (3/2 - 4 lambda/3) / (lambda/2), with
    // lambda = omega^2 l / g.
    const double lambda = w_slow * w_slow * l / g;
    const double t1 = 1e-4, t2 = t1 * (1.5 - 4 * lambda / 3) / (lambda / 2);  // [rad]: linear
    const ClassKSystem system(model);
    ClassKOde ode(system);
    Eigen::VectorXd y = system.RestState();
    y(2) = l * std::sin(t1);
    y(3) = -l * std::cos(t1);
    y(4) = y(2) + l * std::sin(t2);
    y(5) = y(3) - l * std::cos(t2);
    const double dt = 1e-3;  // omega dt = 0.003: RK4 phase error ~1e-12 per period
    double last = y(4), last_t = 0;
    std::vector<double> crossings;  // downward zero crossings of the lower node's x
    RunRk4(ode, y, dt, 20000, [&](long, double t, const Eigen::VectorXd& s) {
      if (last > 0 && s(4) <= 0) crossings.push_back(last_t + dt * last / (last - s(4)));
      last = s(4);
      last_t = t;
    });
    REQUIRE(crossings.size() >= 5);
    const double period =
        (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
    INFO(crossings.size() << " crossings, period " << period << " s, closed form "
                          << 2 * std::numbers::pi / w_slow);
    // Linear interpolation of a sine's zero crossing errs by ~(omega dt)^3/6 dt = 5e-12 s;
    // the amplitude (1e-4 rad) shifts the period by ~1e-9 relative.
    CHECK(2 * std::numbers::pi / period == Approx(w_slow).epsilon(1e-7));
  }
}

TEST_CASE("planar p = 2 and p = 3 bridges stay at rest and have stable modes") {
  for (const int p : {2, 3}) {
    for (int n = 1; n <= 3; ++n) {
      const DynamicModel model = BuildDynamicModel(DesignOf(n, p));
      REQUIRE(model.tensegrity_class == p);
      const ModalResult modes = ComputeModes(model);
      REQUIRE(!modes.modes.empty());
      const double dt = 0.5 * Rk4StableStep(modes);  // half the RK4 limit of the stiffest mode
      const ClassKSystem system(model);
      ClassKOde ode(system);
      const Eigen::VectorXd y0 = system.RestState();
      const double span = model.positions.row(0).maxCoeff() - model.positions.row(0).minCoeff();
      double drift = 0;
      RunRk4(ode, y0, dt, std::lround(std::ceil(0.2 / dt)),
             [&](long, double, const Eigen::VectorXd& y) {
               drift =
                   std::max(drift, (y.head(system.coordinates()) - y0.head(system.coordinates()))
                                       .cwiseAbs()
                                       .maxCoeff());
             });
      INFO("p = " << p << ", n = " << n << ": " << modes.modes.size() << " modes, lowest "
                  << modes.modes.front().frequency_hz << " Hz, highest "
                  << modes.modes.back().frequency_hz << " Hz; drift at rest " << drift
                  << " m over 0.2 s (dt " << dt << " s)");
      CHECK(modes.modes.front().omega_squared > 0);  // no mechanism, no instability
      // The acceptance bound; the design's equilibrium residual (~1e-9 m/s^2 here) moves a
      // node ~1e-11 m in 0.2 s.
      CHECK(drift <= 1e-9 * span);
    }
  }
}

TEST_CASE("a p = 2 bridge's modal and time-history frequencies agree") {
  DynamicsConfig run;
  run.duration =
      20.0;       // ~40 cycles of the lowest mode near 12 rad/s: with 7 the estimate is off by 1e-4
  run.dt = 1e-4;  // 7x below the RK4 limit of p = 2, n = 2
  run.perturbation.bar_class = 1;
  run.perturbation.delta = 1e-4;  // [m]: strings stay taut, the motion is linear
  run.frequency.enabled = true;
  const DynamicModel model = BuildDynamicModel(DesignOf(2, 2), ModelOptionsOf(run));
  const SimulationResult result = Simulate(model, run);
  REQUIRE(result.summary.has_frequency);
  CHECK(result.summary.engine == "classk");
  CHECK(result.summary.slack.total == 0);
  const ModalResult modes = ComputeModes(model);
  double closest = 0;
  for (const Mode& mode : modes.modes) {
    if (std::abs(mode.omega_rad_s - result.summary.frequency.omega_rad_s) <
        std::abs(closest - result.summary.frequency.omega_rad_s)) {
      closest = mode.omega_rad_s;
    }
  }
  INFO("time history " << result.summary.frequency.omega_rad_s << " rad/s, nearest mode " << closest
                       << " rad/s, lowest " << modes.modes.front().omega_rad_s);
  // The estimate's resolution over 40 cycles (9e-6 seen); a mass or stiffness error would
  // show at the 1e-3 level.
  CHECK(result.summary.frequency.omega_rad_s == Approx(closest).epsilon(5e-5));
}

// Counts CHOLMOD's allocations through SuiteSparse's memory hooks.
long g_cholmod_allocations = 0;
void* CountingMalloc(size_t size) {
  ++g_cholmod_allocations;
  return std::malloc(size);
}
void* CountingCalloc(size_t n, size_t size) {
  ++g_cholmod_allocations;
  return std::calloc(n, size);
}
void* CountingRealloc(void* p, size_t size) {
  ++g_cholmod_allocations;
  return std::realloc(p, size);
}

TEST_CASE("after the workspace's warm-up CHOLMOD allocates nothing per step") {
  const DynamicModel model = BuildDynamicModel(DesignOf(2, 1, 2));
  ClassKOptions stab;
  stab.stabilisation = true;
  const ClassKSystem system(model, stab, {TimedLoad{0, 1, 1, Eigen::Vector3d(0, -100, 0)}});
  ClassKOde ode(system);
  Rk4Workspace ws(system.state_size());
  Eigen::VectorXd y = system.RestState();
  const auto saved = SuiteSparse_config;
  SuiteSparse_config.malloc_func = CountingMalloc;
  SuiteSparse_config.calloc_func = CountingCalloc;
  SuiteSparse_config.realloc_func = CountingRealloc;
  g_cholmod_allocations = 0;
  for (int k = 0; k < 100; ++k) Rk4Step(ode, k * 1e-5, 1e-5, y, ws);
  const long in_steps = g_cholmod_allocations;
  ClassKWorkspace fresh(system);  // the hooks do see CHOLMOD's allocations
  const long in_construction = g_cholmod_allocations - in_steps;
  SuiteSparse_config = saved;
  INFO(in_construction << " allocations while building a workspace");
  CHECK(in_steps == 0);
  CHECK(in_construction > 0);
}

TEST_CASE("dependent bar constraints are reported, not solved") {
  // Two bars joining the same two nodes: their length constraints coincide, A is singular.
  DynamicModel model = DoublePendulum(1.0, 1.0, 9.81);
  model.bars.push_back(model.bars[1]);
  const ClassKSystem system(model);
  CHECK_THROWS_WITH(ClassKWorkspace(system), Catch::Contains("not positive definite"));
}

}  // namespace
}  // namespace tbridge
