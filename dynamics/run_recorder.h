// What a run keeps of its motion: the history of the recorded nodes (in memory or streamed to
// sinks as it is taken) and the two deck signals of the frequency measurement, on uniform
// grids of the step; and, after the run, the deck frequency read from them (SPEC.md §9).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/dynamics_config.h"
#include "dynamics/model.h"
#include "dynamics/run_summary.h"

namespace tbridge {

// Takes the recorded rows as the run produces them, so that a long history goes to disk in
// memory bounded by one row (RunHooks::history).
class HistorySink {
 public:
  virtual ~HistorySink() = default;
  // Before the first step: the model and the recorded nodes (0-based). May throw ConfigError.
  virtual void Begin(const DynamicModel& model, const std::vector<int>& recorded_nodes) = 0;
  // One record at time t [s]: dim coordinates [m] of each recorded node, in their order.
  virtual void Row(double t, const double* coordinates) = 0;
};

struct SimulationResult {
  SimulationSummary summary;
  // Recorded history: one row per record time: t, then dim coordinates of each recorded node.
  std::vector<int> recorded_nodes;  // 0-based
  int dim = 2;
  // Row-major, so a record is one contiguous write (column-major made each of its values a
  // cache miss a whole column away).
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> history;
  // The deck's vertical displacement, sampled every frequency.every steps from t = 0 [m]:
  // summed over model.deck_nodes (the paper's signal, DeckSignal), and weighted mirror-odd
  // about mid-span (+1 left, -1 right, 0 on it; it cancels in every symmetric mode, as the sum
  // cancels in every antisymmetric one). Two numbers a sample, however long the deck; empty
  // when frequency is off.
  Eigen::VectorXd deck_even, deck_odd;
  double deck_sample_dt = 0;  // [s]
};

// Fills `result`'s history (or the sinks) and deck signals during one run. Everything is sized
// in the constructor; taking a row or a sample allocates nothing.
class RunRecorder {
 public:
  // `result.recorded_nodes` and `result.dim` are set. Calls every sink's Begin.
  RunRecorder(const DynamicModel& model, const DynamicsConfig& config, long total_steps,
              const std::vector<HistorySink*>& sinks, SimulationResult& result);

  // The state at t = 0.
  void Start(const double* state);
  // After each fixed step, in order, ending at t: the rows and samples that fall on it (every
  // record.every-th and frequency.every-th step). Counted down, not found by a remainder: a
  // division every step cost more than the rest of this.
  void AfterStep(double t, const double* state) {
    if (recording_ && --history_countdown_ == 0) {
      history_countdown_ = history_every_;
      TakeHistory(t, state);
    }
    if (deck_ && --deck_countdown_ == 0) {
      deck_countdown_ = deck_every_;
      TakeDeck(state);
    }
  }
  // After an adaptive step reaching t: every grid time up to t, each state given by
  // interpolate(t_grid, out) (dense output into `out`, sized like the state).
  template <class Interpolate>
  void UpTo(double t, Eigen::VectorXd& out, Interpolate&& interpolate) {
    for (; recording_ && history_next_ * history_spacing_ <= t * (1 + 1e-12); ++history_next_) {
      interpolate(history_next_ * history_spacing_, out);
      TakeHistory(history_next_ * history_spacing_, out.data());
    }
    for (; deck_ && deck_next_ * deck_spacing_ <= t * (1 + 1e-12); ++deck_next_) {
      interpolate(deck_next_ * deck_spacing_, out);
      TakeDeck(out.data());
    }
  }
  // Trims the held rows and samples to what the run took, with t <= duration.
  void Finish(double duration);

 private:
  void TakeHistory(double t, const double* state);
  void TakeDeck(const double* state);

  const DynamicModel& model_;
  const std::vector<HistorySink*>& sinks_;
  SimulationResult& result_;
  bool recording_ = false, deck_ = false, streaming_ = false;
  int history_every_ = 1, deck_every_ = 1;
  int history_countdown_ = 1, deck_countdown_ = 1;  // steps to the next row, the next sample
  double history_spacing_ = 0, deck_spacing_ = 0;   // [s]
  long history_next_ = 1, deck_next_ = 1;           // next grid index of an adaptive run
  long history_rows_ = 0, deck_rows_ = 0;
  Eigen::VectorXd row_;           // the row being taken, when streamed
  std::vector<double> odd_sign_;  // per deck node
};

// The deck frequency of a finished run into `summary` (frequency, crossing and antisymmetric
// frequencies, or a note saying why there is none), from `result`'s deck signals.
void MeasureDeckFrequency(const DynamicModel& model, const SimulationResult& result,
                          SimulationSummary& summary);

}  // namespace tbridge
