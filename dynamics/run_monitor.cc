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

RunMonitor::RunMonitor(const DynamicModel& model, const EngineFrame& engine,
                       const DynamicsConfig& config, const Eigen::VectorXd& y0, BarForceProbe probe)
    : model_(model),
      engine_(engine),
      config_(config),
      dim_(model.dim),
      c_(engine.coordinates()),
      probe_(std::move(probe)) {
  const size_t n_s = model.strings.size();
  StringArrays& st = strings_;
  for (size_t k = 0; k < n_s; ++k) {
    const DynamicString& s = model.strings[k];
    const double area = model.strings.area[k];
    st.oi.push_back(s.i * dim_);
    st.oj.push_back(s.j * dim_);
    st.rest.push_back(s.rest_length);
    st.rest_sq.push_back(s.rest_length * s.rest_length);
    st.inv_rest_sq.push_back(1.0 / (s.rest_length * s.rest_length));
    st.k.push_back(s.stiffness);
    st.c.push_back(s.damping);
    st.inv_area.push_back(area > 0 ? 1.0 / area : 0.0);
  }
  for (const DynamicBar& b : model.bars)
    bars_.push_back({b.i * dim_, b.j * dim_, 1.0 / (b.length * b.length)});
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
    TimedLoadState s{(l.node - 1) * dim_, l.t_start, l.t_end,  l.rise_s, l.fall_s,
                     l.spread_s,          {0, 0, 0}, {0, 0, 0}};
    for (int d = 0; d < dim_; ++d) {
      s.force[d] = l.force[d];
      s.last[d] = x0_(s.o + d);
    }
    timed_.push_back(s);
  }
  // The geometry at the start: the strings no engine evaluates (both ends pinned) keep it.
  len2_.assign(n_s, 0.0);
  inv_len_.assign(n_s, 0.0);
  rate_.assign(n_s, 0.0);
  geometry_ = {len2_.data(), inv_len_.data(), rate_.data()};
  if (dim_ == 2) {
    FillGeometry<2, true>(y0.data());
  } else {
    FillGeometry<3, true>(y0.data());
  }
  taut_.assign(n_s, 0.0);
  taut_at_start_.assign(n_s, 0);
  for (size_t k = 0; k < n_s; ++k) {  // the start's slack strings are not transitions
    taut_[k] = len2_[k] >= st.rest_sq[k] ? 1.0 : 0.0;
    taut_at_start_[k] = taut_[k] != 0;
    if (!taut_at_start_[k]) ++summary_.slack.slack_at_start;
  }
  transitions_.assign(n_s, 0.0);
  energy_.assign(n_s, 0.0);
  stress_.assign(n_s, 0.0);
  min_ratio_sq_.assign(n_s, std::numeric_limits<double>::infinity());
  summary_.peak_string_tension.assign(n_s, 0.0);
  if (probe_) {
    lambda_.setZero(static_cast<Eigen::Index>(model.bars.size()));
    summary_.peak_bar_compression.assign(model.bars.size(), 0.0);
    summary_.peak_bar_tension.assign(model.bars.size(), 0.0);
    reaction_ends_ = ReactionEnds(model);
    reaction_loads_ = ReactionGroupLoads(model);
    summary_.peak_reactions.assign(reaction_ends_.size(), ReactionPeak{});
  }
  summary_.allowed_stress = model.allowed_stress;
  double kinetic = 0, elastic = 0;
  Measure(0.0, 0.0, y0.data(), true, kinetic, elastic);  // the geometry at y0: filled above
  auto& e = summary_.energy;
  e.kinetic_start = e.kinetic_end = kinetic;
  e.elastic_start = e.elastic_end = elastic;
  e.reference = std::max(kinetic + elastic, 1e-12);
  h0_ = kinetic + elastic;
}

