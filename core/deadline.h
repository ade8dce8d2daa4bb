// A limit on a computation's wall time, for the fits under fit_sequence's --time-budget: a
// fit asks whether its time is up between steps and gives its solver what is left.
#pragma once

#include <algorithm>
#include <chrono>
#include <limits>

namespace opgraph {

class Deadline {
 public:
  // `seconds` from now; 0: no limit (the default, where a fit's result must not depend on time).
  explicit Deadline(double seconds = 0) : seconds_(seconds), start_(std::chrono::steady_clock::now()) {}

  bool limited() const { return seconds_ > 0; }
  // Seconds until the deadline (0 once passed); infinite without a limit.
  double SecondsLeft() const {
    if (!limited()) return std::numeric_limits<double>::infinity();
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    return std::max(0.0, seconds_ - elapsed);
  }
  bool Passed() const { return limited() && SecondsLeft() <= 0; }

 private:
  double seconds_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace opgraph
