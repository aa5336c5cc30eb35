#include "design/load_cases.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>

#include "core/error.h"

namespace tbridge {

const char* LimitStateName(LimitState state) {
  return state == LimitState::kUltimate ? "ultimate" : "serviceability";
}

const char* BaseActionName(int action) {
  static const char* const kNames[kNumBaseActions] = {"G_deck",  "G_self", "Q_full", "Q_left",
                                                      "Q_right", "W",      "F_paper"};
  return kNames[action];
}

double PayloadShare(const LoadCase& c) { return c.factor[kPayloadFull] + c.factor[kPaperLoad]; }

Eigen::Matrix3Xd Actions::StationLoad(int station, double load) const {
  Eigen::Matrix3Xd out = Eigen::Matrix3Xd::Zero(3, base[0].cols());
  AddStationLoad(station, load, out);
  return out;
}

void Actions::AddStationLoad(int station, double load, Eigen::Matrix3Xd& loads) const {
  if (station < 0 || station >= static_cast<int>(station_nodes.size())) {
    throw std::out_of_range("StationLoad: station " + std::to_string(station) + " of " +
                            std::to_string(station_nodes.size()));
  }
  const std::vector<int>& nodes = station_nodes[station];
  for (int v : nodes) loads(1, v) -= load / static_cast<double>(nodes.size());
}

Eigen::Matrix3Xd Actions::Loads(const LoadCase& c, int station) const {
  Eigen::Matrix3Xd out = Eigen::Matrix3Xd::Zero(3, base[0].cols());
  for (int a = 0; a < kNumBaseActions; ++a) {
    if (c.factor[a] != 0) out += c.factor[a] * base[a];
  }
  if (station >= 0 && c.station_load != 0) AddStationLoad(station, c.station_load, out);
  return out;
}

Actions MakeActions(const Config& config, const BridgeTopology& topology, const Deck& deck) {
  const Structure& s = topology.structure;
  const BridgeConfig& b = config.bridge;
  Actions a;
  for (Eigen::Matrix3Xd& m : a.base) m = Eigen::Matrix3Xd::Zero(3, s.num_nodes());
  // Stations: the deck nodes grouped by x (one per plane). Loads per metre become node loads
  // of one section length l_d each (half of each end section goes straight to a support).
  std::map<double, std::vector<int>> by_x;
  for (int v : topology.deck_nodes) {
    const double x = s.nodes(0, v);
    auto it = by_x.lower_bound(x - 1e-9 * b.span);
    if (it != by_x.end() && std::abs(it->first - x) <= 1e-9 * b.span) {
      it->second.push_back(v);
    } else {
      by_x[x].push_back(v);
    }
  }
  const double planes = b.planes;
  const double l_d = deck.section_length;
  const double q = b.payload / b.span;  // payload per metre [N/m]
  for (const auto& [x, nodes] : by_x) {
    a.station_x.push_back(x);
    a.station_nodes.push_back(nodes);
    // Half spans: the station at midspan takes half of its section from each side.
    const double left =
        x < 0.5 * b.span - 1e-9 * b.span ? 1.0 : (x > 0.5 * b.span + 1e-9 * b.span ? 0.0 : 0.5);
    for (int v : nodes) {
      a.base[kDeckDead](1, v) = -(deck.section_mass * config.design.gravity +
                                  config.loads.superimposed_dead_n_per_m * l_d) /
                                planes;
      a.base[kPayloadFull](1, v) = -q * l_d / planes;
      a.base[kPayloadLeft](1, v) = -q * l_d * left / planes;
      a.base[kPayloadRight](1, v) = -q * l_d * (1.0 - left) / planes;
      if (b.planes == 2) a.base[kWind](2, v) = config.loads.wind_n_per_m * l_d / planes;
      a.base[kPaperLoad](1, v) = -deck.node_load;
    }
  }
  return a;
}

Eigen::Matrix3Xd SelfWeightLoads(const Structure& s, const std::vector<double>& mass, double g) {
  Eigen::Matrix3Xd out = Eigen::Matrix3Xd::Zero(3, s.num_nodes());
  const int nb = s.num_bars();
  for (int k = 0; k < nb + s.num_strings(); ++k) {
    const Member& m = s.MemberAt(k);
    const double half = 0.5 * mass[k] * g;
    out(1, m.i) -= half;
    out(1, m.j) -= half;
  }
  return out;
}

namespace {

std::string Factor(double f) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", f);
  return text;
}

}  // namespace