void RunMonitor::Accept(long step, double t_old, double t, const double* y, double dissipated,
                        bool strings_recorded) {
  // The state's sum finds a NaN or an infinity anywhere in it (they propagate through it), and
  // the work of the constant loads is W . (x - x0), when there are any: Eigen's reductions,
  // which run in vector registers.
  const Eigen::Map<const Eigen::VectorXd> state(y, 2 * static_cast<Eigen::Index>(c_));
  if (!std::isfinite(state.sum())) Fail(step, t, "a node position or velocity is not finite");
  const double load_dot_x = has_loads_ ? loads_.dot(state.head(c_)) : 0.0;
  double kinetic = 0, elastic = 0;
  Measure(t, 0.5 * (t_old + t), y, strings_recorded, kinetic, elastic);
  auto& e = summary_.energy;
  e.dissipated += dissipated;
  // Work of the loads: constant loads exactly, W . (x - x0), from the pass above; each timed load
  // by its force times the displacement of its node over the part of the step it acts in
  // (exact, since the driver holds the loads constant over a step; a ramp's force is taken at
  // the middle of that part).
  const double work = load_dot_x - loads_dot_x0_;
  for (TimedLoadState& l : timed_) {
    const LoadInterval active = LoadActive(l.t_start, l.t_end, l.spread_s);
    const double overlap = std::min(t, active.last) - std::max(t_old, active.first);
    if (overlap > 0) {
      const double mid = std::max(t_old, active.first) + 0.5 * overlap;
      const double shape = LoadShape(mid, l.t_start, l.t_end, l.rise_s, l.fall_s, l.spread_s);
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
    const double error =
        std::max(std::sqrt(bar_ratio_sq_max_) - 1.0, 1.0 - std::sqrt(bar_ratio_sq_min_));
    std::ostringstream what;
    what << "the bar-length error " << error
         << " exceeds guard.max_bar_length_error = " << config_.guard.max_bar_length_error;
    Fail(step, t, what.str());
  }
  if (drift > config_.guard.max_energy_growth) {
    std::ostringstream what;
    what << "the energy grew by " << drift
         << " of its initial value (guard.max_energy_growth = " << config_.guard.max_energy_growth
         << ")";
    Fail(step, t, what.str());
  }
}

template <int Dim, bool Damped>
void RunMonitor::FillGeometry(const double* y) {
  const double* x = y;
  const double* v = y + c_;
  for (size_t k = 0; k < strings_.oi.size(); ++k) {
    const int oi = strings_.oi[k], oj = strings_.oj[k];
    double len2 = 0, rate = 0;
    for (int d = 0; d < Dim; ++d) {
      const double dx = x[oj + d] - x[oi + d];
      len2 += dx * dx;
      if constexpr (Damped) rate += dx * (v[oj + d] - v[oi + d]);
    }
    len2_[k] = len2;
    inv_len_[k] = 1.0 / std::sqrt(len2);
    if constexpr (Damped) rate_[k] = rate;
  }
}

template <bool Damped>
void RunMonitor::MeasureStrings(double t, double& elastic) {
  // CAUTION: performance-sensitive: every accepted step of every run passes here. One pass
  // with no branch and no sum across strings, which the compiler turns into vector
  // instructions (two strings at a time with SSE2): the slack test is a factor of 0 or 1, the
  // counts are doubles, and the elastic energy and the stress are stored per string and
  // reduced after (a sum in the loop would keep it scalar).
  const size_t n_s = strings_.oi.size();
  const double* len2 = len2_.data();
  const double* inv_len = inv_len_.data();
  const double* rate = rate_.data();
  const double* rest = strings_.rest.data();
  const double* rest_sq = strings_.rest_sq.data();
  const double* inv_rest_sq = strings_.inv_rest_sq.data();
  const double* stiffness = strings_.k.data();
  const double* damping = strings_.c.data();
  const double* inv_area = strings_.inv_area.data();
  double* min_ratio_sq = min_ratio_sq_.data();
  double* peak = summary_.peak_string_tension.data();
  double* taut_now = taut_.data();
  double* transitions = transitions_.data();
  double* energy = energy_.data();
  double* stress = stress_.data();
  // The arrays are distinct: the compiler would otherwise version the loop on every pair.
#if defined(__clang__)
#pragma clang loop vectorize(assume_safety)
#elif defined(__GNUC__)
#pragma GCC ivdep
#endif
  for (size_t k = 0; k < n_s; ++k) {
    min_ratio_sq[k] = std::min(min_ratio_sq[k], len2[k] * inv_rest_sq[k]);
    const double taut = len2[k] >= rest_sq[k] ? 1.0 : 0.0;  // a factor, not a branch
    // |s| as s.s / |s|, with 1/|s| as the engines compute it: no square root, no division.
    const double len = len2[k] * inv_len[k];
    const double spring = StringTension(stiffness[k], rest[k], len);
    double tension = spring;
    if constexpr (Damped) tension = std::max(spring + damping[k] * (rate[k] * inv_len[k]), 0.0);
    tension *= taut;
    energy[k] = taut * (0.5 * spring * (len - rest[k]));
    peak[k] = std::max(peak[k], tension);
    stress[k] = tension * inv_area[k];
    transitions[k] += std::abs(taut - taut_now[k]);
    taut_now[k] = taut;
  }
  const Eigen::Map<const Eigen::ArrayXd> energies(energy, static_cast<Eigen::Index>(n_s));
  const Eigen::Map<const Eigen::ArrayXd> stresses(stress, static_cast<Eigen::Index>(n_s));
  elastic += energies.sum();
  if (n_s == 0) return;
  // The largest stress so far, and the first string that reached it.
  const double step_max = stresses.maxCoeff();
  if (step_max > summary_.max_string_stress) {
    summary_.max_string_stress = step_max;
    max_stress_string_ = static_cast<int>(std::find(stress, stress + n_s, step_max) - stress);
    summary_.max_stress_time = t;
  }
}

template <int Dim>
void RunMonitor::MeasureBars(const double* x) {
  double lo = bar_ratio_sq_min_, hi = bar_ratio_sq_max_;  // locals: no store per bar
  for (const PackedBar& b : bars_) {
    double len2 = 0;
    for (int d = 0; d < Dim; ++d) {
      const double db = x[b.oj + d] - x[b.oi + d];
      len2 += db * db;
    }
    const double r = len2 * b.inv_rest_sq;
    lo = std::min(lo, r);
    hi = std::max(hi, r);
  }
  bar_ratio_sq_min_ = lo;
  bar_ratio_sq_max_ = hi;
}

void RunMonitor::Measure(double t, double load_time, const double* y, bool strings_recorded,
                         double& kinetic, double& elastic) {
  const bool damped = engine_.damped();
  if (!strings_recorded) {
    if (dim_ == 2) {
      damped ? FillGeometry<2, true>(y) : FillGeometry<2, false>(y);
    } else {
      damped ? FillGeometry<3, true>(y) : FillGeometry<3, false>(y);
    }
  }
  damped ? MeasureStrings<true>(t, elastic) : MeasureStrings<false>(t, elastic);
  dim_ == 2 ? MeasureBars<2>(y) : MeasureBars<3>(y);
  // The deck's peak displacement in each direction: the largest over the deck nodes, and the
  // first node with it only when that beats the peak so far (no branch per node).
  const size_t n_deck = deck_offsets_.size();
  const auto displacement = [&](size_t n, int d) {
    return std::abs(y[deck_offsets_[n] + d] - deck_rest_[3 * n + d]);
  };
  for (int d = 0; d < dim_; ++d) {
    double largest = 0;
    for (size_t n = 0; n < n_deck; ++n) largest = std::max(largest, displacement(n, d));
    if (largest > summary_.peak_deck_displacement[d]) {
      size_t n = 0;
      while (displacement(n, d) != largest) ++n;
      summary_.peak_deck_displacement[d] = largest;
      summary_.peak_deck_node[d] = model_.deck_nodes[n];
      summary_.peak_deck_time[d] = t;
    }
  }
  if (probe_) {
    probe_(load_time, y, lambda_);
    for (size_t k = 0; k < model_.bars.size(); ++k) {
      const double force =
          lambda_(static_cast<Eigen::Index>(k)) * model_.bars[k].length;  // > 0: compression
      double& peak = force >= 0 ? summary_.peak_bar_compression[k] : summary_.peak_bar_tension[k];
      peak = std::max(peak, std::abs(force));
    }
    if (!reaction_ends_.empty()) MeasureReactions(y);
  }
  kinetic = engine_.KineticEnergy(y);
}

void RunMonitor::MeasureReactions(const double* y) {
  const int nb = static_cast<int>(model_.bars.size());
  const bool damped = engine_.damped();
  const auto position = [this, y](int node) {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int d = 0; d < dim_; ++d) p[d] = y[node * dim_ + d];
    return p;
  };
  // A bar's compression lambda l; a string's tension as MeasureStrings takes it (its damper's
  // share included), from the same geometry.
  const auto force = [&](int member) {
    if (member < nb) return lambda_(member) * model_.bars.length[static_cast<size_t>(member)];
    const size_t k = static_cast<size_t>(member - nb);
    if (len2_[k] < strings_.rest_sq[k]) return 0.0;
    const double spring = StringTension(strings_.k[k], strings_.rest[k], len2_[k] * inv_len_[k]);
    return damped ? std::max(spring + strings_.c[k] * (rate_[k] * inv_len_[k]), 0.0) : spring;
  };
  for (size_t g = 0; g < reaction_ends_.size(); ++g) {
    summary_.peak_reactions[g].Take(
        GroupReaction(model_, reaction_ends_[g], reaction_loads_[g], position, force));
  }
}

