#include "dynamics/initial_state.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "core/json_reader.h"

namespace tbridge {

namespace {

constexpr double kSameLength = 1e-9;  // relative; bars this close share a length class

}  // namespace

std::vector<std::vector<int>> BarLengthClasses(const DynamicModel& model) {
  std::vector<int> order(model.bars.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return model.bars[a].length > model.bars[b].length; });
  std::vector<std::vector<int>> classes;
  for (const int k : order) {
    const double l = model.bars[k].length;
    if (!classes.empty()) {
      const double ref = model.bars[classes.back().front()].length;
      if (std::abs(l - ref) <= kSameLength * ref) {
        classes.back().push_back(k);
        continue;
      }
    }
    classes.push_back({k});
  }
  return classes;
}

Eigen::VectorXd InitialState(const DynamicModel& model, const DynamicsConfig& config) {
  const int dim = model.dim, n_n = model.num_nodes(), c = dim * n_n;
  Eigen::VectorXd y = Eigen::VectorXd::Zero(2 * c);
  for (int a = 0; a < n_n; ++a) {
    for (int d = 0; d < dim; ++d) y(a * dim + d) = model.positions(d, a);
  }
  const PerturbationConfig& p = config.perturbation;
  if (p.bar_class > 0) {
    const auto classes = BarLengthClasses(model);
    if (p.bar_class > static_cast<int>(classes.size())) {
      throw ConfigError("dynamics.perturbation.bar_class", std::to_string(p.bar_class),
                        "this bridge has bar length classes 1.." + std::to_string(classes.size()) +
                            " (1 = longest)");
    }
    std::vector<bool> moved(n_n, false);
    for (const int k : classes[p.bar_class - 1]) {
      for (const int a : {model.bars[k].i, model.bars[k].j}) {
        if (model.fixed[a] || moved[a]) continue;
        moved[a] = true;
        y(a * dim + 1) -= p.delta;
      }
    }
  }
  for (size_t k = 0; k < config.initial.size(); ++k) {
    const NodeInitialConfig& in = config.initial[k];
    const std::string key = "dynamics.initial[" + std::to_string(k) + "]";
    if (in.node > n_n) {
      throw ConfigError(key + ".node", std::to_string(in.node),
                        "must be in 1.." + std::to_string(n_n));
    }
    const int a = in.node - 1;
    if (model.fixed[a])
      throw ConfigError(key + ".node", std::to_string(in.node),
                        "is a support; supports do not move");
    if (dim == 2 && (in.displacement[2] != 0 || in.velocity[2] != 0)) {
      throw ConfigError(key, "z component", "must be 0: this bridge moves in the x-y plane");
    }
    for (int d = 0; d < dim; ++d) {
      y(a * dim + d) += in.displacement[d];
      y(c + a * dim + d) += in.velocity[d];
    }
  }
  // Rigid bars: the initial state must respect their lengths and length rates.
  for (const DynamicBar& b : model.bars) {
    double len2 = 0, rate = 0, speed2 = 0;
    for (int d = 0; d < dim; ++d) {
      const double db = y(b.j * dim + d) - y(b.i * dim + d);
      const double dv = y(c + b.j * dim + d) - y(c + b.i * dim + d);
      len2 += db * db;
      rate += db * dv;
      speed2 += dv * dv;
    }
    const double len = std::sqrt(len2);
    const std::string name = std::to_string(b.i + 1) + "-" + std::to_string(b.j + 1);
    if (std::abs(len - b.length) > 1e-9 * b.length) {
      throw ConfigError("dynamics.initial", "bar " + name + " length " + NumberText(len) + " m",
                        "initial displacements must keep every bar's length " +
                            NumberText(b.length) + " m (move both ends of a bar together)");
    }
    if (std::abs(rate) > 1e-9 * len * std::max(std::sqrt(speed2), 1e-300) && speed2 > 0) {
      throw ConfigError("dynamics.initial",
                        "bar " + name + " length rate " + NumberText(rate / len) + " m/s",
                        "initial velocities must keep every bar's length (relative velocity "
                        "of its ends perpendicular to it)");
    }
  }
  return y;
}

}  // namespace tbridge
