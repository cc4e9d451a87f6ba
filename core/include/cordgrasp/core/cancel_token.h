#pragma once
// A request to stop a long job early (the command line sets it on SIGINT / SIGTERM). Jobs check
// it between units of work (an attempt, a grasp, a trial, a bench row), keep what is finished
// and mark their outputs incomplete.
#include <atomic>
#include <csignal>
#include <string>

namespace cordgrasp {

/// A read-only view of a flag owned by someone else: the number of the signal that asked to
/// stop (0 = keep going). Default-constructed: never cancelled. Cheap to copy.
class CancelToken {
 public:
  CancelToken() = default;
  /// Views `signal`, which must outlive every copy of the token.
  explicit CancelToken(const std::atomic<int>* signal) : signal_(signal) {}

  /// True once a stop was asked for.
  bool cancelled() const { return signal_ && signal_->load(std::memory_order_relaxed) != 0; }

  /// "SIGINT", "SIGTERM", "signal N" for another one, or "" when not cancelled.
  std::string reason() const {
    const int s = signal_ ? signal_->load(std::memory_order_relaxed) : 0;
    if (s == 0) return "";
    if (s == SIGINT) return "SIGINT";
    if (s == SIGTERM) return "SIGTERM";
    return "signal " + std::to_string(s);
  }

 private:
  const std::atomic<int>* signal_ = nullptr;
};

}  // namespace cordgrasp