void RunMonitor::Finish() {
  SimulationSummary& s = summary_;
  const size_t n_s = strings_.oi.size();
  s.slack.per_string.assign(n_s, 0);
  s.slack.total = s.slack.ever_slack = s.slack.slack_at_end = 0;
  for (size_t k = 0; k < n_s; ++k) {
    s.slack.per_string[k] = static_cast<int>(transitions_[k]);
    s.slack.total += s.slack.per_string[k];
    // Slack at the start, or slack after a transition.
    if (!taut_at_start_[k] || transitions_[k] > 0) ++s.slack.ever_slack;
    if (taut_[k] == 0) ++s.slack.slack_at_end;  // at the last accepted state
  }
  s.min_string_strain.resize(n_s);
  for (size_t k = 0; k < n_s; ++k) s.min_string_strain[k] = std::sqrt(min_ratio_sq_[k]) - 1.0;
  s.max_bar_length_error =
      std::max(std::sqrt(bar_ratio_sq_max_) - 1.0, 1.0 - std::sqrt(bar_ratio_sq_min_));
  if (max_stress_string_ >= 0) s.max_stress_string = model_.names.string_name[max_stress_string_];
  s.stress_exceeds_allowed = s.max_string_stress > s.allowed_stress;
}

void RunMonitor::Fail(long step, double t, const std::string& what) const {
  std::ostringstream msg;
  msg << "the run blew up at step " << step << ", t = " << t << " s: " << what
      << ". Try a smaller dt";
  // A safe dt from the highest linearised frequency: half RK4's limit 2 sqrt(2)/omega_max.
  double omega = 0;
  try {
    if (omega_max_) omega = omega_max_();
  } catch (const std::exception&) {
    omega = 0;  // no advice beats a second failure
  }
  const double safe = 0.5 * Rk4StepLimit(omega);
  if (omega > 0 && safe < config_.dt) {
    msg << ": the highest linearised frequency " << omega << " rad/s makes RK4 stable only below "
        << 2 * safe << " s, so dt = " << safe
        << " s is safe (or integrator \"sdirk3\" keeps this dt)";
  } else {
    msg << " (e.g. dt = " << config_.dt / 4 << " s; the highest linearised frequency " << omega
        << " rad/s allows this dt, so the cause is the motion, not stability)";
  }
  if (!config_.stabilisation.enabled) msg << " or enable stabilisation";
  throw ModelError(msg.str());
}

}  // namespace tbridge
