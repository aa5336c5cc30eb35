#include "dynamics/run_monitor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/error.h"
#include "core/string_law.h"
#include "dynamics/node_forces.h"
#include "dynamics/step_size.h"

namespace tbridge {

RunMonitor::RunMonitor(const DynamicModel& model, const EngineFrame& engine, const DynamicsConfig& config,
                       const Eigen::VectorXd& y0, BarForceProbe probe)
    : model_(model), engine_(engine), config_(config), dim_(model.dim), c_(engine.coordinates()),
      probe_(std::move(probe)) {
  const size_t n_s = model.strings.size();
  for (size_t k = 0; k < n_s; ++k) {
    const DynamicString& s = model.strings[k];
    const double area = model.strings.area[k];
    strings_.push_back({s.i * dim_, s.j * dim_, s.rest_length, s.rest_length * s.rest_length,
                        1.0 / (s.rest_length * s.rest_length), s.stiffness, s.damping, area > 0 ? 1.0 / area : 0.0});
  }
  for (const DynamicBar& b : model.bars) bars_.push_back({b.i * dim_, b.j * dim_, 1.0 / (b.length * b.length)});
  for (const int a : model.deck_nodes) {
    deck_offsets_.push_back(a * dim_);
    for (int d = 0; d < 3; ++d) deck_rest_.push_back(model.positions(d, a));
  }
  const double g = config.guard.max_bar_length_error;
  bar_guard_hi_ = (1 + g) * (1 + g);
  bar_guard_lo_ = g < 1 ? (1 - g) * (1 - g) : 0.0;
  x0_ = y0.head(c_);
  loads_ = Eigen::VectorXd::Zero(c_);
  if (model.loads.size() != 0) {
    for (int a = 0; a < model.num_nodes(); ++a) {
      for (int d = 0; d < dim_; ++d) loads_(a * dim_ + d) = model.loads(d, a);
    }
  }
  loads_dot_x0_ = loads_.dot(x0_);
  has_loads_ = loads_.cwiseAbs().maxCoeff() > 0;
  for (const LoadStepConfig& l : config.loads) {
    TimedLoadState s{(l.node - 1) * dim_, l.t_start, l.t_end, l.rise_s, l.fall_s, {0, 0, 0}, {0, 0, 0}};
    for (int d = 0; d < dim_; ++d) {
      s.force[d] = l.force[d];
      s.last[d] = x0_(s.o + d);
    }
    timed_.push_back(s);
  }
  taut_.assign(n_s, 0);
  for (size_t k = 0; k < n_s; ++k) {  // the start's slack strings are not transitions
    const PackedString& st = strings_[k];
    double len2 = 0;
    for (int d = 0; d < dim_; ++d) {
      const double dx = y0(st.oj + d) - y0(st.oi + d);
      len2 += dx * dx;
    }
    taut_[k] = len2 >= st.rest_sq;
    if (!taut_[k]) ++summary_.slack.slack_at_start;
  }
  // The strings no engine evaluates (both ends pinned) keep the geometry they start with.
  geometry_.resize(n_s);
  for (size_t k = 0; k < n_s; ++k) {
    const PackedString& st = strings_[k];
    double len2 = 0, rate = 0;
    for (int d = 0; d < dim_; ++d) {
      const double dx = y0(st.oj + d) - y0(st.oi + d);
      len2 += dx * dx;
      rate += dx * (y0(c_ + st.oj + d) - y0(c_ + st.oi + d));
    }
    geometry_[k] = {len2, 1.0 / std::sqrt(len2), rate};
  }
  ever_slack_.assign(n_s, 0);
  min_ratio_sq_.assign(n_s, std::numeric_limits<double>::infinity());
  summary_.slack.per_string.assign(n_s, 0);
  summary_.peak_string_tension.assign(n_s, 0.0);
  if (probe_) {
    lambda_.setZero(static_cast<Eigen::Index>(model.bars.size()));
    summary_.peak_bar_compression.assign(model.bars.size(), 0.0);
    summary_.peak_bar_tension.assign(model.bars.size(), 0.0);
  }
  summary_.allowed_stress = model.allowed_stress;
  double kinetic = 0, elastic = 0;
  Measure(0.0, 0.0, y0.data(), nullptr, kinetic, elastic);
  auto& e = summary_.energy;
  e.kinetic_start = e.kinetic_end = kinetic;
  e.elastic_start = e.elastic_end = elastic;
  e.reference = std::max(kinetic + elastic, 1e-12);
  h0_ = kinetic + elastic;
}

void RunMonitor::Accept(long step, double t_old, double t, const double* y, double dissipated,
                         const StringGeometry* strings) {
  // The state's sum finds a NaN or an infinity anywhere in it (they propagate through it), and
  // the work of the constant loads is W . (x - x0), when there are any: Eigen's reductions,
  // which run in vector registers.
  const Eigen::Map<const Eigen::VectorXd> state(y, 2 * static_cast<Eigen::Index>(c_));
  if (!std::isfinite(state.sum())) Fail(step, t, "a node position or velocity is not finite");
  const double load_dot_x = has_loads_ ? loads_.dot(state.head(c_)) : 0.0;
  double kinetic = 0, elastic = 0;
  Measure(t, 0.5 * (t_old + t), y, strings, kinetic, elastic);
  auto& e = summary_.energy;
  e.dissipated += dissipated;
  // Work of the loads: constant loads exactly, W . (x - x0), from the pass above; each timed load
  // by its force times the displacement of its node over the part of the step it acts in
  // (exact, since the driver holds the loads constant over a step; a ramp's force is taken at
  // the middle of that part).
  const double work = load_dot_x - loads_dot_x0_;
  for (TimedLoadState& l : timed_) {
    const double overlap = std::min(t, l.t_end) - std::max(t_old, l.t_start);
    if (overlap > 0) {
      const double mid = std::max(t_old, l.t_start) + 0.5 * overlap;
      const double shape = LoadShape(mid, l.t_start, l.t_end, l.rise_s, l.fall_s);
      double fdx = 0;
      for (int d = 0; d < dim_; ++d) fdx += l.force[d] * (y[l.o + d] - l.last[d]);
      timed_work_ += shape * fdx * overlap / (t - t_old);
    }
    for (int d = 0; d < dim_; ++d) l.last[d] = y[l.o + d];
  }
  e.external_work = work + timed_work_;
  e.kinetic_end = kinetic;
  e.elastic_end = elastic;
  const double drift = (kinetic + elastic - e.external_work + e.dissipated - h0_) / e.reference;
  e.final_drift = drift;
  e.max_drift = std::max(e.max_drift, std::abs(drift));
  if (bar_ratio_sq_max_ > bar_guard_hi_ || bar_ratio_sq_min_ < bar_guard_lo_) {
    const double error = std::max(std::sqrt(bar_ratio_sq_max_) - 1.0, 1.0 - std::sqrt(bar_ratio_sq_min_));
    std::ostringstream what;
    what << "the bar-length error " << error << " exceeds guard.max_bar_length_error = "
         << config_.guard.max_bar_length_error;
    Fail(step, t, what.str());
  }
  if (drift > config_.guard.max_energy_growth) {
    std::ostringstream what;
    what << "the energy grew by " << drift << " of its initial value (guard.max_energy_growth = "
         << config_.guard.max_energy_growth << ")";
    Fail(step, t, what.str());
  }
}

template <int Dim, bool Damped, bool Given>
void RunMonitor::MeasureMembers(double t, const double* y, const StringGeometry* given, double& elastic) {
  // CAUTION: performance-sensitive: every accepted step of every run passes here. The
  // dimension and the damping are template arguments, so an undamped run reads no velocity
  // and divides by nothing, and the coordinate loops unroll. The arrays and the running
  // extremes are locals: a store to the char flags may alias anything, and would otherwise
  // make the compiler reload every member pointer after it. With Given, each string's length
  // and rate come from the engine's evaluation at this state, computed there by the same
  // expressions; gathering the ends' coordinates again was most of the monitor's time.
  const double* x = y;
  const double* v = y + c_;
  const PackedString* strings = strings_.data();
  const size_t n_s = strings_.size();
  double* min_ratio_sq = min_ratio_sq_.data();
  double* peak = summary_.peak_string_tension.data();
  char* taut_now = taut_.data();
  char* ever_slack = ever_slack_.data();
  int* transitions = summary_.slack.per_string.data();
  double max_stress = summary_.max_string_stress;
  int max_stress_string = max_stress_string_, new_transitions = 0, newly_slack = 0;
  double elastic_sum = 0;
  for (size_t k = 0; k < n_s; ++k) {
    const PackedString& s = strings[k];
    double len2 = 0, rate = 0;
    if constexpr (Given) {
      len2 = given[k].len2;
      rate = given[k].rate;
    } else {
      for (int d = 0; d < Dim; ++d) {
        const double dx = x[s.oj + d] - x[s.oi + d];
        len2 += dx * dx;
        if constexpr (Damped) rate += dx * (v[s.oj + d] - v[s.oi + d]);
      }
    }
    min_ratio_sq[k] = std::min(min_ratio_sq[k], len2 * s.inv_rest_sq);
    const bool taut = len2 >= s.rest_sq;
    if (taut) {
      // |s| as len2 / |s|, with 1/|s| as the engines compute it: given, that takes no square
      // root and no division here (they share one unit, which bounded the monitor).
      double inv_len = 0;
      if constexpr (Given) {
        inv_len = given[k].inv_len;
      } else {
        inv_len = 1.0 / std::sqrt(len2);
      }
      const double len = len2 * inv_len;
      const double spring = StringTension(s.k, s.rest, len);
      elastic_sum += 0.5 * spring * (len - s.rest);
      double tension = spring;
      if constexpr (Damped) {
        const double length_rate = rate * inv_len;
        tension = std::max(spring + s.c * length_rate, 0.0);
      }
      peak[k] = std::max(peak[k], tension);
      const double stress = tension * s.inv_area;
      if (stress > max_stress) {
        max_stress = stress;
        max_stress_string = static_cast<int>(k);
      }
    } else if (!ever_slack[k]) {
      ever_slack[k] = 1;
      ++newly_slack;
    }
    if (static_cast<char>(taut) != taut_now[k]) {
      taut_now[k] = taut;
      ++transitions[k];
      ++new_transitions;
    }
  }
  elastic += elastic_sum;
  if (max_stress_string != max_stress_string_ || max_stress != summary_.max_string_stress) {
    summary_.max_string_stress = max_stress;
    max_stress_string_ = max_stress_string;
    summary_.max_stress_time = t;
  }
  summary_.slack.ever_slack += newly_slack;
  summary_.slack.total += new_transitions;
  for (const PackedBar& b : bars_) {
    double len2 = 0;
    for (int d = 0; d < Dim; ++d) {
      const double db = x[b.oj + d] - x[b.oi + d];
      len2 += db * db;
    }
    const double r = len2 * b.inv_rest_sq;
    bar_ratio_sq_min_ = std::min(bar_ratio_sq_min_, r);
    bar_ratio_sq_max_ = std::max(bar_ratio_sq_max_, r);
  }
}

void RunMonitor::Measure(double t, double load_time, const double* y, const StringGeometry* given, double& kinetic,
                         double& elastic) {
  const auto members = [&]<int Dim, bool Damped>() {
    given != nullptr ? MeasureMembers<Dim, Damped, true>(t, y, given, elastic)
                     : MeasureMembers<Dim, Damped, false>(t, y, given, elastic);
  };
  const bool damped = engine_.damped();
  if (dim_ == 2) {
    damped ? members.operator()<2, true>() : members.operator()<2, false>();
  } else {
    damped ? members.operator()<3, true>() : members.operator()<3, false>();
  }
  const double* x = y;
  for (size_t n = 0; n < deck_offsets_.size(); ++n) {
    const int o = deck_offsets_[n];
    for (int d = 0; d < dim_; ++d) {
      const double u = std::abs(x[o + d] - deck_rest_[3 * n + d]);
      if (u > summary_.peak_deck_displacement[d]) {
        summary_.peak_deck_displacement[d] = u;
        summary_.peak_deck_node[d] = model_.deck_nodes[n];
        summary_.peak_deck_time[d] = t;
      }
    }
  }
  if (probe_) {
    probe_(load_time, y, lambda_);
    for (size_t k = 0; k < model_.bars.size(); ++k) {
      const double force = lambda_(static_cast<Eigen::Index>(k)) * model_.bars[k].length;  // > 0: compression
      double& peak = force >= 0 ? summary_.peak_bar_compression[k] : summary_.peak_bar_tension[k];
      peak = std::max(peak, std::abs(force));
    }
  }
  kinetic = engine_.KineticEnergy(y);
}

void RunMonitor::Finish(const double* y) {
  SimulationSummary& s = summary_;
  for (const PackedString& st : strings_) {
    double len2 = 0;
    for (int d = 0; d < dim_; ++d) {
      const double dx = y[st.oj + d] - y[st.oi + d];
      len2 += dx * dx;
    }
    if (len2 < st.rest_sq) ++s.slack.slack_at_end;
  }
  s.min_string_strain.resize(strings_.size());
  for (size_t k = 0; k < strings_.size(); ++k) s.min_string_strain[k] = std::sqrt(min_ratio_sq_[k]) - 1.0;
  s.max_bar_length_error = std::max(std::sqrt(bar_ratio_sq_max_) - 1.0, 1.0 - std::sqrt(bar_ratio_sq_min_));
  if (max_stress_string_ >= 0) s.max_stress_string = model_.names.string_name[max_stress_string_];
  s.stress_exceeds_allowed = s.max_string_stress > s.allowed_stress;
}

void RunMonitor::Fail(long step, double t, const std::string& what) const {
  std::ostringstream msg;
  msg << "the run blew up at step " << step << ", t = " << t << " s: " << what << ". Try a smaller dt";
  // A safe dt from the highest linearised frequency: half RK4's limit 2 sqrt(2)/omega_max.
  double omega = 0;
  try {
    if (omega_max_) omega = omega_max_();
  } catch (const std::exception&) {
    omega = 0;  // no advice beats a second failure
  }
  const double safe = 0.5 * Rk4StepLimit(omega);
  if (omega > 0 && safe < config_.dt) {
    msg << ": the highest linearised frequency " << omega << " rad/s makes RK4 stable only below " << 2 * safe
        << " s, so dt = " << safe << " s is safe (or integrator \"sdirk3\" keeps this dt)";
  } else {
    msg << " (e.g. dt = " << config_.dt / 4 << " s; the highest linearised frequency " << omega
        << " rad/s allows this dt, so the cause is the motion, not stability)";
  }
  if (!config_.stabilisation.enabled) msg << " or enable stabilisation";
  throw ModelError(msg.str());
}

}  // namespace tbridge
