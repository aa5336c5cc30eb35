#include "dynamics/run_recorder.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "dynamics/response.h"

namespace tbridge {

RunRecorder::RunRecorder(const DynamicModel& model, const DynamicsConfig& config, long total_steps,
                         const std::vector<HistorySink*>& sinks, SimulationResult& result)
    : model_(model), sinks_(sinks), result_(result) {
  const int n_cols = 1 + model.dim * static_cast<int>(result.recorded_nodes.size());
  recording_ = !result.recorded_nodes.empty();
  streaming_ = !sinks.empty();
  deck_ = config.frequency.enabled && !model.deck_nodes.empty();
  history_every_ = history_countdown_ = config.record.every;
  deck_every_ = deck_countdown_ = config.frequency.every;
  history_spacing_ = config.dt * config.record.every;
  deck_spacing_ = config.dt * config.frequency.every;
  if (recording_ && streaming_) {
    row_.resize(n_cols);
    for (HistorySink* sink : sinks) sink->Begin(model, result.recorded_nodes);
  }
  if (recording_ && !streaming_)
    result.history.resize(total_steps / config.record.every + 2, n_cols);
  if (deck_) {
    // Mirror-odd weights about mid-span (halfway between the outermost nodes).
    const double lo = model.positions.row(0).minCoeff(), hi = model.positions.row(0).maxCoeff();
    const double mid = 0.5 * (lo + hi), span = hi - lo;
    for (const int a : model.deck_nodes) {
      const double x = model.positions(0, a) - mid;
      odd_sign_.push_back(std::abs(x) <= 1e-9 * span ? 0.0 : (x > 0 ? -1.0 : 1.0));
    }
    const Eigen::Index samples = total_steps / config.frequency.every + 2;
    result.deck_even.resize(samples);
    result.deck_odd.resize(samples);
    result.deck_sample_dt = deck_spacing_;
  }
}

void RunRecorder::Start(const double* state) {
  if (recording_) TakeHistory(0.0, state);
  if (deck_) TakeDeck(state);
}

void RunRecorder::TakeHistory(double t, const double* state) {
  if (!streaming_ && history_rows_ >= result_.history.rows()) return;
  // Streamed rows are taken into row_; held ones straight into the history (row-major:
  // contiguous).
  double* row = streaming_ ? row_.data() : result_.history.row(history_rows_).data();
  const int dim = model_.dim;
  const std::vector<int>& nodes = result_.recorded_nodes;
  row[0] = t;
  for (size_t k = 0; k < nodes.size(); ++k) {
    for (int d = 0; d < dim; ++d) row[1 + dim * k + d] = state[nodes[k] * dim + d];
  }
  if (streaming_) {
    for (HistorySink* sink : sinks_) sink->Row(t, row + 1);
  }
  ++history_rows_;
}

void RunRecorder::TakeDeck(const double* state) {
  if (deck_rows_ >= result_.deck_even.size()) return;
  const int dim = model_.dim;
  double even = 0, odd = 0;
  for (size_t k = 0; k < model_.deck_nodes.size(); ++k) {
    const int a = model_.deck_nodes[k];
    const double u = state[a * dim + 1] - model_.positions(1, a);
    even += u;
    odd += odd_sign_[k] * u;
  }
  result_.deck_even(deck_rows_) = even;
  result_.deck_odd(deck_rows_) = odd;
  ++deck_rows_;
}

void RunRecorder::Finish(double duration) {
  if (recording_ && !streaming_)
    result_.history.conservativeResize(history_rows_, result_.history.cols());
  if (deck_) {
    // The samples with t <= duration, for the frequency and the summary alike.
    const Eigen::Index rows = SamplesWithin(deck_rows_, deck_spacing_, duration);
    result_.deck_even.conservativeResize(rows);
    result_.deck_odd.conservativeResize(rows);
  }
}

void MeasureDeckFrequency(const DynamicModel& model, const SimulationResult& result,
                          SimulationSummary& s) {
  if (model.deck_nodes.empty()) {
    s.frequency_note = "the model has no deck nodes";
    return;
  }
  const Eigen::VectorXd& even = result.deck_even;
  const Eigen::VectorXd& odd = result.deck_odd;
  const FrequencyReading reading = MeasureFrequency(even, result.deck_sample_dt);
  if (!reading.estimate) {
    s.frequency_note = "no deck frequency: " + reading.note;
    return;
  }
  s.frequency = *reading.estimate;
  s.has_frequency = true;
  try {
    s.crossing_frequency = MeanPeriodFromCrossings(even, result.deck_sample_dt);
  } catch (const std::invalid_argument&) {
    // fewer than three crossings: a record shorter than a period; the spectral estimate stands
    // alone
  }
  const auto spread = [](const Eigen::VectorXd& v) {
    return (v.array() - v.mean()).abs().maxCoeff();
  };
  // The antisymmetric modes by the same rules: none where the odd part drifts or is too short.
  if (spread(odd) > 1e-6 * spread(even))
    s.antisymmetric_frequency = MeasureFrequency(odd, result.deck_sample_dt).estimate;
}

}  // namespace tbridge
