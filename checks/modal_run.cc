#include "checks/modal_run.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/error.h"
#include "core/two_lanes.h"
#include "design/abutments.h"
#include "design/mirror.h"
#include "design/static_model.h"
#include "dynamics/modal.h"
#include "dynamics/node_forces.h"

namespace tbridge {

namespace {

// The modes at or below `cutoff_hz` (at least one): every mode densely where the model is
// small, else the lowest by Lanczos, asking for twice as many until one is above the cutoff.
ModalResult ModesBelow(const DynamicModel& model, double cutoff_hz) {
  ModalOptions options;
  options.highest = false;
  options.count = 24;
  for (;;) {
    ModalResult r = ComputeModes(model, options);
    const bool enough =
        r.all_modes || (!r.modes.empty() && r.modes.back().frequency_hz > cutoff_hz);
    if (enough) {
      size_t keep = 1;
      while (keep < r.modes.size() && r.modes[keep].frequency_hz <= cutoff_hz) ++keep;
      r.modes.resize(std::min(keep, r.modes.size()));
      return r;
    }
    options.count *= 2;
  }
}

// The modal basis restricted to what the run reads.
struct ModalBasis {
  Eigen::VectorXd omega;    // per mode [rad/s]
  Eigen::MatrixXd member;   // modes x members: force change per unit modal coordinate [N]
  Eigen::MatrixXd deck;     // modes x deck nodes: vertical displacement per unit coordinate
  Eigen::MatrixXd station;  // modes x stations: phi_i . P_k [N per unit coordinate]
};

// Whether string `q` may go slack (else it must stay taut).
bool MaySlack(const ModalRunOptions& options, int q) {
  return q < static_cast<int>(options.may_go_slack.size()) && options.may_go_slack[q];
}

// A string that must stay taut and is slack at the start or at a station is a finding the
// nonlinear run measures (its strain). One that may go slack does so in the quasi-static
// response exactly; the excess sees it taut, which the nonlinearity measure bounds. Returns why
// the run cannot go on, or "" when no such string is slack.
std::string TautStringSlackAtStation(const DynamicModel& model, const StationResponses& stations,
                                     const ModalRunOptions& options) {
  const int nb = static_cast<int>(model.bars.size()), ns = static_cast<int>(model.strings.size());
  const int count = static_cast<int>(stations.forces.size());
  for (int q = 0; q < ns; ++q) {
    if (MaySlack(options, q)) continue;
    bool slack = stations.standing_forces[nb + q] <= 0;
    for (int k = 0; k < count && !slack; ++k) slack = stations.forces[k][nb + q] <= 0;
    if (slack)
      return "string " + model.names.string_name[q] +
             ", which must stay taut, is slack at a station";
  }
  return "";
}

// How far the bridge is from linear over the load: the linear tangent's deck response to each
// station's load against the nonlinear solve's, the largest difference over the largest
// nonlinear response.
double Nonlinearity(const DynamicModel& model, const StationResponses& stations,
                    StaticTangent& tangent, const std::vector<Eigen::VectorXd>& deck_change_at) {
  const int count = static_cast<int>(stations.forces.size());
  const int n_deck = static_cast<int>(model.deck_nodes.size());
  double difference = 0, largest = 0;
  Eigen::Matrix3Xd displacement;
  Eigen::VectorXd force_change;
  Eigen::Matrix3Xd station_load = Eigen::Matrix3Xd::Zero(3, model.num_nodes());
  for (int k = 0; k < count; ++k) {
    station_load.setZero();
    for (size_t a = 0; a < stations.load_nodes[k].size(); ++a) {
      station_load.col(stations.load_nodes[k][a]) =
          stations.load_forces[k].col(static_cast<Eigen::Index>(a));
    }
    tangent.Solve(station_load, displacement, force_change);
    for (int n = 0; n < n_deck; ++n) {
      const double nonlinear = deck_change_at[k][n];
      difference = std::max(difference, std::abs(displacement(1, model.deck_nodes[n]) - nonlinear));
      largest = std::max(largest, std::abs(nonlinear));
    }
  }
  return largest > 0 ? difference / largest : 0.0;
}

// The modal basis of `modes`: each mode's member forces by the static tangent under its
// inertia load, its deck heights and its work against each station's load. Returns why the
// basis cannot be formed, or "".
std::string FormModalBasis(const DynamicModel& model, const StationResponses& stations,
                           const ModalResult& modes, StaticTangent& tangent, ModalBasis& basis) {
  const int nb = static_cast<int>(model.bars.size()), ns = static_cast<int>(model.strings.size()),
            nm = nb + ns;
  const int count = static_cast<int>(stations.forces.size());
  const int n_deck = static_cast<int>(model.deck_nodes.size());
  const int m = static_cast<int>(modes.modes.size());
  const LinearisedSystem lin = Linearise(model);

  basis.omega.resize(m);
  basis.member.resize(m, nm);
  basis.deck.resize(m, n_deck);
  basis.station.resize(m, count);
  const int n_dof = static_cast<int>(lin.dof_node.size());
  Eigen::VectorXd shape_dofs(n_dof);
  Eigen::Matrix3Xd load = Eigen::Matrix3Xd::Zero(3, model.num_nodes()), displacement;
  Eigen::VectorXd force_change;
  for (int i = 0; i < m; ++i) {
    const Mode& mode = modes.modes[i];
    basis.omega[i] = mode.omega_rad_s;
    for (int d = 0; d < n_dof; ++d) shape_dofs[d] = mode.shape(lin.dof_axis[d], lin.dof_node[d]);
    const Eigen::VectorXd inertia = mode.omega_squared * (lin.mass * shape_dofs);
    load.setZero();
    for (int d = 0; d < n_dof; ++d) load(lin.dof_axis[d], lin.dof_node[d]) = inertia[d];
    tangent.Solve(load, displacement, force_change);
    // The static response to omega^2 M phi is phi itself when the static and dynamic models
    // are one bridge (the same geometry, stiffness and bar forces): 1e-6 of the shape allows the
    // two equilibria's solver tolerances (1e-10 of the forces) and stops a mismatch.
    const double size = mode.shape.cwiseAbs().maxCoeff();
    if ((displacement - mode.shape).cwiseAbs().maxCoeff() > 1e-6 * size) {
      std::ostringstream os;
      os << "the static tangent does not reproduce mode " << i + 1 << " (" << mode.frequency_hz
         << " Hz): the static and dynamic models differ";
      return os.str();
    }
    basis.member.row(i) = force_change.transpose();
    for (int n = 0; n < n_deck; ++n) basis.deck(i, n) = mode.shape(1, model.deck_nodes[n]);
    for (int k = 0; k < count; ++k) {
      double work = 0;
      for (size_t a = 0; a < stations.load_nodes[k].size(); ++a) {
        work += mode.shape.col(stations.load_nodes[k][a])
                    .dot(stations.load_forces[k].col(static_cast<Eigen::Index>(a)));
      }
      basis.station(i, k) = work;
    }
  }
  return "";
}

// The modal force's corners: F is linear in t between knots (the load's centre at the first
// support, at each station, at the second support), and at knot j its slope changes by
// `slope_change[j]` (per mode). A spread load turns each corner over the crossing's spread
// (Crossing::SpreadS) about it.
struct ModalCorners {
  std::vector<double> time;                  // per knot [s]
  std::vector<Eigen::ArrayXd> slope_change;  // per knot, per mode [N/s per unit coordinate]
};

ModalCorners CornersOf(const StationResponses& stations, const ModalBasis& basis) {
  const int count = static_cast<int>(stations.time_s.size());
  const int m = static_cast<int>(basis.omega.size());
  ModalCorners c;
  std::vector<Eigen::ArrayXd> value;  // F at each knot, per mode
  const auto add_knot = [&](double t, const Eigen::ArrayXd& f) {
    // Knots at one time (a station at a support) keep the later value: F steps there, which
    // the march does not see (as a load's sudden arrival it is the quasi-static part's).
    if (!c.time.empty() && t <= c.time.back()) {
      value.back() = f;
      return;
    }
    c.time.push_back(t);
    value.push_back(f);
  };
  add_knot(stations.crossing.TimeAtS(0.0), Eigen::ArrayXd::Zero(m));
  for (int k = 0; k < count; ++k) add_knot(stations.time_s[k], basis.station.col(k).array());
  add_knot(stations.crossing.TimeAtS(stations.crossing.span_m), Eigen::ArrayXd::Zero(m));
  Eigen::ArrayXd slope = Eigen::ArrayXd::Zero(m), next(m);
  for (size_t j = 0; j < c.time.size(); ++j) {
    if (j + 1 < c.time.size()) {
      next = (value[j + 1] - value[j]) / (c.time[j + 1] - c.time[j]);
    } else {
      next.setZero();
    }
    c.slope_change.push_back(next - slope);
    slope = next;
  }
  return c;
}

// The times the march stops at, in order, and what happens there: a knot's corner (all at once
// with no spread: de/dt jumps by -dS / omega^2), a spread corner starting (d2F/dt2 rises by
// dS / spread) or ending (falls by it), or a station time, where the quasi-static response
// peaks (sampled, nothing changes).
struct MarchMark {
  double t;
  int knot;  // the corner's knot (ModalCorners), or -1: a station time
  enum class Kind { kCorner, kSpreadStart, kSpreadEnd, kStation } kind;
};

std::vector<MarchMark> MarksOf(const StationResponses& stations, const ModalCorners& corners) {
  std::vector<MarchMark> marks;
  const double spread = stations.crossing.SpreadS();
  for (size_t j = 0; j < corners.time.size(); ++j) {
    const int knot = static_cast<int>(j);
    const double t = corners.time[j];
    if (spread > 0) {
      marks.push_back({t - 0.5 * spread, knot, MarchMark::Kind::kSpreadStart});
      marks.push_back({t + 0.5 * spread, knot, MarchMark::Kind::kSpreadEnd});
    } else {
      marks.push_back({t, knot, MarchMark::Kind::kCorner});
    }
  }
  for (const double t : stations.time_s) marks.push_back({t, -1, MarchMark::Kind::kStation});
  std::stable_sort(marks.begin(), marks.end(),
                   [](const MarchMark& a, const MarchMark& b) { return a.t < b.t; });
  return marks;
}

// The quasi-static response at time t: the standing response plus each station's change by
// its share of the load then (LoadShape of its lever-rule ramps, spread as the load is), the
// same share the nonlinear run's loads take (checks/load_scenarios.h). Asked at times in
// order: it keeps the first station whose share is not over.
class QuasiStatic {
 public:
  QuasiStatic(const StationResponses& stations, const std::vector<Eigen::VectorXd>& force_change_at,
              const std::vector<Eigen::VectorXd>& deck_change_at, size_t groups)
      : s_(stations),
        force_change_(force_change_at),
        deck_change_(deck_change_at),
        groups_(groups) {}

