#include "dynamics/engine_frame.h"

#include "core/error.h"

namespace tbridge {

EngineFrame::EngineFrame(const DynamicModel& model, const EngineOptions& options,
                         const std::vector<TimedLoad>& timed, const char* engine)
    : engine_(engine), dim_(model.dim), n_n_(model.num_nodes()), options_(options) {
  const std::string where(engine);
  CheckModel(model, where);
  if (options.stabilisation && !(options.omega_rad_s > 0 && options.zeta >= 0)) {
    throw ModelError(where + ": stabilisation needs omega > 0 and zeta >= 0");
  }
  node_mass_ = model.node_mass;
  mass_damping_ = model.mass_damping_per_s;
  loads_ = NodeLoads(model, timed, engine);
  strings_ = PackStrings(model, damped_);
  rest_positions_.resize(coordinates());
  for (int a = 0; a < n_n_; ++a) {
    for (int d = 0; d < dim_; ++d) rest_positions_(a * dim_ + d) = model.positions(d, a);
  }
}

void EngineFrame::AddNodes(const DynamicModel& model, const std::vector<bool>& has_bar) {
  for (int a = 0; a < n_n_; ++a) {
    if (model.fixed[a]) {
      fixed_offsets_.push_back(a * dim_);
    } else if (!has_bar[a]) {
      const double m = NodeMass(a);
      if (!(m > 0)) {
        throw ModelError(
            Where() + ": free node " + std::to_string(a + 1) +
            " has neither a bar nor a mass (use string_mass \"nodes\" or give it mass)");
      }
      lone_.push_back({a * dim_, m, 1.0 / m});
    }
  }
  // One dense pass where lone nodes hold most coordinates (a structure of strings); node by
  // node where bars hold most (a bridge: the dense pass would weigh mostly zeros).
  if (2 * static_cast<int>(lone_.size()) * dim_ >= coordinates()) {
    lone_mass_ = Eigen::VectorXd::Zero(coordinates());
    for (const LoneNode& n : lone_) lone_mass_.segment(n.o, dim_).setConstant(n.mass);
  }
}

Eigen::VectorXd EngineFrame::RestState() const {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(state_size());
  y.head(coordinates()) = rest_positions_;
  return y;
}

template <int Dim>
double EngineFrame::KineticEnergyOf(const double* y) const {
  // CAUTION: performance-sensitive: the run's monitor calls it at every accepted step.
  const double* v = y + coordinates();
  auto dot = [&](int a, int b) {
    double s = 0;
    for (int d = 0; d < Dim; ++d) s += v[a + d] * v[b + d];
    return s;
  };
  // The lone nodes as one pass over every coordinate, weighted by lone_mass_ (zero elsewhere),
  // or node by node; in four running sums, so the additions do not wait on each other (in the
  // dense pass they pair into vector ones).
  double e[4] = {0, 0, 0, 0};
  if (lone_mass_.size() != 0) {
    const double* m = lone_mass_.data();
    const int c = coordinates();
    int i = 0;
    for (; i + 4 <= c; i += 4) {
      for (int l = 0; l < 4; ++l) e[l] += m[i + l] * v[i + l] * v[i + l];
    }
    for (; i < c; ++i) e[0] += m[i] * v[i] * v[i];
  } else {
    for (size_t k = 0; k < lone_.size(); ++k)
      e[k % 2] += lone_[k].mass * dot(lone_[k].o, lone_[k].o);
  }
  for (const MassBlock& b : blocks_) {
    e[1] += b.m00 * dot(b.oi, b.oi);
    e[2] += b.m11 * dot(b.oj, b.oj);
    e[3] += b.two_m01 * dot(b.oi, b.oj);
  }
  for (const MassEnd& b : block_ends_) e[0] += b.mass * dot(b.o, b.o);
  return 0.5 * ((e[0] + e[1]) + (e[2] + e[3]));
}

double EngineFrame::KineticEnergy(const double* y) const {
  return dim_ == 2 ? KineticEnergyOf<2>(y) : KineticEnergyOf<3>(y);
}

}  // namespace tbridge
