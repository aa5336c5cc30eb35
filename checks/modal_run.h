// The dynamic check's walking load by modal superposition, in the mode-acceleration form:
//
//   F(t) = sum_k w_k(t) P_k      (P_k: the point load standing at deck station k; w_k its
//                                 lever-rule share, a hat from the station before to the next,
//                                 spread over the load's contact length: LoadShape)
//   force_j(t) = QS_j(t) + sum_i S_ij e_i(t),   e_i = q_i - F_i / omega_i^2,
//
// QS the quasi-static response, exact and nonlinear at each station (a static solve with P_k
// standing) and interpolated between them by the same shares w_k; q_i the modal coordinate of
// mode i (mass-normalised shape phi_i, F_i = phi_i . F) and e_i its dynamic excess over the
// quasi-static response, e_i'' + omega_i^2 e_i = -F_i'' / omega_i^2; S_ij the force change in
// member j per unit of q_i: the static response to the load omega_i^2 M phi_i, whose
// displacement is phi_i (statics/static_solve.h's tangent, with the bars' forces from
// equilibrium). A point load's F is linear in t between station times, and at each its slope
// changes by dS at once: de_i/dt jumps by -dS / omega_i^2, and every mode rings on, undamped,
// with an amplitude falling only as 1 / omega_i^3. A load spread over its contact length c
// (loads.travelling_contact_length_m) turns that corner over tau = c / v, F_i'' = dS / tau
// there: e_i turns as a free oscillator about -F_i'' / omega_i^4, exactly, and a mode with
// omega_i tau >> 1 is left ringing at a fraction of about 2 / (omega_i tau) of the point
// load's (the 10 cm of EN 1991-2's Q_fwk at walking pace: 1/20 at 100 Hz). The modes kept are
// those below a cutoff frequency: a mode far above the load's corners answers
// quasi-statically, and its quasi-static part is in QS, exactly. The response is sampled at
// every station time (where QS peaks) and on a grid of 1/20 of the highest kept mode's period.
//
// The excess comes from the model linearised about the run's start (the bridge at rest under
// its standing loads, dynamics/modal.h), so the run is done only where the bridge is close to
// linear over the load (ModalRunOptions::max_nonlinearity: its deck's linear response to each
// station's load against the nonlinear one) and no string that must stay taut goes slack (at a
// station or in the response). A string that may go slack does so in the quasi-static part
// exactly, and its tension is read as at least 0; the excess sees it taut, an error the
// nonlinearity measure includes (the deck's linear response is the taut one too). Where the
// run is not done, the caller runs the nonlinear model instead (checks/dynamic_check.h).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "checks/load_scenarios.h"
#include "design/design.h"
#include "dynamics/model.h"
#include "dynamics/run_summary.h"
#include "statics/static_solve.h"

namespace tbridge {

// The quasi-static responses the run interpolates: at rest under the standing loads, and with
// the point load at each station in turn (nonlinear static solves).
struct StationResponses {
  Eigen::VectorXd standing_forces;      // [C_bars; T_strings] [N]
  Eigen::VectorXd standing_deck_y;      // vertical position of each deck node [m]
  std::vector<Eigen::VectorXd> forces;  // per station [N]
  std::vector<Eigen::VectorXd> deck_y;  // per station [m]
  // Per reaction group of the model (its abutments): the reaction standing and per station [N].
  std::vector<Eigen::Vector3d> standing_reactions;
  std::vector<std::vector<Eigen::Vector3d>> reactions;
  // Per station: the point load alone, at the nodes it loads (their forces, 3 x nodes [N]).
  std::vector<std::vector<int>> load_nodes;
  std::vector<Eigen::Matrix3Xd> load_forces;
  std::vector<double> time_s;  // per station: when the load's centre stands there [s]
  Crossing crossing;           // the load's crossing: its supports' times, spread and duration
};

// The static responses of `force_n` crossing the deck of `d` as `crossing` says (stations in
// the order the deck is crossed), on the standing loads of `model`, solved nonlinearly by
// `statics`, each from the last station's equilibrium (StaticSeries, statics/static_solve.h)
// in two lanes: the first half of the stations after the standing loads, the second from the
// reference state. One station's loads at a time per lane (O(n_n) memory for the loads
// whatever the number of stations). `standing` gets the state at rest; `converged` is false
// when a solve did not converge (its station then keeps the standing response).
StationResponses MovingLoadStations(const Design& d, const DynamicModel& model,
                                    const StaticModel& statics, double force_n,
                                    const Crossing& crossing, StaticState& standing,
                                    bool& converged);

struct ModalRunOptions {
  double cutoff_hz = 0;  // the modes kept: those at or below this frequency (> 0)
  // The largest nonlinearity (ModalRunResult::nonlinearity) the run is done at.
  double max_nonlinearity = 0.03;
  // Per string: whether it may go slack (the design's strings that need not stay taut); the
  // others hand the run over where they would.
  std::vector<char> may_go_slack;
};

struct ModalRunResult {
  bool done = false;
  std::string note;            // why not done (a string changing state, a model mismatch)
  int modes = 0;               // modes kept
  double highest_mode_hz = 0;  // the highest mode kept
  double sample_dt_s = 0;      // the grid step
  long samples = 0;
  // The largest difference of the deck's linear (tangent) response to a station's load from
  // its nonlinear one, over the largest nonlinear response.
  double nonlinearity = 0;
  // As the nonlinear run reports them (dynamics/run_summary.h).
  std::vector<double> peak_bar_compression, peak_string_tension, min_string_strain;
  // The stations' (nonlinear, at their own geometry) plus the excess's, at the model's positions.
  std::vector<ReactionPeak> peak_reactions;
  double peak_deck_displacement_m = 0;  // largest vertical deck displacement from the start
};

// The options the dynamic check runs with: the design's loads.dynamic_modal_cutoff_hz and
// loads.dynamic_modal_max_nonlinearity, and its strings that need not stay taut (MustStayTaut).
ModalRunOptions ModalRunOptionsOf(const Design& d);

// Runs the walking load on `model` (at rest at its positions under model.loads) with the
// static responses `stations` of `statics` about `standing` (the same bridge, the same
// standing loads). Throws ModelError only for inconsistent sizes.
ModalRunResult RunModalMovingLoad(const DynamicModel& model, const StaticModel& statics,
                                  const StaticState& standing, const StationResponses& stations,
                                  const ModalRunOptions& options);

}  // namespace tbridge
