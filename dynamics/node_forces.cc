#include "dynamics/node_forces.h"

#include <cmath>
#include <cstring>
#include <string>

#include "core/error.h"

namespace tbridge {

NodeLoads::NodeLoads(const DynamicModel& model, const std::vector<TimedLoad>& timed,
                     const char* engine)
    : dim_(model.dim) {
  const int n_n = model.num_nodes();
  constant_ = Eigen::VectorXd::Zero(dim_ * n_n);
  if (model.loads.size() != 0) {
    for (int a = 0; a < n_n; ++a) {
      for (int d = 0; d < dim_; ++d) constant_(a * dim_ + d) = model.loads(d, a);
    }
  }
  for (const TimedLoad& l : timed) {
    if (l.node < 0 || l.node >= n_n) {
      throw ModelError(std::string(engine) + ": a timed load names node " +
                       std::to_string(l.node + 1) + " out of range");
    }
    timed_.push_back({l.t_start,
                      l.t_end,
                      l.rise_s,
                      l.fall_s,
                      l.omega_rad_s,
                      l.spread_s,
                      l.node * dim_,
                      {l.force.x(), l.force.y(), l.force.z()}});
  }
}

void NodeLoads::At(double t, double* force) const {
  std::memcpy(force, constant_.data(), sizeof(double) * static_cast<size_t>(constant_.size()));
  for (const PackedLoad& l : timed_) {
    double shape = LoadShape(t, l.t_start, l.t_end, l.rise_s, l.fall_s, l.spread_s);
    if (l.omega != 0.0) shape *= std::sin(l.omega * t);
    if (shape != 0.0) {
      for (int d = 0; d < dim_; ++d) force[l.o + d] += shape * l.f[d];
    }
  }
}

std::vector<PackedString> PackStrings(const DynamicModel& model, bool& damped) {
  const int dim = model.dim;
  std::vector<PackedString> out;
  damped = false;
  for (size_t k = 0; k < model.strings.size(); ++k) {
    const DynamicString s = model.strings[k];
    if (model.fixed[s.i] && model.fixed[s.j]) continue;  // moves nothing
    out.push_back({s.i * dim, s.j * dim, s.stiffness, s.stiffness * s.rest_length, s.damping,
                   static_cast<int>(k)});
    damped = damped || s.damping > 0;
  }
  return out;
}

}  // namespace tbridge