std::vector<LoadCase> MakeLoadCases(const Config& config, const Deck& deck,
                                    std::vector<std::string>& notes) {
  const LoadsConfig& l = config.loads;
  const bool self = config.design.self_weight;
  std::vector<LoadCase> cases;
  // G with factor g (deck, self-weight when on), and its text.
  auto permanent = [self](LoadCase& c, double g) {
    c.factor[kDeckDead] = g;
    c.factor[kSelfWeight] = self ? g : 0.0;
  };
  auto add = [&cases](std::string name, LimitState state, std::string text, const LoadCase& base) {
    LoadCase c = base;
    c.name = std::move(name);
    c.state = state;
    c.combination = std::move(text);
    cases.push_back(c);
  };
  if (l.Asks(LoadFamily::kPaper)) {
    LoadCase c;
    c.factor[kPaperLoad] = 1.0;
    c.factor[kSelfWeight] = self ? 1.0 : 0.0;
    add("paper", LimitState::kUltimate, "G + Q_full (the paper's design load, unfactored)", c);
    return cases;
  }
  const double gs = l.gamma_g_sup, gi = l.gamma_g_inf, gq = l.gamma_q;
  const std::string Gs = Factor(gs) + " G", Gi = Factor(gi) + " G";
  // An ultimate case with unfavourable G, its twin with favourable G (when the factors
  // differ), and the characteristic (serviceability) case.
  auto family = [&](const std::string& name, const std::string& variable_uls,
                    const std::string& variable_sls, LoadCase variable_u, LoadCase variable_s) {
    permanent(variable_u, gs);
    add("uls_" + name, LimitState::kUltimate, Gs + variable_uls, variable_u);
    if (gi != gs) {
      permanent(variable_u, gi);
      add("uls_" + name + "_favourable", LimitState::kUltimate, Gi + variable_uls, variable_u);
    }
    permanent(variable_s, 1.0);
    add("sls_" + name, LimitState::kServiceability, "G" + variable_sls, variable_s);
  };
  if (l.Asks(LoadFamily::kPermanent)) family("permanent", "", "", LoadCase{}, LoadCase{});
  if (l.Asks(LoadFamily::kPayload)) {
    const char* parts[] = {"full", "left", "right"};
    for (int k = 0; k < 3; ++k) {
      LoadCase u, s;
      u.factor[kPayloadFull + k] = gq;
      s.factor[kPayloadFull + k] = 1.0;
      const std::string q = std::string("Q_") + parts[k];
      family(std::string("payload_") + parts[k], " + " + Factor(gq) + " " + q, " + " + q, u, s);
    }
  }
  if (l.Asks(LoadFamily::kTravelling)) {
    LoadCase u, s;
    u.station_load = gq * l.travelling_load_n;
    s.station_load = l.travelling_load_n;
    family("travelling", " + " + Factor(gq) + " Q_t (each deck station in turn)",
           " + Q_t (each deck station in turn)", u, s);
  }
  if (l.Asks(LoadFamily::kPaperTravelling)) {
    // Eqs 50-51: the deck node load f on each inner deck node in turn, on top of the payload.
    LoadCase u, s;
    u.factor[kPayloadFull] = gq;
    u.station_load = gq * deck.station_load;
    s.factor[kPayloadFull] = 1.0;
    s.station_load = deck.station_load;
    family("paper_travelling", " + " + Factor(gq) + " (Q_full + f at each deck station in turn)",
           " + Q_full + f (each deck station in turn)", u, s);
  }
  if (l.Asks(LoadFamily::kWind)) {
    if (config.bridge.planes != 2) {
      notes.push_back("loads.cases: \"wind\" left out: a planar bridge carries no transverse load");
    } else {
      LoadCase u, s;
      u.factor[kWind] = l.gamma_w;
      s.factor[kWind] = 1.0;
      family("wind", " + " + Factor(l.gamma_w) + " W", " + W", u, s);
      if (l.Asks(LoadFamily::kPayload)) {
        LoadCase uq, sq;
        uq.factor[kPayloadFull] = gq;
        uq.factor[kWind] = l.gamma_w * l.psi0_wind;
        sq.factor[kPayloadFull] = 1.0;
        sq.factor[kWind] = l.psi0_wind;
        family("payload_wind",
               " + " + Factor(gq) + " Q_full + " + Factor(l.gamma_w * l.psi0_wind) + " W",
               " + Q_full + " + Factor(l.psi0_wind) + " W", uq, sq);
      }
    }
  }
  // Config validation refuses such a list (core/config.cc); a config built otherwise still
  // gets the message rather than a design over no load.
  if (cases.empty()) {
    throw ConfigError("loads.cases", std::to_string(l.cases.size()) + " names",
                      "leaves no load case for this bridge (\"wind\" needs bridge.planes = 2)");
  }
  return cases;
}

}  // namespace tbridge
