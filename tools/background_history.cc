#include "tools/background_history.h"

#include <algorithm>
#include <memory>

namespace tbridge::cli {

BackgroundHistory::BackgroundHistory(std::vector<HistorySink*> sinks, bool always, int capacity)
    : sinks_(std::move(sinks)), always_(always), capacity_(std::max(capacity, 4)) {}

BackgroundHistory::~BackgroundHistory() { Stop(/*drain=*/false); }

void BackgroundHistory::Begin(const DynamicModel& model, const std::vector<int>& recorded_nodes) {
  for (HistorySink* sink : sinks_) sink->Begin(model, recorded_nodes);
  width_ = 1 + model.dim * static_cast<int>(recorded_nodes.size());
  threaded_ = always_ || width_ >= kThreadedWidth;
  if (!threaded_) return;
  // Not zeroed: a page of the ring is touched when a row first reaches it, so a short run
  // pays for the rows it records, not for the whole ring (zeroing it took 1 ms of a 3 ms run).
  ring_ = std::make_unique_for_overwrite<double[]>(static_cast<size_t>(capacity_) *
                                                   static_cast<size_t>(width_));
  writer_ = std::thread(&BackgroundHistory::Write, this);
}

void BackgroundHistory::Row(double t, const double* coordinates) {
  if (!threaded_) {
    for (HistorySink* sink : sinks_) sink->Row(t, coordinates);
    return;
  }
  std::unique_lock<std::mutex> lock(mutex_);
  if (head_ - tail_ == capacity_) {
    run_waiting_ = true;
    rows_ready_.notify_one();
    room_ready_.wait(lock, [&] { return head_ - tail_ < capacity_ || error_ != nullptr; });
    run_waiting_ = false;
  }
  if (error_ != nullptr) return;  // Finish reports it; the run itself goes on to its end
  double* slot = ring_.get() + (head_ % capacity_) * width_;
  slot[0] = t;
  std::copy(coordinates, coordinates + width_ - 1, slot + 1);
  ++head_;
  // Wake the writer for a batch, not a row: a wake-up is a system call.
  if (writer_waiting_ && head_ - tail_ >= capacity_ / 4) rows_ready_.notify_one();
}

void BackgroundHistory::Write() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    writer_waiting_ = true;
    rows_ready_.wait(lock, [&] { return done_ || head_ - tail_ >= capacity_ / 4; });
    writer_waiting_ = false;
    if (done_ && (head_ == tail_ || !drain_)) return;
    // The queued rows are the writer's until tail_ moves: the run only fills free slots.
    const long first = tail_, last = head_;
    lock.unlock();
    try {
      for (long r = first; r < last; ++r) {
        const double* slot = ring_.get() + (r % capacity_) * width_;
        for (HistorySink* sink : sinks_) sink->Row(slot[0], slot + 1);
      }
    } catch (...) {
      lock.lock();
      error_ = std::current_exception();
      tail_ = head_;
      room_ready_.notify_one();
      return;
    }
    lock.lock();
    tail_ = last;
    if (run_waiting_) room_ready_.notify_one();
  }
}

void BackgroundHistory::Stop(bool drain) {
  if (!writer_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
    drain_ = drain;
  }
  rows_ready_.notify_one();
  writer_.join();
}

void BackgroundHistory::Finish() {
  Stop(/*drain=*/true);
  if (error_ != nullptr) std::rethrow_exception(error_);
}

}  // namespace tbridge::cli
