// A progress line with an ETA for long work, shared by every command.
//
// The work reports how far it has come; a reporter decides whether and when to draw:
//
//   ProgressReporter progress(ProgressReporter::Wanted(parsed.Flag("--progress")));
//   progress.Stage("simulate");
//   for (...) { ...; progress.Update(t, duration); }   // cheap: stores two numbers
//
// A default-constructed reporter is disabled and every call is a no-op, so library code can
// take a `ProgressReporter*` (nullptr or disabled = silent) without caring who listens.
//
// When enabled, a background thread redraws one line on the stream every `interval_s`, but
// only once the reporter has existed for `delay_s` (short runs print nothing):
//
//   simulate  45% [#############.................] elapsed 0:00:03  ETA 0:00:04
//
// The ETA extrapolates the rate since the first Update of the stage, so work that was
// already done when the stage began (a resumed sweep) does not shorten it. A stage with an
// unknown total (total <= 0) shows only the elapsed time. The line goes to stderr and is
// ended with a newline when the reporter is destroyed, so an error message printed after it
// starts on a line of its own. Update and Stage may be called from any thread.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace tbridge {

class ProgressReporter {
 public:
  // Disabled: prints nothing, starts no thread.
  ProgressReporter() = default;
  // `enabled` false gives the disabled reporter. `out` is the stream drawn on (stderr);
  // `delay_s` [s] the quiet time before the first draw; `interval_s` [s] between redraws.
  explicit ProgressReporter(bool enabled, std::FILE* out = stderr, double delay_s = 1.0,
                            double interval_s = 0.25);
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;
  // Finish().
  ~ProgressReporter();

  // True when a command should draw progress: `forced` (its --progress flag) or stderr is a
  // terminal.
  static bool Wanted(bool forced);

  bool enabled() const { return enabled_; }
  // Begins a named stage ("design", "simulate", "candidates"); its progress starts unknown.
  void Stage(const std::string& name);
  // `done` of `total` units of the current stage (any unit: steps, seconds, candidates).
  // total <= 0: unknown total.
  void Update(double done, double total);
  // A hook the work polls through this reporter: called, in the working thread, by every
  // Stage and Update, drawn or not (a disabled reporter calls it too). It may throw to stop
  // the work (the Python module raises KeyboardInterrupt so on Ctrl-C); the exception leaves
  // the work as any error does. Set it before the work starts.
  void SetCancelHook(std::function<void()> hook) { cancel_ = std::move(hook); }
  // Put before every later stage's name ("sizing 3: " + "static check"), so that work nested
  // in a larger loop says where in the loop it is. Call from the thread that owns the reporter.
  void SetStagePrefix(std::string prefix) { prefix_ = std::move(prefix); }
  // Put before that prefix: an outer loop's place, which the inner loop's own prefix does not
  // replace ("angle 30 deg (trial 5): " + "sizing 3 (of at most 25): " + "static check"). Call
  // from the thread that owns the reporter; "" clears it.
  void SetOuterPrefix(std::string prefix) { outer_ = std::move(prefix); }

  // Stops drawing for good and ends the line if one was drawn, e.g. before printing warnings
  // or results; later calls do nothing. Call from the thread that owns the reporter.
  void Finish();

  // The line drawn for a stage at `elapsed_s` since its first update, for tests: e.g.
  // "simulate  45% [#####.....] elapsed 0:00:03  ETA 0:00:04". `fraction` < 0: unknown;
  // `eta_s` < 0: unknown.
  static std::string Line(const std::string& stage, double fraction, double elapsed_s,
                          double eta_s);

 private:
  void Run();
  void DrawLocked();

  std::atomic<bool> enabled_{false};
  std::FILE* out_ = nullptr;
  double delay_s_ = 0, interval_s_ = 0;
  std::chrono::steady_clock::time_point created_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  bool drawn_ = false;  // a line is on the stream and not yet ended
  std::string stage_;
  std::chrono::steady_clock::time_point stage_start_;
  double done_ = 0, total_ = 0;
  double first_done_ = -1;  // done at the stage's first update (baseline for the rate)
  std::chrono::steady_clock::time_point first_time_;
  std::thread thread_;
  std::function<void()> cancel_;
  std::string prefix_, outer_;
};

// What the process is working on, for the one message that cannot ask the work itself (out of
// memory): the subject a command names (SetWorkSubject: "the design of the bridge at n = 10")
// and the stage any reporter last began, enabled or not, with its prefix ("sizing 3 (of at most
// 15): static check"). WorkInProgress() joins them: "static check, sizing 3 ..., of the design
// of the bridge at n = 10"; "" where neither is known. Either may be called from any thread.
void SetWorkSubject(const std::string& subject);
std::string WorkInProgress();

// "h:mm:ss" of a non-negative number of seconds (negative counts as 0).
std::string ClockText(double seconds);

}  // namespace tbridge
