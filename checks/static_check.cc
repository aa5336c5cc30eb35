#include "checks/static_check.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>

#include "core/error.h"
#include "core/two_lanes.h"
#include "design/abutments.h"
#include "design/case_envelope.h"
#include "design/mirror.h"
#include "design/static_model.h"

namespace tbridge {

namespace {

// What the check measures of a state, as utilisations: per member [bars; strings] what its
// finding would be (an ultimate case: yield or buckling of a bar, yield of a string; a
// serviceability case: 1 - T / (A sigma_w) of a string that must stay taut, over 1 where it is
// slack, or T / (A sigma_ser), its serviceability stress, where that is larger), then the largest
// deck deflection over its limit (serviceability). -inf where the case measures nothing.
class Measures {
 public:
  explicit Measures(const Design& d)
      : d_(d),
        rule_(BarRuleOf(d.config)),
        E_(BarMaterial(d.config).youngs_modulus),
        sigma_w_(StringMaterial(d.config).DesignStress()),
        sigma_ser_(StringServiceStress(d.config)),
        limit_m_(d.config.bridge.span / d.config.loads.deflection_limit) {}

  int size() const { return static_cast<int>(d_.bars.size() + d_.strings.size()) + 1; }

  // Of member forces [C; T] and node positions `nodes` under a case of limit state `state`,
  // into `out` (size()).
  void Of(LimitState state, const Eigen::VectorXd& forces, const Eigen::Matrix3Xd& nodes,
          Eigen::VectorXd& out) const {
    const int nb = static_cast<int>(d_.bars.size());
    out.setConstant(size(), -std::numeric_limits<double>::infinity());
    if (state == LimitState::kUltimate) {
      for (int b = 0; b < nb; ++b) {
        const BarCapacity cap = BarResistance(d_.bars[b].area, d_.bars[b].length, rule_, E_);
        const double f = forces[b];
        out[b] = std::max(std::abs(f) / cap.yield, f > 0 ? f / cap.buckling : 0.0);
      }
      for (size_t k = 0; k < d_.strings.size(); ++k) {
        const double area = d_.strings[k].area;
        if (area > 0) out[nb + k] = std::max(forces[nb + k], 0.0) / (area * sigma_w_);
      }
      return;
    }
    for (size_t k = 0; k < d_.strings.size(); ++k) {
      const double area = d_.strings[k].area;
      if (!(area > 0)) continue;
      out[nb + k] = forces[nb + k] / (area * sigma_ser_);
      if (MustStayTaut(d_, static_cast<int>(k)))
        out[nb + k] = std::max(out[nb + k], 1.0 - forces[nb + k] / (area * sigma_w_));
    }
    const Structure& s = d_.topology.structure;
    double deflection = 0;
    for (int v : d_.topology.deck_nodes)
      deflection = std::max(deflection, std::abs(nodes(1, v) - s.nodes(1, v)));
    out[size() - 1] = deflection / limit_m_;
  }

