// Evaluator's speculation (search/evaluator.h): prefetches on idle threads, the speculators
// that run whole lines of search ahead, the fits they share, and the threads they lend.
#include <algorithm>
#include <atomic>
#include <future>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "core/parallel_for.h"
#include "search/evaluator.h"

namespace opgraph {

void Evaluator::Prefetch(const std::vector<Layout>& layouts, FitPrecision precision,
                         const std::function<void()>& meanwhile) {
  std::vector<const Layout*> jobs;
  std::vector<std::string> keys;
  for (const Layout& layout : layouts) {
    if (Threads() < 2) break;  // no idle thread to fit on
    std::string key = Key(layout, precision);
    if (cache_.count(key) || prefetched_.count(key) || std::count(keys.begin(), keys.end(), key)) continue;
    jobs.push_back(&layout);
    keys.push_back(std::move(key));
  }
  // Task 0, on the calling thread, is `meanwhile`; the fits touch no member until they are kept.
  std::vector<Outcome> outcomes(jobs.size());
  const int borrowed = BorrowThreads(static_cast<int>(jobs.size()) + 1 - options_.num_threads);
  ParallelFor(static_cast<int>(jobs.size()) + 1, options_.num_threads + borrowed, [&](int j) {
    if (j == 0) {
      if (meanwhile) meanwhile();
    } else {
      outcomes[j - 1] = FitOnce(keys[j - 1], *jobs[j - 1], precision);
    }
  });
  ReturnThreads(borrowed);
  for (size_t j = 0; j < jobs.size(); ++j) prefetched_.emplace(std::move(keys[j]), std::move(outcomes[j]));
}

struct Evaluator::SharedFits {
  struct Fit {
    int line;  // the speculator's that fits it
    std::shared_future<Outcome> outcome;
  };
  std::mutex mutex;
  std::map<std::string, Fit> fits;
};

Evaluator::Outcome Evaluator::FitOnce(const std::string& key, const Layout& layout, FitPrecision precision) const {
  if (!shared_fits_) return FitUncached(layout, precision);
  std::promise<Outcome> promise;
  std::shared_future<Outcome> future;
  int line = line_;
  {
    std::lock_guard<std::mutex> lock(shared_fits_->mutex);
    const auto [entry, claimed] = shared_fits_->fits.emplace(key, SharedFits::Fit{line_, {}});
    if (!claimed) {
      future = entry->second.outcome, line = entry->second.line;
    } else {
      entry->second.outcome = promise.get_future().share();
    }
  }
  if (future.valid()) {  // fitted by another line; a fit never waits on one
    Outcome outcome = future.get();
    outcome.from_earlier_line = line < line_;
    return outcome;
  }
  try {
    Outcome outcome = FitUncached(layout, precision);
    promise.set_value(outcome);
    return outcome;
  } catch (...) {
    promise.set_exception(std::current_exception());
    throw;
  }
}

std::vector<Evaluator> Evaluator::Speculators(int count, int num_threads) const {
  const auto shared_fits = std::make_shared<SharedFits>();
  const auto line_work = std::make_shared<std::vector<std::atomic<int64_t>>>(count);
  for (std::atomic<int64_t>& work : *line_work) work = 0;
  const auto spare_threads = std::make_shared<std::atomic<int>>(0);
  std::vector<Evaluator> speculators(count, *this);
  for (int i = 0; i < count; ++i) {
    Evaluator& speculator = speculators[i];
    speculator.options_.num_threads = num_threads;
    speculator.options_.progress = nullptr;
    if (i > 0) speculator.options_.on_progress = nullptr;
    speculator.speculative_ = true;
    speculator.line_work_ = line_work;
    speculator.line_ = i;
    speculator.work_at_start_ = work_;
    speculator.spare_threads_ = spare_threads;
    speculator.shared_fits_ = shared_fits;
  }
  return speculators;
}

void Evaluator::LendThreads() {
  if (spare_threads_) *spare_threads_ += options_.num_threads;
}

int Evaluator::Threads() const { return options_.num_threads + (spare_threads_ ? spare_threads_->load() : 0); }

int Evaluator::BorrowThreads(int wanted) const {
  if (!spare_threads_) return 0;
  int spare = spare_threads_->load();
  while (spare > 0 && wanted > 0) {
    const int taken = std::min(spare, wanted);
    if (spare_threads_->compare_exchange_weak(spare, spare - taken)) return taken;
  }
  return 0;
}

void Evaluator::ReturnThreads(int count) const {
  if (count > 0) *spare_threads_ += count;
}

void Evaluator::Adopt(Evaluator* speculator) {
  for (auto& [key, outcome] : speculator->speculated_) {
    if (cache_.count(key) == 0 && prefetched_.count(key) == 0) prefetched_.emplace(key, std::move(outcome));
  }
  speculator->speculated_.clear();
  if (*speculation_cancelled_) cancelled_ = true;
}

}  // namespace opgraph
