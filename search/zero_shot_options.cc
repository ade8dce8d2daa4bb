// The search's options, how it ended and the summary of its fits' costs (search/zero_shot.h).
#include <algorithm>
#include <string>
#include <vector>

#include "search/zero_shot.h"

namespace opgraph {

FitCostSummary SummariseFitCosts(const std::vector<FitCost>& costs) {
  FitCostSummary summary;
  double work = 0, seconds = 0;
  std::vector<double> per_unit;
  for (const FitCost& cost : costs) {
    if (cost.work <= 0 || cost.seconds < 1e-3) continue;
    work += static_cast<double>(cost.work), seconds += cost.seconds;
    per_unit.push_back(cost.seconds / static_cast<double>(cost.work));
  }
  summary.fits = static_cast<int>(per_unit.size());
  if (per_unit.empty()) return summary;
  const double mean = seconds / work;
  summary.microseconds_per_unit = 1e6 * mean;
  std::sort(per_unit.begin(), per_unit.end());
  auto percentile = [&](double q) { return per_unit[static_cast<size_t>(q * (per_unit.size() - 1))] / mean; };
  summary.ratio_p10 = percentile(0.1), summary.ratio_p90 = percentile(0.9);
  return summary;
}

const char* SearchEndName(SearchEnd end) {
  switch (end) {
    case SearchEnd::kComplete: return "complete";
    case SearchEnd::kWorkBudget: return "work budget";
    case SearchEnd::kTimeBudget: return "time budget";
    case SearchEnd::kCancelled: return "cancelled";
  }
  return "unknown";
}

std::string ZeroShotOptions::Check() const {
  if (work_budget < 1) return "work budget must be positive";
  if (!(time_budget_seconds >= 0)) return "time budget must be positive, or 0 for none";
  if (max_ops < 3) return "max ops must be at least 3";
  if (max_faces < 1 || max_faces > kMaxFacesCeiling) return "max faces must be in [1, " + std::to_string(kMaxFacesCeiling) + "]";
  if (!(min_relative_gain >= 0 && min_relative_gain < 1)) return "min relative gain must be in [0, 1)";
  if (num_threads < 1) return "threads must be at least 1";
  if (beam_width < 1) return "beam width must be at least 1";
  return "";
}

}  // namespace opgraph
