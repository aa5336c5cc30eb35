#include "core/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace tbridge {

namespace {

double Seconds(std::chrono::steady_clock::duration d) {
  return std::chrono::duration<double>(d).count();
}

}  // namespace

std::string ClockText(double seconds) {
  const long s = std::isfinite(seconds) ? std::lround(std::max(0.0, seconds)) : 0;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return buf;
}

std::string ProgressReporter::Line(const std::string& stage, double fraction, double elapsed_s,
                                   double eta_s) {
  std::string line = stage;
  if (fraction >= 0) {
    const double f = std::min(1.0, fraction);
    const int width = 30, filled = static_cast<int>(width * f);
    char pct[16];
    std::snprintf(pct, sizeof pct, " %3d%% ", static_cast<int>(100 * f));
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "[" + std::string(...).
    line += pct;
    line += '[';
    line.append(filled, '#');
    line.append(width - filled, '.');
    line += ']';
  }
  line += " elapsed ";
  line += ClockText(elapsed_s);
  if (fraction >= 0) {
    line += "  ETA ";
    line += eta_s >= 0 ? ClockText(eta_s) : std::string("?");
  }
  return line;
}

ProgressReporter::ProgressReporter(bool enabled, std::FILE* out, double delay_s, double interval_s)
    : out_(out),
      delay_s_(delay_s),
      interval_s_(interval_s),
      created_(std::chrono::steady_clock::now()) {
  stage_start_ = created_;
  if (enabled && out_ != nullptr) {
    enabled_ = true;
    thread_ = std::thread([this] { Run(); });
  }
}

ProgressReporter::~ProgressReporter() { Finish(); }

bool ProgressReporter::Wanted(bool forced) { return forced || ::isatty(STDERR_FILENO) == 1; }

namespace {

// The work in progress (SetWorkSubject, the last Stage): process-wide, as the one reader is
// main's handler of an out-of-memory.
std::mutex work_mutex;
std::string work_subject, work_stage;

void SetWorkStage(const std::string& stage) {
  std::lock_guard<std::mutex> lock(work_mutex);
  work_stage = stage;
}

}  // namespace

void SetWorkSubject(const std::string& subject) {
  std::lock_guard<std::mutex> lock(work_mutex);
  work_subject = subject;
}

std::string WorkInProgress() {
  std::lock_guard<std::mutex> lock(work_mutex);
  if (work_stage.empty()) return work_subject;
  return work_subject.empty() ? work_stage : work_stage + ", of " + work_subject;
}

void ProgressReporter::Stage(const std::string& name) {
  if (cancel_) cancel_();
  SetWorkStage(outer_ + prefix_ + name);
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  stage_ = outer_ + prefix_ + name;
  stage_start_ = std::chrono::steady_clock::now();
  done_ = total_ = 0;
  first_done_ = -1;
}

void ProgressReporter::Update(double done, double total) {
  if (cancel_) cancel_();
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  done_ = done;
  total_ = total;
  if (first_done_ < 0) {
    first_done_ = done;
    first_time_ = std::chrono::steady_clock::now();
  }
}

void ProgressReporter::Finish() {
  if (!enabled_.exchange(false)) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
  std::lock_guard<std::mutex> lock(mutex_);
  if (!drawn_) return;
  DrawLocked();  // the last state, so the line ends at the final figures
  std::fputc('\n', out_);
  std::fflush(out_);
  drawn_ = false;
}

void ProgressReporter::DrawLocked() {
  const auto now = std::chrono::steady_clock::now();
  const double fraction = total_ > 0 ? std::clamp(done_ / total_, 0.0, 1.0) : -1.0;
  double eta = -1;
  if (fraction >= 0 && first_done_ >= 0 && done_ > first_done_) {
    const double rate = (done_ - first_done_) / Seconds(now - first_time_);  // units per second
    if (rate > 0) eta = (total_ - done_) / rate;
  }
  const std::string line =
      Line(stage_.empty() ? "working" : stage_, fraction, Seconds(now - stage_start_), eta);
  // "\r" + the line + clearing of what a longer previous line left ("\033[K" is understood
  // by terminals; in a log file it is a harmless escape).
  std::fprintf(out_, "\r%s\033[K", line.c_str());
  std::fflush(out_);
  drawn_ = true;
}

void ProgressReporter::Run() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stop_) {
    wake_.wait_for(lock, std::chrono::duration<double>(interval_s_));
    if (stop_) break;
    if (Seconds(std::chrono::steady_clock::now() - created_) >= delay_s_) DrawLocked();
  }
}

}  // namespace tbridge