 private:
  const Design& d_;
  BarRule rule_;
  // The bars' modulus, the strings' design and serviceability stresses.
  double E_, sigma_w_, sigma_ser_, limit_m_;
};

// The linear pass over every station of every travelling family: the response about the
// reference state to each family's loads without its travelling load, once per family, and
// to a unit load at each station, once per station (shared by the families), combined.
// `visit(c, k, measures)` sees each family c at each station k, station by station, in
// O(members + nodes) memory.
template <class Visit>
void LinearStations(const Design& d, const std::vector<int>& families, StaticTangent& tangent,
                    const StaticState& start, const Measures& measures, Visit visit) {
  const int stations = static_cast<int>(d.actions.station_nodes.size());
  const Structure& s = d.topology.structure;
  Eigen::VectorXd start_forces(s.num_bars() + s.num_strings());
  start_forces << start.bar_compression, start.string_tension;
  std::vector<Eigen::VectorXd> base_forces(families.size());
  std::vector<Eigen::Matrix3Xd> base_nodes(families.size());
  Eigen::Matrix3Xd du, nodes, unit = Eigen::Matrix3Xd::Zero(3, s.num_nodes());
  Eigen::VectorXd dx, forces, m;
  for (size_t f = 0; f < families.size(); ++f) {
    tangent.Solve(d.actions.Loads(d.cases[families[f]]) - d.loads, du, dx);
    base_forces[f] = start_forces + dx;
    base_nodes[f] = start.nodes + du;
  }
  for (int k = 0; k < stations; ++k) {
    d.actions.AddStationLoad(k, 1.0, unit);
    tangent.Solve(unit, du, dx);
    unit.setZero();
    for (size_t f = 0; f < families.size(); ++f) {
      const LoadCase& c = d.cases[families[f]];
      forces = base_forces[f] + c.station_load * dx;
      nodes = base_nodes[f] + c.station_load * du;
      measures.Of(c.state, forces, nodes, m);
      visit(static_cast<int>(f), k, m);
    }
  }
}

// Which stations of each travelling family are solved nonlinearly (selected[f][k]): the
// linear pass's largest measure of each member and of the deflection over every family and
// station, and the stations where a measure comes within `margin` of it or of its limit 1.
std::vector<std::vector<char>> SelectStations(const Design& d, const std::vector<int>& families,
                                              StaticTangent& tangent, const StaticState& start,
                                              double margin) {
  const int stations = static_cast<int>(d.actions.station_nodes.size());
  std::vector<std::vector<char>> selected(families.size(), std::vector<char>(stations, 0));
  // The linear pass measures members and deflections, not reactions: with an abutment capacity
  // to hold, every station is solved.
  const SupportsConfig& supports = d.config.supports;
  if (margin >= 1 || !tangent.ok() || supports.horizontal_capacity_n ||
      supports.vertical_capacity_n) {
    for (std::vector<char>& f : selected) std::fill(f.begin(), f.end(), 1);
    return selected;
  }
  const Measures measures(d);
  Eigen::VectorXd largest =
      Eigen::VectorXd::Constant(measures.size(), -std::numeric_limits<double>::infinity());
  LinearStations(d, families, tangent, start, measures,
                 [&largest](int, int, const Eigen::VectorXd& m) { largest = largest.cwiseMax(m); });
  LinearStations(
      d, families, tangent, start, measures, [&](int f, int k, const Eigen::VectorXd& m) {
        for (int i = 0; i < m.size() && !selected[f][k]; ++i) {
          if (m[i] == -std::numeric_limits<double>::infinity()) continue;
          selected[f][k] = m[i] >= largest[i] - margin * std::abs(largest[i]) || m[i] >= 1 - margin;
        }
      });
  return selected;
}

// Each abutment's largest horizontal and vertical reactions over the converged ultimate cases,
// against the config's capacities.
std::vector<AbutmentFinding> AbutmentFindings(const Design& d,
                                              const std::vector<CaseResponse>& cases) {
  std::vector<AbutmentFinding> out;
  const SupportsConfig& capacity = d.config.supports;
  for (const Abutment& a : AbutmentsOf(d.topology.structure, d.config.bridge.span)) {
    AbutmentFinding f;
    f.nodes = a.nodes;
    f.x_m = a.x_m;
    f.horizontal_capacity_n = capacity.horizontal_capacity_n.value_or(0.0);
    f.vertical_capacity_n = capacity.vertical_capacity_n.value_or(0.0);
    for (const CaseResponse& c : cases) {
      if (!c.converged || d.cases[static_cast<size_t>(c.case_index)].state != LimitState::kUltimate)
        continue;
      const AbutmentReaction r = ReactionOf(a, c.reactions);
      if (r.Horizontal() > f.horizontal_n)
        f.horizontal_n = r.Horizontal(), f.horizontal_case = c.label;
      if (r.Vertical() > f.vertical_n) f.vertical_n = r.Vertical(), f.vertical_case = c.label;
    }
    // No ultimate case found an equilibrium: the reference state's reactions (the permanent load
    // and the prestress, in which the bridge stands) are the least the abutment takes, where
    // an empty envelope read "0 kN" (the 30 m footbridge fixed at 10 deg: 99.6 MN each).
    if (f.horizontal_case.empty() && f.vertical_case.empty() && d.reactions.cols() > 0) {
      const AbutmentReaction r = ReactionOf(a, d.reactions);
      const std::string label = "reference state: no ultimate case found an equilibrium";
      f.horizontal_n = r.Horizontal(), f.horizontal_case = label;
      f.vertical_n = r.Vertical(), f.vertical_case = label;
    }
    out.push_back(std::move(f));
  }
  return out;
}

// The stations checked per case (-1: a case that does not travel).
std::vector<std::vector<int>> StationsOfCases(const Design& d, const std::vector<int>& family_of,
                                              const std::vector<std::vector<char>>& selected,
                                              int stations) {
  std::vector<std::vector<int>> stations_of(d.cases.size(), std::vector<int>{-1});
  for (size_t c = 0; c < d.cases.size(); ++c) {
    if (family_of[c] >= 0) {
      stations_of[c].clear();
      for (int k = 0; k < stations; ++k) {
        if (selected[family_of[c]][k]) stations_of[c].push_back(k);
      }
    }
  }
  return stations_of;
}

// A solve of a case at a station, or a station whose response is a solved one's mirror image.
struct Job {
  int c = 0, station = -1, lane = 0;
  bool restart = true;  // the first of its series
  int image_of = -1;    // the job whose mirror image this station's response is (not solved)
};

// The jobs of `stations_of`, a station that is the mirror image of a solved one not solved
// again; `solves` takes the number of solves (for the progress).
std::vector<Job> PlanJobs(const Design& d, const std::vector<std::vector<int>>& stations_of,
                          const std::vector<int>& family_of,
                          const std::vector<std::vector<char>>& selected,
                          const std::optional<StationMirror>& mirror,
                          const std::vector<int>& case_image, int stations, int& solves) {
  std::vector<Job> jobs;
  int lane_solves[2] = {0, 0};
  solves = 0;
  for (size_t c = 0; c < d.cases.size(); ++c) {
    const std::vector<int>& st = stations_of[c];
    const bool paired = mirror && !case_image.empty() && case_image[c] == static_cast<int>(c) &&
                        !st.empty() && st.front() >= 0;
    // Per station of the case, its job (to find the image's).
    std::vector<int> job_at(static_cast<size_t>(stations), -1);
    std::vector<size_t> solved;  // indexes into st
    for (size_t i = 0; i < st.size(); ++i) {
      const int image = paired ? mirror->station_image[static_cast<size_t>(st[i])] : -1;
      if (image < 0 || image >= st[i] ||
          !selected[static_cast<size_t>(family_of[c])][static_cast<size_t>(image)]) {
        solved.push_back(i);
      }
    }
    const size_t half = solved.size() > 1 ? (solved.size() + 1) / 2 : solved.size();
    const int single_lane = lane_solves[1] < lane_solves[0] ? 1 : 0;
    for (size_t i = 0, next = 0; i < st.size(); ++i) {
      Job job{static_cast<int>(c), st[i], 0, false, -1};
      if (next < solved.size() && solved[next] == i) {
        job.lane = solved.size() > 1 ? (next < half ? 0 : 1) : single_lane;
        job.restart = next == 0 || next == half;
        ++lane_solves[job.lane];
        ++solves;
        ++next;
      } else {
        job.lane = -1;
        job.image_of =
            job_at[static_cast<size_t>(mirror->station_image[static_cast<size_t>(st[i])])];
      }
      if (st[i] >= 0) job_at[static_cast<size_t>(st[i])] = static_cast<int>(jobs.size());
      jobs.push_back(job);
    }
  }
  return jobs;
}

// A job's response and its loads' sum and size (for the balance of the reactions).
struct Solved {
  StaticResult result;
  Eigen::Vector3d load_total = Eigen::Vector3d::Zero();
  double load_abs_sum = 0;
};

// Solves the jobs in their two lanes, then takes each mirrored station's response from its
// image's (counted in out.mirrored).
std::vector<Solved> SolveJobs(const Design& d, const StaticModel& model, const StaticState& start,
                              std::optional<StaticTangent>& tangent, const std::vector<Job>& jobs,
                              int solves, const std::optional<StationMirror>& mirror,
                              ProgressReporter* progress, StaticCheck& out) {
  std::vector<Solved> solved(jobs.size());
  std::atomic<int> done{0};
  std::atomic<bool> stop{false};
  const auto run_lane = [&](int lane) {
    StaticSeries series(model, start, d.loads, lane == 0 && tangent ? &*tangent : nullptr);
    for (size_t i = 0; i < jobs.size() && !stop; ++i) {
      const Job& job = jobs[i];
      if (job.lane != lane) continue;
      // Only this thread's lane reports (the reporter's cancel hook runs in its owner's thread).
      if (lane == 0 && progress != nullptr) progress->Update(done.load(), solves);
      if (job.restart) series.Restart();
      const Eigen::Matrix3Xd loads = d.actions.Loads(d.cases[job.c], job.station);
      solved[i].result = series.Solve(loads);
      solved[i].load_total = loads.rowwise().sum();
      solved[i].load_abs_sum = loads.cwiseAbs().sum();
      ++done;
    }
  };
  InTwoLanes([&] { run_lane(1); },
             [&] {
               try {
                 run_lane(0);
               } catch (...) {
                 stop = true;  // the other lane ends at its next solve
                 throw;
               }
             });
  for (size_t i = 0; i < jobs.size(); ++i) {
    const int j = jobs[i].image_of;
    if (j < 0) continue;
    solved[i].result = mirror->mirror.Of(solved[static_cast<size_t>(j)].result);
    solved[i].load_abs_sum = solved[static_cast<size_t>(j)].load_abs_sum;
    solved[i].load_total =
        mirror->mirror.flip.cwiseProduct(solved[static_cast<size_t>(j)].load_total);
    ++out.mirrored;
  }
  return solved;
}

// The response of case `c` at `station` (-1: not travelling): its convergence, reactions and
// their balance against the loads, and its largest deck deflection.
CaseResponse CaseResponseOf(const Design& d, int c, int station, const Solved& solved) {
  const Structure& s = d.topology.structure;
  const StaticResult& result = solved.result;
  CaseResponse r;
  r.case_index = c;
  r.station = station;
  r.label = CaseLabel(d.cases, d.actions, MemberExtreme{0, c, station});
  r.converged = result.converged;
  r.message = result.message;
  r.slack_strings = result.slack_strings;
  r.reactions = result.state.reactions;
  r.balance = (r.reactions.rowwise().sum() + solved.load_total).norm() /
              std::max(solved.load_abs_sum, 1e-300);
  for (int v : d.topology.deck_nodes) {
    const double dy = std::abs(result.state.nodes(1, v) - s.nodes(1, v));
    if (dy > r.deflection_m) r.deflection_m = dy, r.deflection_node = v;
  }
  return r;
}

// The members' findings under an ultimate case: bars in yield and buckling, strings in yield.
void RaiseUltimateFindings(const Design& d, const StaticResult& result, const CaseResponse& r,
                           const BarRule& rule, double E, double sigma_w, StaticCheck& out) {
  const Structure& s = d.topology.structure;
  const int nb = s.num_bars();
  for (int b = 0; b < nb; ++b) {
    const MemberSizing& m = d.bars[b];
    const double force = result.state.bar_compression[b];
    const BarCapacity cap = BarResistance(m.area, m.length, rule, E);
    RaiseFinding(out.members[b], std::abs(force), cap.yield, r.label, LimitMode::kYield);
    if (force > 0) RaiseFinding(out.members[b], force, cap.buckling, r.label, LimitMode::kBuckling);
  }
  for (size_t k = 0; k < d.strings.size(); ++k) {
    const MemberSizing& m = d.strings[k];
    if (m.area > 0)
      RaiseFinding(out.members[nb + k], result.state.string_tension[k], m.area * sigma_w, r.label,
                   LimitMode::kYield);
  }
}

// The strings' findings under a serviceability case (their stress, and a string that must stay
// taut gone slack), and the largest deflection.
void RaiseServiceFindings(const Design& d, const StaticResult& result, const CaseResponse& r,
                          double sigma_w, double sigma_ser, const MemberMaterial& strings,
                          StaticCheck& out) {
  const Structure& s = d.topology.structure;
  const int nb = s.num_bars();
  for (size_t k = 0; k < d.strings.size(); ++k) {
    const MemberSizing& m = d.strings[k];
    if (m.area > 0) {
      RaiseFinding(out.members[nb + k], result.state.string_tension[k], m.area * sigma_ser, r.label,
                   LimitMode::kServiceability);
    }
  }
  for (size_t k = 0; k < d.strings.size(); ++k) {
    const Member& e = s.strings[k];
    const double length = (result.state.nodes.col(e.j) - result.state.nodes.col(e.i)).norm();
    const MemberSizing& m = d.strings[k];
    if (length >= m.rest_length || !MustStayTaut(d, static_cast<int>(k))) continue;
    RaiseSlackFinding(out.members[nb + k], (length - m.rest_length) / m.rest_length, sigma_w,
                      strings.youngs_modulus, r.label);
  }
  if (r.deflection_m > out.deflection_max_m) {
    out.deflection_max_m = r.deflection_m;
    out.deflection_case = r.label;
  }
}

}  // namespace

StaticCheck CheckStatics(const Design& d, ProgressReporter* progress) {
  if (progress != nullptr) progress->Stage("static check");
  const Structure& s = d.topology.structure;
  const StaticModel model = StaticModelOf(d);
  const int nb = s.num_bars();
  const StaticState start = ReferenceState(model, d);
  const BarRule rule = BarRuleOf(d.config);
  const double E = BarMaterial(d.config).youngs_modulus;
  const MemberMaterial strings = StringMaterial(d.config);
  const double sigma_w = strings.DesignStress();
  const double sigma_ser = StringServiceStress(d.config);

  StaticCheck out;
  out.done = true;
  out.members.resize(d.bars.size() + d.strings.size());
  out.force_max.assign(out.members.size(), 0.0);
  out.force_min.assign(out.members.size(), std::numeric_limits<double>::infinity());
  out.deflection_limit_m = d.config.bridge.span / d.config.loads.deflection_limit;
  out.stations = static_cast<int>(d.actions.station_nodes.size());

  // The travelling families, screened by the linear pass.
  std::vector<int> families, family_of(d.cases.size(), -1);
  for (size_t c = 0; c < d.cases.size(); ++c) {
    if (d.cases[c].station_load == 0) continue;
    family_of[c] = static_cast<int>(families.size());
    families.push_back(static_cast<int>(c));
  }
  // Factorised only for a travelling family, whose many solves it serves (a second
  // factorisation held beside the solve's own: 8 % more memory on the paper's n = 16).
  std::optional<StaticTangent> tangent;
  std::vector<std::vector<char>> selected;
  if (!families.empty()) {
    tangent.emplace(model, start);
    selected = SelectStations(d, families, *tangent, start, d.config.loads.station_margin);
  }

  const std::vector<std::vector<int>> stations_of =
      StationsOfCases(d, family_of, selected, out.stations);

  // A symmetric design under a travelling family that is its own mirror image: the response
  // at a station is the mirror image of the response at its image station (MidSpanMirror),
  // so only one station of each mirrored pair is solved.
  std::optional<StationMirror> mirror;
  std::vector<int> case_image;
  if (!families.empty())
    mirror = MidSpanMirror(model, start, d.loads, d.actions, d.config.bridge.span);
  if (mirror) case_image = CaseImages(mirror->mirror, d.actions, d.cases);

  // The solves in their order (case by case, station by station), in two lanes: each case's
  // stations to solve split in halves, each half a series from the reference state and then
  // from the last station's equilibrium; a case without stations goes to the lane with less
  // work. The lanes are fixed by the design alone, so the results do not depend on the machine.
  int solves = 0;  // for the progress
  const std::vector<Job> jobs =
      PlanJobs(d, stations_of, family_of, selected, mirror, case_image, out.stations, solves);
  const std::vector<Solved> solved =
      SolveJobs(d, model, start, tangent, jobs, solves, mirror, progress, out);

  for (size_t i = 0; i < jobs.size(); ++i) {
    const int c = jobs[i].c, station = jobs[i].station;
    const LoadCase& lc = d.cases[c];
    const StaticResult& result = solved[i].result;
    if (jobs[i].image_of < 0) ++out.nonlinear_solves;
    CaseResponse r = CaseResponseOf(d, c, station, solved[i]);
    out.all_converged = out.all_converged && r.converged;
    if (r.converged) {
      for (int j = 0; j < nb + static_cast<int>(d.strings.size()); ++j) {
        const double force =
            j < nb ? result.state.bar_compression[j] : result.state.string_tension[j - nb];
        out.force_min[j] = std::min(out.force_min[j], force);
        if (lc.state == LimitState::kUltimate) out.force_max[j] = std::max(out.force_max[j], force);
      }
    }
    if (r.converged && lc.state == LimitState::kUltimate)
      RaiseUltimateFindings(d, result, r, rule, E, sigma_w, out);
    if (r.converged && lc.state == LimitState::kServiceability)
      RaiseServiceFindings(d, result, r, sigma_w, sigma_ser, strings, out);
    out.cases.push_back(std::move(r));
  }
  for (double& f : out.force_min) {
    if (std::isinf(f)) f = 0;  // no case converged
  }
  out.abutments = AbutmentFindings(d, out.cases);
  return out;
}

namespace {

// Adds to `out` (the check of a design as designed) what `other` found in another state of its
// prestress, whose cases' labels take `suffix`.
void AddState(StaticCheck& out, StaticCheck other, const std::string& suffix) {
  out.prestress_states.push_back(suffix.substr(1));
  for (size_t j = 0; j < out.members.size(); ++j) {
    MemberFinding& f = other.members[j];
    if (f.utilisation > out.members[j].utilisation) {
      f.governing_case += suffix;
      out.members[j] = f;
    }
    out.force_max[j] = std::max(out.force_max[j], other.force_max[j]);
    out.force_min[j] = std::min(out.force_min[j], other.force_min[j]);
  }
  if (other.deflection_max_m > out.deflection_max_m) {
    out.deflection_max_m = other.deflection_max_m;
    out.deflection_case = other.deflection_case + suffix;
  }
  out.nonlinear_solves += other.nonlinear_solves;
  out.mirrored += other.mirrored;
  out.all_converged = out.all_converged && other.all_converged;
  for (CaseResponse& r : other.cases) {
    r.label += suffix;
    out.cases.push_back(std::move(r));
  }
}

}  // namespace

StaticCheck CheckStaticsInEveryState(const Design& d, const std::vector<DesignState>& others,
                                     ProgressReporter* progress) {
  StaticCheck out = CheckStatics(d, progress);
  for (const DesignState& other : others) {
    if (other.design) {
      AddState(out, CheckStatics(*other.design, progress), other.spec.suffix);
      continue;
    }
    // The bridge with its rest lengths so changed does not stand: the check fails, and says so.
    out.prestress_states.push_back(other.spec.suffix.substr(1));
    CaseResponse r;
    r.label = "reference" + other.spec.suffix;
    r.message = other.failure;
    out.all_converged = false;
    out.cases.push_back(std::move(r));
  }
  out.abutments = AbutmentFindings(d, out.cases);
  return out;
}

CaseAt CaseOfLabel(const Design& d, const std::string& label, const std::string& key) {
  // A case in another state of the prestress (CheckStaticsInEveryState): by its label's suffix.
  const std::vector<PrestressStateSpec> states = PrestressStatesOf(d);
  for (size_t k = 1; k < states.size(); ++k) {
    const std::string& suffix = states[k].suffix;
    if (label.size() > suffix.size() && label.ends_with(suffix)) {
      CaseAt at = CaseOfLabel(d, label.substr(0, label.size() - suffix.size()), key);
      at.state = static_cast<int>(k);
      return at;
    }
  }
  std::string allowed;
  for (size_t c = 0; c < d.cases.size(); ++c) {
    const LoadCase& lc = d.cases[c];
    const int stations =
        lc.station_load != 0 ? static_cast<int>(d.actions.station_nodes.size()) : 0;
    for (int k = stations > 0 ? 0 : -1; k < stations; ++k) {
      const std::string name =
          CaseLabel(d.cases, d.actions, MemberExtreme{0, static_cast<int>(c), k});
      if (name == label) return CaseAt{static_cast<int>(c), k};
    }
    allowed += (allowed.empty() ? "" : ", ") + lc.name +
               (stations > 0 ? " at node N (a station's first deck node)" : "");
  }
  for (size_t k = 1; k < states.size(); ++k)
    allowed += "; each also followed by \"" + states[k].suffix.substr(1) + "\"";
  throw ConfigError(key, "'" + label + "'", "a case of the design: " + allowed);
}

Eigen::Matrix3Xd SolveCaseNodes(const Design& design, const CaseAt& at) {
  const Design d =
      at.state > 0
          ? DesignInState(design, PrestressStatesOf(design).at(static_cast<size_t>(at.state)))
          : design;
  const StaticModel model = StaticModelOf(d);
  const StaticState start = ReferenceState(model, d);
  const StaticResult result =
      SolveStatic(model, start, d.loads, d.actions.Loads(d.cases.at(at.case_index), at.station));
  if (!result.converged) {
    throw ModelError(CaseLabel(d.cases, d.actions, MemberExtreme{0, at.case_index, at.station}) +
                     ": no static equilibrium found (" + result.message + ")");
  }
  return result.state.nodes;
}

}  // namespace tbridge
