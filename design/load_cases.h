// The design's load cases: characteristic actions on the nodes of a bridge and their EN 1990
// combinations (loads section, core/config.h).
//
// Member forces are linear in the loads, so a case is a set of coefficients on a few base
// actions (one node-load matrix each) plus, for the travelling loads, a point load that visits
// each deck station in turn. A travelling family is one case per station; its envelope over
// the stations comes from the influence lines (design/case_envelope.h), without forming a
// column per station and case.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "core/config.h"
#include "design/deck.h"
#include "design/topology.h"

namespace tbridge {

enum class LimitState { kUltimate, kServiceability };
const char* LimitStateName(LimitState state);  // "ultimate" | "serviceability"

// The characteristic base actions, in this order. kPaperLoad is the paper's design load as eq. 9
// writes it, f = F_tot / 2^n (deck beams and payload together) on each deck node, so that the
// paper's case gives its loads bit for bit.
enum BaseAction {
  kDeckDead = 0,
  kSelfWeight,
  kPayloadFull,
  kPayloadLeft,
  kPayloadRight,
  kWind,
  kPaperLoad,
  kNumBaseActions
};
const char* BaseActionName(
    int action);  // "G_deck", "G_self", "Q_full", "Q_left", "Q_right", "W", "F_paper"

struct LoadCase;
// The share of the full-span payload that `c` carries (its own, or within the paper's load).
double PayloadShare(const LoadCase& c);

struct LoadCase {
  std::string name;         // "uls_payload_full", "sls_travelling", "paper", ...
  std::string combination;  // "1.35 G + 1.5 Q_full", as an engineer writes it
  LimitState state = LimitState::kUltimate;
  std::array<double, kNumBaseActions> factor{};  // coefficient of each base action
  // A travelling family: `station_load` [N] on each deck station in turn (0 = none).
  double station_load = 0;
  // The factors as a vector over the base actions.
  Eigen::Map<const Eigen::VectorXd> Factors() const { return {factor.data(), kNumBaseActions}; }
};

// Node loads [N] of the base actions (3 x n_n each) and the deck stations a travelling load
// visits. Self-weight is set by the design's fixed point (SelfWeightLoads).
struct Actions {
  std::array<Eigen::Matrix3Xd, kNumBaseActions> base;
  // Per station (in order of x), the deck nodes it loads and each one's share (planes).
  std::vector<std::vector<int>> station_nodes;
  std::vector<double> station_x;  // [m]
  // `load` [N] shared by the nodes of `station`; throws std::out_of_range for a station
  // outside station_nodes.
  Eigen::Matrix3Xd StationLoad(int station, double load) const;
  // Adds StationLoad(station, load) to `loads` (3 x n_n) in place, touching only the
  // station's nodes: a station at a time in O(planes), where StationLoad is O(n_n).
  void AddStationLoad(int station, double load, Eigen::Matrix3Xd& loads) const;
  // The loads of `c` with its travelling load (if any) at `station` (-1: none; else as
  // StationLoad).
  Eigen::Matrix3Xd Loads(const LoadCase& c, int station = -1) const;
};

// The base actions of a bridge; the self-weight matrix starts at zero.
Actions MakeActions(const Config& config, const BridgeTopology& topology, const Deck& deck);

// Half of each member's weight rho A l g at each of its ends, downward [N].
Eigen::Matrix3Xd SelfWeightLoads(const Structure& s, const std::vector<double>& member_mass_kg,
                                 double gravity);

// The cases of config.loads.cases for this bridge, never none: a list that leaves none (only
// "wind" on a planar bridge) throws ConfigError naming loads.cases. `notes` receives what was
// left out and why (wind on a planar bridge).
std::vector<LoadCase> MakeLoadCases(const Config& config, const Deck& deck,
                                    std::vector<std::string>& notes);

}  // namespace tbridge
