// A history sink that hands the recorded rows to a writer thread: the run copies each row into
// a bounded ring and goes on stepping while the writer formats the CSV and the VTK samples.
// Formatting 12 significant digits costs ~25-40 ns a value; for a wide row that is more than
// handing it over, and on a second core the formatting costs the run little.
//
// Memory: `capacity` rows of the recorded width, whatever the run's length. The run waits when
// the ring is full, so a slow disk slows the run instead of growing memory.
#pragma once

#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "dynamics/simulation.h"

namespace tbridge::cli {

class BackgroundHistory : public HistorySink {
 public:
  // The rows go to `sinks`, in order, on the writer thread; Begin is passed on at once. Rows
  // narrower than kThreadedWidth values go straight through unless `always`: formatting them
  // costs less than handing them over. Measured in-run, best of interleaved runs, with the CSV
  // buffered and FormatG12: the MOTES prism's 73 values a row 7.6 ms inline against 8.6 ms
  // threaded; the paper's n = 6 bridge's 257 values 139 ms inline against 132 ms threaded.
  explicit BackgroundHistory(std::vector<HistorySink*> sinks, bool always = false,
                             int capacity = 1024);
  static constexpr int kThreadedWidth = 128;
  // Stops the writer without the rows still queued (a failed run writes nothing anyway).
  ~BackgroundHistory() override;
  BackgroundHistory(const BackgroundHistory&) = delete;
  BackgroundHistory& operator=(const BackgroundHistory&) = delete;

  void Begin(const DynamicModel& model, const std::vector<int>& recorded_nodes) override;
  void Row(double t, const double* coordinates) override;
  // After the run: every queued row written; rethrows what a sink threw on the writer thread.
  void Finish();

 private:
  void Write();           // the writer thread
  void Stop(bool drain);  // drain: write the queued rows first

  std::vector<HistorySink*> sinks_;
  bool always_, threaded_ = false;
  int capacity_, width_ = 0;        // rows; doubles a row (t, then the coordinates)
  std::unique_ptr<double[]> ring_;  // capacity_ x width_
  long head_ = 0, tail_ = 0;        // rows queued so far, rows written so far
  bool done_ = false, drain_ = true, writer_waiting_ = false, run_waiting_ = false;
  std::exception_ptr error_;
  std::mutex mutex_;
  std::condition_variable rows_ready_, room_ready_;
  std::thread writer_;
};

}  // namespace tbridge::cli
