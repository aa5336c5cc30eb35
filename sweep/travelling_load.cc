#include "sweep/travelling_load.h"

#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"
#include "dynamics/class1.h"
#include "dynamics/integrators.h"

namespace tbridge {

namespace {

struct BarCheck {
  int i, j;           // 0-based nodes
  double m00, m01, m11;  // mass matrix with the end point masses (class1.h)
  double rest_sq;
  double tension_capacity, compression_capacity;  // [N]
};

}  // namespace

TravellingLoadResult RunTravellingLoad(const DynamicModel& model, const Design& design,
                                       const TravellingLoadConfig& config) {
  const int dim = model.dim;
  if (model.deck_nodes.empty()) throw ModelError("travelling load: the model has no deck nodes");
  if (design.bars.size() != model.bars.size()) throw ModelError("travelling load: model and design bars differ");
  const int planes = std::max(1, design.topology.planes);
  const int stations = static_cast<int>(model.deck_nodes.size()) / planes;
  const double station_time = config.duration / stations;
  const double force = config.load_factor * design.deck.node_load;
  std::vector<TimedLoad> timed;
  for (int k = 0; k < stations; ++k) {
    for (int plane = 0; plane < planes; ++plane) {
      timed.push_back({k * station_time, (k + 1) * station_time, model.deck_nodes[k + plane * stations],
                       Eigen::Vector3d(0, -force, 0)});
    }
  }
  const Class1System system(model, {}, timed);  // throws for class k
  Class1Ode ode(system);
  Class1Workspace check_ws(system.coordinates());

  const double sigma_w = model.allowed_stress;
  const double sf_buckling = design.config.design.buckling_safety_factor;
  std::vector<BarCheck> bars;
  for (size_t k = 0; k < model.bars.size(); ++k) {
    const DynamicBar& b = model.bars[k];
    const double area = design.bars[k].area;
    const double mi = model.node_mass.size() ? model.node_mass(b.i) : 0.0;
    const double mj = model.node_mass.size() ? model.node_mass(b.j) : 0.0;
    const double euler = std::numbers::pi * model.youngs_modulus * area * area / (4 * b.length * b.length * sf_buckling);
    bars.push_back({b.i, b.j, b.mass / 3 + mi, b.mass / 6, b.mass / 3 + mj, b.length * b.length, sigma_w * area,
                    std::min(sigma_w * area, euler)});
  }

  TravellingLoadResult r;
  std::vector<char> was_slack(model.strings.size(), 0);
  Eigen::VectorXd y = system.RestState();
  Eigen::VectorXd dy(system.state_size());
  Eigen::VectorXd f(system.coordinates());  // non-bar node forces
  const int c = system.coordinates();
  Rk4Workspace ws(system.state_size());
  const long total = std::max<long>(1, std::lround(std::ceil(config.duration / config.dt - 1e-9)));

  // CAUTION: performance-sensitive (runs once per step)
  auto check = [&](double t_hold, double t) {
    for (const int a : model.deck_nodes) {
      r.peak_deck_displacement = std::max(r.peak_deck_displacement, std::abs(y(a * dim + 1) - model.positions(1, a)));
    }
    system.LoadsAt(t_hold, f.data());
    for (size_t k = 0; k < model.strings.size(); ++k) {
      const DynamicString& s = model.strings[k];
      double len2 = 0, rate = 0;
      double d[3] = {0, 0, 0};
      for (int q = 0; q < dim; ++q) {
        d[q] = y(s.j * dim + q) - y(s.i * dim + q);
        len2 += d[q] * d[q];
        rate += d[q] * (y(c + s.j * dim + q) - y(c + s.i * dim + q));
      }
      const double len = std::sqrt(len2);
      if (len < s.rest_length) {
        was_slack[k] = 1;
        continue;
      }
      const double gamma = std::max(s.stiffness * (1 - s.rest_length / len) + s.damping * rate / len2, 0.0);
      r.peak_string_stress = std::max(r.peak_string_stress, gamma * len / model.string_area[k]);
      for (int q = 0; q < dim; ++q) {
        f(s.i * dim + q) += gamma * d[q];
        f(s.j * dim + q) -= gamma * d[q];
      }
    }
    system.Derivative(t_hold, y.data(), dy.data(), check_ws);
    for (const BarCheck& b : bars) {
      const bool fi = model.fixed[b.i], fj = model.fixed[b.j];
      if (fi && fj) continue;
      double bb = 0, lambda_num = 0;
      for (int q = 0; q < dim; ++q) {
        const double bq = y(b.j * dim + q) - y(b.i * dim + q);
        const double ai = dy(c + b.i * dim + q), aj = dy(c + b.j * dim + q);
        bb += bq * bq;
        // Node i: m00 a_i + m01 a_j = F_i - lambda b; pinned i: (m/3 + m_j) a_j = F_j + lambda b.
        lambda_num += fi ? bq * (b.m11 * aj - f(b.j * dim + q)) : bq * (f(b.i * dim + q) - b.m00 * ai - (fj ? 0 : b.m01 * aj));
      }
      const double err = std::abs(bb - b.rest_sq) / b.rest_sq;
      if (!std::isfinite(bb) || err > 2e-3) {
        throw ModelError("travelling load: bar length error " + std::to_string(0.5 * err) + " at t = " +
                         std::to_string(t) + " s; try a smaller sweep.travelling_load.dt than " +
                         std::to_string(config.dt) + " s");
      }
      const double compression = lambda_num / std::sqrt(bb);  // lambda l, > 0 in compression
      const double ratio = compression >= 0 ? compression / b.compression_capacity : -compression / b.tension_capacity;
      r.peak_bar_capacity_ratio = std::max(r.peak_bar_capacity_ratio, ratio);
    }
  };

  check(0.5 * config.dt, 0.0);
  for (long step = 1; step <= total; ++step) {
    const double t_old = (step - 1) * config.dt;
    const double t = step == total ? config.duration : step * config.dt;
    const double hold = 0.5 * (t_old + t);
    ode.HoldLoadsAt(hold);
    Rk4Step(ode, t_old, t - t_old, y, ws);
    check(hold, t);
  }
  r.steps = total;
  r.peak_stress_ratio = r.peak_string_stress / sigma_w;
  for (const char s : was_slack) r.slack_strings += s;
  return r;
}

}  // namespace tbridge