  void At(double t, Eigen::VectorXd& force, Eigen::VectorXd& deck,
          std::vector<Eigen::Vector3d>& reaction) {
    const int count = static_cast<int>(s_.time_s.size());
    const double spread = s_.crossing.SpreadS(), half = 0.5 * spread;
    force = s_.standing_forces;
    deck = s_.standing_deck_y;
    reaction.assign(s_.standing_reactions.begin(),
                    s_.standing_reactions.begin() + static_cast<std::ptrdiff_t>(groups_));
    while (first_ < count && t >= Knot(first_ + 1) + half) ++first_;
    for (int k = first_; k < count && Knot(k - 1) - half < t; ++k) {
      const double before = Knot(k - 1), at = Knot(k), after = Knot(k + 1);
      const double w = LoadShape(t, before, after, at - before, after - at, spread);
      if (w == 0) continue;
      force += w * force_change_[k];
      deck += w * deck_change_[k];
      for (size_t g = 0; g < groups_; ++g)
        reaction[g] += w * (s_.reactions[k][g] - s_.standing_reactions[g]);
    }
  }

 private:
  // Station k's time; k = -1 and k = count: the supports'.
  double Knot(int k) const {
    const int count = static_cast<int>(s_.time_s.size());
    if (k < 0) return s_.crossing.TimeAtS(0.0);
    return k >= count ? s_.crossing.TimeAtS(s_.crossing.span_m) : s_.time_s[k];
  }
  const StationResponses& s_;
  const std::vector<Eigen::VectorXd>& force_change_;
  const std::vector<Eigen::VectorXd>& deck_change_;
  size_t groups_;
  int first_ = 0;
};

// The march in steps of at most out.sample_dt_s between the marks (MarksOf): the quasi-static
// response plus the modes' excess e, exact for the modal force F piecewise quadratic in t. With
// F'' = g constant between two marks, e'' + omega^2 e = -g / omega^2: e turns about
// -g / omega^4 as a free undamped oscillator. Takes the peak member forces into `peak` and
// `low`, the largest deck displacement into `deck_peak`, and the support reactions' peaks and
// the sample count into `out`.
void MarchModes(const DynamicModel& model, const StationResponses& stations,
                const ModalBasis& basis, const std::vector<Eigen::VectorXd>& force_change_at,
                const std::vector<Eigen::VectorXd>& deck_change_at, ModalRunResult& out,
                Eigen::VectorXd& peak, Eigen::VectorXd& low, double& deck_peak) {
  const int nm = static_cast<int>(model.bars.size() + model.strings.size());
  const int count = static_cast<int>(stations.forces.size());
  const int n_deck = static_cast<int>(model.deck_nodes.size());
  const int m = static_cast<int>(basis.omega.size());
  const ModalCorners corners = CornersOf(stations, basis);
  const std::vector<MarchMark> marks = MarksOf(stations, corners);
  const Eigen::ArrayXd omega = basis.omega.array(), omega_sq = omega.square(),
                       omega_4 = omega_sq.square();
  // The march's state and workspace: it allocates nothing as it goes.
  Eigen::ArrayXd e = Eigen::ArrayXd::Zero(m), v = Eigen::ArrayXd::Zero(m),
                 g = Eigen::ArrayXd::Zero(m), centre = Eigen::ArrayXd::Zero(m);
  Eigen::ArrayXd c(m), s(m), e_next(m), y(m);
  Eigen::VectorXd force(nm), deck(n_deck), excess_force(nm), excess_deck(n_deck);
  // The support reactions: the stations' own (nonlinear, at their geometry: the deck chain's
  // turn at the support carries a share of the load) by the load's share, as the forces, plus
  // the dynamic excess's, linear in its member forces at the model's positions (its own turn is
  // the excess's share of the deck's, ~1 % of the stations').
  const std::vector<std::vector<ReactionEnd>> reaction_ends = ReactionEnds(model);
  const size_t groups = static_cast<int>(stations.reactions.size()) == count
                            ? std::min(reaction_ends.size(), stations.standing_reactions.size())
                            : 0;
  out.peak_reactions.assign(groups, ReactionPeak{});
  std::vector<Eigen::Vector3d> reaction;
  const auto at_rest = [&model](int node) { return Eigen::Vector3d(model.positions.col(node)); };
  const auto excess_of = [&excess_force](int member) { return excess_force[member]; };
  const Eigen::Vector3d no_load = Eigen::Vector3d::Zero();
  Eigen::VectorXd start_y(n_deck);
  for (int n = 0; n < n_deck; ++n) start_y[n] = model.positions(1, model.deck_nodes[n]);
  QuasiStatic quasi_static(stations, force_change_at, deck_change_at, groups);
  const auto evaluate = [&](double t) {
    quasi_static.At(t, force, deck, reaction);
    excess_force.noalias() = basis.member.transpose() * e.matrix();
    excess_deck.noalias() = basis.deck.transpose() * e.matrix();
    force += excess_force;
    deck += excess_deck;
    peak = peak.cwiseMax(force);
    low = low.cwiseMin(force);
    for (size_t k = 0; k < groups; ++k)
      out.peak_reactions[k].Take(
          reaction[k] + GroupReaction(model, reaction_ends[k], no_load, at_rest, excess_of));
    deck_peak = std::max(deck_peak, (deck - start_y).cwiseAbs().maxCoeff());
    ++out.samples;
  };
  const auto march_to = [&](double t0, double t1) {
    const double length = t1 - t0;
    if (length <= 0) return;
    const int steps = std::max(1, static_cast<int>(std::ceil(length / out.sample_dt_s - 1e-9)));
    const double h = length / steps;
    c = (omega * h).cos();
    s = (omega * h).sin();
    for (int step = 1; step <= steps; ++step) {
      y = e - centre;
      e_next = centre + y * c + v / omega * s;
      v = v * c - y * omega * s;
      e = e_next;
      evaluate(step == steps ? t1 : t0 + step * h);
    }
  };
  evaluate(0.0);
  double t = 0;
  for (const MarchMark& mark : marks) {
    const double at = std::min(mark.t, stations.crossing.DurationS());
    march_to(t, at);
    t = std::max(t, at);
    if (mark.knot < 0) continue;
    const Eigen::ArrayXd& change = corners.slope_change[static_cast<size_t>(mark.knot)];
    if (mark.kind == MarchMark::Kind::kCorner) {
      v -= change / omega_sq;
    } else {
      g += (mark.kind == MarchMark::Kind::kSpreadStart ? 1.0 : -1.0) / stations.crossing.SpreadS() *
           change;
      centre = -g / omega_4;
    }
  }
  march_to(t, stations.crossing.DurationS());
}

}  // namespace

ModalRunOptions ModalRunOptionsOf(const Design& d) {
  ModalRunOptions options;
  options.cutoff_hz = d.config.loads.dynamic_modal_cutoff_hz;
  options.max_nonlinearity = d.config.loads.dynamic_modal_max_nonlinearity;
  for (int q = 0; q < d.topology.structure.num_strings(); ++q)
    options.may_go_slack.push_back(!MustStayTaut(d, q));
  return options;
}

StationResponses MovingLoadStations(const Design& d, const DynamicModel& model,
                                    const StaticModel& statics, double force_n,
                                    const Crossing& crossing, StaticState& standing,
                                    bool& converged) {
  const StaticState start = ReferenceState(statics, d);
  StationResponses out;
  const int n_deck = static_cast<int>(model.deck_nodes.size());
  const auto deck_y = [&](const StaticState& state) {
    Eigen::VectorXd y(n_deck);
    for (int n = 0; n < n_deck; ++n) y[n] = state.nodes(1, model.deck_nodes[n]);
    return y;
  };
  const auto forces = [](const StaticState& state) {
    Eigen::VectorXd f(state.bar_compression.size() + state.string_tension.size());
    f << state.bar_compression, state.string_tension;
    return f;
  };
  const auto reactions = [&model](const StaticState& state) {
    std::vector<Eigen::Vector3d> sums;
    for (const std::vector<int>& group : model.reaction_groups) {
      const AbutmentReaction r = ReactionOf(Abutment{group, 0.0}, state.reactions);
      sums.emplace_back(r.x, r.y, r.z);
    }
    return sums;
  };
  // The standing loads, then each station from the last one's equilibrium (StaticSeries): its
  // load differs by one station's step. In two lanes (core/two_lanes.h): the standing loads
  // and the first half of the stations, and the second half from the reference state. On a
  // symmetric bridge only the stations up to mid-span are solved: the response at the others
  // is the mirror image of their images' (MidSpanMirror).
  const int stations = static_cast<int>(d.actions.station_nodes.size());
  const std::optional<StationMirror> mirror =
      MidSpanMirror(statics, start, model.loads, d.actions, d.config.bridge.span);
  std::vector<int> solved;
  for (int k = 0; k < stations; ++k) {
    if (!mirror || mirror->station_image[static_cast<size_t>(k)] >= k) solved.push_back(k);
  }
  const int half = (static_cast<int>(solved.size()) + 1) / 2;
  StaticResult at_rest;
  std::vector<StaticResult> at(static_cast<size_t>(stations));
  std::atomic<bool> stop{false};
  const auto run_lane = [&](int first, int last, bool standing_first) {
    StaticSeries series(statics, start, d.loads);
    if (standing_first) at_rest = series.Solve(model.loads);
    Eigen::Matrix3Xd loads = model.loads;
    for (int i = first; i < last && !stop; ++i) {
      const int k = solved[static_cast<size_t>(i)];
      d.actions.AddStationLoad(k, force_n, loads);
      at[k] = series.Solve(loads);
      for (const int node : d.actions.station_nodes[k]) loads.col(node) = model.loads.col(node);
    }
  };
  InTwoLanes([&] { run_lane(half, static_cast<int>(solved.size()), false); },
             [&] {
               try {
                 run_lane(0, half, true);
               } catch (...) {
                 stop = true;
                 throw;
               }
             });
  for (int k = 0; k < stations && mirror; ++k) {
    const int image = mirror->station_image[static_cast<size_t>(k)];
    if (image >= k) continue;
    at[k] = mirror->mirror.Of(at[image]);
  }
  converged = at_rest.converged;
  standing = at_rest.state;
  out.standing_forces = forces(standing);
  out.standing_deck_y = deck_y(standing);
  out.standing_reactions = reactions(standing);
  out.crossing = crossing;
  Eigen::Matrix3Xd loads = model.loads;
  for (int k = 0; k < stations; ++k) {
    const std::vector<int>& nodes = d.actions.station_nodes[k];
    d.actions.AddStationLoad(k, force_n, loads);
    Eigen::Matrix3Xd alone(3, static_cast<Eigen::Index>(nodes.size()));
    for (size_t a = 0; a < nodes.size(); ++a) {
      alone.col(static_cast<Eigen::Index>(a)) = loads.col(nodes[a]) - model.loads.col(nodes[a]);
      loads.col(nodes[a]) = model.loads.col(nodes[a]);
    }
    const StaticResult& r = at[k];
    converged = converged && r.converged;
    out.forces.push_back(r.converged ? forces(r.state) : out.standing_forces);
    out.deck_y.push_back(r.converged ? deck_y(r.state) : out.standing_deck_y);
    out.reactions.push_back(r.converged ? reactions(r.state) : out.standing_reactions);
    out.load_nodes.push_back(nodes);
    out.load_forces.push_back(std::move(alone));
    out.time_s.push_back(crossing.TimeAtS(d.actions.station_x[k]));
  }
  return out;
}

ModalRunResult RunModalMovingLoad(const DynamicModel& model, const StaticModel& statics,
                                  const StaticState& standing, const StationResponses& stations,
                                  const ModalRunOptions& options) {
  ModalRunResult out;
  const int nb = static_cast<int>(model.bars.size()), ns = static_cast<int>(model.strings.size()),
            nm = nb + ns;
  const int count = static_cast<int>(stations.forces.size());
  const int n_deck = static_cast<int>(model.deck_nodes.size());
  if (stations.standing_forces.size() != nm || static_cast<int>(stations.time_s.size()) != count ||
      static_cast<int>(stations.load_nodes.size()) != count ||
      static_cast<int>(stations.load_forces.size()) != count ||
      static_cast<int>(stations.deck_y.size()) != count ||
      stations.standing_deck_y.size() != n_deck) {
    throw ModelError("modal run: station responses sized unlike the model");
  }
  const auto not_done = [&out](const std::string& why) {
    out.note = why;
    return out;
  };
  if (model.mass_damping_per_s != 0 ||
      std::any_of(model.strings.damping.begin(), model.strings.damping.end(),
                  [](double c) { return c != 0; })) {
    return not_done("the model is damped (the modal run is of the undamped model)");
  }
  if (const std::string why = TautStringSlackAtStation(model, stations, options); !why.empty())
    return not_done(why);

  StaticTangent tangent(statics, standing);
  if (!tangent.ok()) return not_done("the static tangent at the start did not factorise");
  // Each station's change from the standing response (forces, then deck heights), formed once.
  std::vector<Eigen::VectorXd> force_change_at(count), deck_change_at(count);
  for (int k = 0; k < count; ++k) {
    force_change_at[k] = stations.forces[k] - stations.standing_forces;
    deck_change_at[k] = stations.deck_y[k] - stations.standing_deck_y;
  }
  out.nonlinearity = Nonlinearity(model, stations, tangent, deck_change_at);
  if (out.nonlinearity > options.max_nonlinearity) {
    std::ostringstream os;
    os << "the bridge is not linear enough over the load: its linear deck response differs from "
          "the nonlinear one by "
       << out.nonlinearity << " of the largest, over " << options.max_nonlinearity;
    return not_done(os.str());
  }
  const ModalResult modes = ModesBelow(model, options.cutoff_hz);
  for (const Mode& mode : modes.modes) {
    if (mode.omega_squared <= 0)
      return not_done("the linearised model has a mode of zero or negative stiffness");
  }
  ModalBasis basis;
  if (const std::string why = FormModalBasis(model, stations, modes, tangent, basis); !why.empty())
    return not_done(why);
  out.modes = static_cast<int>(modes.modes.size());
  out.highest_mode_hz = modes.modes.back().frequency_hz;
  // 20 samples per period of the highest mode kept: its peak is read within 1 - cos(pi / 20)
  // = 1.2 % of its own amplitude, a small part of the excess, which is a small part of the force.
  out.sample_dt_s = 1.0 / (20.0 * out.highest_mode_hz);

  Eigen::VectorXd peak = Eigen::VectorXd::Constant(nm, -std::numeric_limits<double>::infinity());
  Eigen::VectorXd low = Eigen::VectorXd::Constant(nm, std::numeric_limits<double>::infinity());
  double deck_peak = 0;
  MarchModes(model, stations, basis, force_change_at, deck_change_at, out, peak, low, deck_peak);

  for (int q = 0; q < ns; ++q) {
    if (low[nb + q] <= 0 && !MaySlack(options, q)) {
      return not_done("string " + model.names.string_name[q] +
                      ", which must stay taut, goes slack in the response");
    }
  }
  out.peak_bar_compression.resize(nb);
  for (int b = 0; b < nb; ++b) out.peak_bar_compression[b] = std::max(peak[b], 0.0);
  out.peak_string_tension.resize(ns);
  out.min_string_strain.resize(ns);
  for (int q = 0; q < ns; ++q) {
    out.peak_string_tension[q] = std::max(peak[nb + q], 0.0);
    out.min_string_strain[q] =
        low[nb + q] / (model.strings.stiffness[q] * model.strings.rest_length[q]);
  }
  out.peak_deck_displacement_m = deck_peak;
  out.done = true;
  return out;
}

}  // namespace tbridge
