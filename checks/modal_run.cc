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

// The march over the stations' segments, each in steps of out.sample_dt_s: the quasi-static
// response plus the modes' excess, exact for a load linear in time on each segment. Takes the
// peak member forces into `peak` and `low`, the largest deck displacement into `deck_peak`,
// and the support reactions' peaks and the sample count into `out`.
void MarchModes(const DynamicModel& model, const StationResponses& stations,
                const ModalBasis& basis, const std::vector<Eigen::VectorXd>& force_change_at,
                const std::vector<Eigen::VectorXd>& deck_change_at, ModalRunResult& out,
                Eigen::VectorXd& peak, Eigen::VectorXd& low, double& deck_peak) {
  const int nb = static_cast<int>(model.bars.size()), ns = static_cast<int>(model.strings.size()),
            nm = nb + ns;
  const int count = static_cast<int>(stations.forces.size());
  const int n_deck = static_cast<int>(model.deck_nodes.size());
  const int m = static_cast<int>(basis.omega.size());
  // The march. Segment s runs from station s - 1 to station s (station -1: the start at the
  // first support; station `count`: the end at the second), the load shared between the two.
  const Eigen::ArrayXd omega = basis.omega.array(), omega_sq = omega.square();
  Eigen::ArrayXd e = Eigen::ArrayXd::Zero(m), v = Eigen::ArrayXd::Zero(m),
                 slope = Eigen::ArrayXd::Zero(m);
  Eigen::ArrayXd c(m), s(m), e_next(m),
      next_slope(m);  // the march's workspace: it allocates nothing
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
  const auto at_rest = [&model](int node) { return Eigen::Vector3d(model.positions.col(node)); };
  const auto excess_of = [&excess_force](int member) { return excess_force[member]; };
  const Eigen::Vector3d no_load = Eigen::Vector3d::Zero();
  Eigen::VectorXd start_y(n_deck);
  for (int n = 0; n < n_deck; ++n) start_y[n] = model.positions(1, model.deck_nodes[n]);
  const auto time_of = [&](int k) {
    return k < 0 ? 0.0 : k >= count ? stations.duration_s : stations.time_s[k];
  };
  const auto evaluate = [&](int before, double share_after) {
    // QS: the standing response plus each station's change, by its share.
    force = stations.standing_forces;
    deck = stations.standing_deck_y;
    if (before >= 0) {
      force += (1 - share_after) * force_change_at[before];
      deck += (1 - share_after) * deck_change_at[before];
    }
    if (before + 1 < count) {
      force += share_after * force_change_at[before + 1];
      deck += share_after * deck_change_at[before + 1];
    }
    excess_force.noalias() = basis.member.transpose() * e.matrix();
    excess_deck.noalias() = basis.deck.transpose() * e.matrix();
    force += excess_force;
    deck += excess_deck;
    peak = peak.cwiseMax(force);
    low = low.cwiseMin(force);
    for (size_t g = 0; g < groups; ++g) {
      Eigen::Vector3d r = stations.standing_reactions[g];
      if (before >= 0)
        r += (1 - share_after) * (stations.reactions[before][g] - stations.standing_reactions[g]);
      if (before + 1 < count)
        r += share_after * (stations.reactions[before + 1][g] - stations.standing_reactions[g]);
      out.peak_reactions[g].Take(
          r + GroupReaction(model, reaction_ends[g], no_load, at_rest, excess_of));
    }
    deck_peak = std::max(deck_peak, (deck - start_y).cwiseAbs().maxCoeff());
    ++out.samples;
  };
  evaluate(-1, 0.0);
  for (int seg = 0; seg <= count; ++seg) {
    const double t0 = time_of(seg - 1), t1 = time_of(seg), length = t1 - t0;
    if (length <= 0) continue;
    // The modal force's slope on this segment and the jump of de/dt it makes at t0.
    next_slope.setZero();
    if (seg < count) next_slope += basis.station.col(seg).array();
    if (seg > 0) next_slope -= basis.station.col(seg - 1).array();
    next_slope /= length;
    v -= (next_slope - slope) / omega_sq;
    slope = next_slope;
    const int steps = std::max(1, static_cast<int>(std::ceil(length / out.sample_dt_s - 1e-9)));
    const double h = length / steps;
    c = (omega * h).cos();
    s = (omega * h).sin();
    for (int step = 1; step <= steps; ++step) {
      e_next = e * c + v / omega * s;
      v = v * c - e * omega * s;
      e = e_next;
      evaluate(seg - 1, static_cast<double>(step) / steps);
    }
  }
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
                                    const StaticModel& statics, double force_n, double duration_s,
                                    StaticState& standing, bool& converged) {
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
  out.duration_s = duration_s;
  const double span = d.config.bridge.span;
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
    out.time_s.push_back(d.actions.station_x[k] / span * duration_s);
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
