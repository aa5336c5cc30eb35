// What a run measures at every accepted state for its summary: string tension, stress and
// slack, bar-length error, deck peaks, energy balance and (when asked) bar force peaks; and the
// guards that stop a run that blows up. It sees every accepted step, so no peak or slack
// transition is missed, whatever is recorded.
//
// Packed: the members are flat arrays of offsets and constants, names stay in the model and
// are looked up once at the end; lengths are compared squared. Allocation-free after
// construction.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "core/dynamics_config.h"
#include "dynamics/engine_frame.h"
#include "dynamics/model.h"
#include "dynamics/run_summary.h"

namespace tbridge {

class RunMonitor {
 public:
  // Evaluates the engine at (t, y) and leaves one bar force density per model bar in `lambda`.
  using BarForceProbe = std::function<void(double t, const double* y, Eigen::VectorXd& lambda)>;

  // Measures the start state y0. `probe`, when given, gives the bar forces (record.bar_forces).
  RunMonitor(const DynamicModel& model, const EngineFrame& engine, const DynamicsConfig& config,
             const Eigen::VectorXd& y0, BarForceProbe probe = {});
  RunMonitor(const RunMonitor&) = delete;  // string_geometry() points into it
  RunMonitor& operator=(const RunMonitor&) = delete;

  // After an accepted step from t_old to t (state y, loads held at the step's midpoint).
  // `dissipated` is the energy the dampers took over the step by the integrator's own stages
  // [J] (RK4, DOPRI5 and SDIRK3 each integrate the stages' damper power with their own
  // weights, which closes the balance across slack kinks). With `strings_recorded`, an engine
  // evaluation at y filled string_geometry(); otherwise the monitor computes the same from y.
  // Throws ModelError on a blow-up.
  // CAUTION: performance-sensitive
  void Accept(long step, double t_old, double t, const double* y, double dissipated,
              bool strings_recorded = false);

  // The strings' geometry, by model string, for an engine evaluation to fill
  // (EngineOde::RecordStringsInNextEvaluation) and Accept to read. The strings the engines
  // leave out (both ends pinned) hold their geometry at the start, which does not change.
  const StringGeometry* string_geometry() const { return &geometry_; }

  // After the last accepted step (its state is the final one): the slack strings at the end,
  // the slack counts, the names and the strains and errors kept squared while running.
  void Finish();

  SimulationSummary& summary() { return summary_; }

  // Called on a blow-up only: the highest linearised frequency of the initial state [rad/s].
  void SetOmegaMax(std::function<double()> omega_max) { omega_max_ = std::move(omega_max); }

 private:
  // The strings, one array per quantity: the pass over them at every step runs in vector
  // registers. Per model string.
  struct StringArrays {
    std::vector<int> oi, oj;             // coordinate offsets of the ends
    std::vector<double> rest, rest_sq;   // L0 [m], L0^2 [m^2]
    std::vector<double> inv_rest_sq;     // 1 / L0^2 [1/m^2]
    std::vector<double> k, c, inv_area;  // [N/m], [N s/m], 1/A [1/m^2] (0 without an area)
  };
  struct PackedBar {
    int oi, oj;
    double inv_rest_sq;  // 1 / l0^2 [1/m^2]
  };
  struct TimedLoadState {
    int o;  // coordinate offset of its node
    double t_start, t_end, rise_s, fall_s, spread_s;
    double force[3];  // [N]
    double last[3];   // node position at the previous accepted step [m]
  };

  [[noreturn]] void Fail(long step, double t, const std::string& what) const;
  // The state y at time t; the loads of `load_time` act on it.
  void Measure(double t, double load_time, const double* y, bool strings_recorded, double& kinetic,
               double& elastic);
  // The strings' geometry at y, as the engines compute it, into geometry_.
  template <int Dim, bool Damped>
  void FillGeometry(const double* y);
  // From geometry_: string tension (the damper's share included), stress, slack and elastic
  // energy [J], added to `elastic`.
  template <bool Damped>
  void MeasureStrings(double t, double& elastic);
  // The extremes of the bars' (l / l0)^2.
  template <int Dim>
  void MeasureBars(const double* y);

  const DynamicModel& model_;
  const EngineFrame& engine_;
  const DynamicsConfig& config_;
  int dim_, c_;
  StringArrays strings_;
  std::vector<PackedBar> bars_;
  std::vector<int> deck_offsets_;  // per deck node: its coordinate offset
  std::vector<double> deck_rest_;  // per deck node: x, y, z of the model's positions [m]
  Eigen::VectorXd x0_, loads_;     // start positions [m], constant loads [N], packed
  double loads_dot_x0_ = 0;        // loads . x0 [J]
  bool has_loads_ = false;         // any constant load
  std::vector<TimedLoadState> timed_;
  std::vector<double> len2_, inv_len_, rate_;  // geometry_'s arrays
  StringGeometry geometry_{};                  // see string_geometry()
  // Per string: 1 while taut, else 0; slack transitions so far (counted in a double so that
  // the pass stays in vector registers); taut at the start; min (s / L0)^2 so far.
  std::vector<double> taut_, transitions_;
  std::vector<char> taut_at_start_;
  std::vector<double> min_ratio_sq_;
  std::vector<double> energy_, stress_;  // per string at the measured state: scratch [J], [Pa]
  double bar_ratio_sq_min_ = 1,
         bar_ratio_sq_max_ = 1;                 // extremes of (l / l0)^2 over bars and steps
  double bar_guard_lo_ = 0, bar_guard_hi_ = 0;  // (1 -+ guard)^2
  int max_stress_string_ = -1;
  BarForceProbe probe_;
  Eigen::VectorXd lambda_;
  // Per reaction group (model.reaction_groups), measured with the bar forces: the member ends
  // at its nodes and the constant loads on them.
  std::vector<std::vector<ReactionEnd>> reaction_ends_;
  std::vector<Eigen::Vector3d> reaction_loads_;
  // The groups' reactions at y, from lambda_ and geometry_, into summary_.peak_reactions.
  void MeasureReactions(const double* y);
  double timed_work_ = 0, h0_ = 0;
  std::function<double()> omega_max_;
  SimulationSummary summary_;
};

}  // namespace tbridge
