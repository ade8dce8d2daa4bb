// A fit's stage carries on through FitterOptions::max_stalled_updates correspondence updates in a
// row that do not improve the loss, then stops, and returns the best point it passed, not the
// last.
#include <algorithm>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "solver/fitter.h"
#include "tests/perturb.h"
#include "tests/twisted_box.h"

namespace opgraph {
namespace {

// The losses at the start of each correspondence update (the history without its final point).
std::vector<double> UpdateLosses(const FitSummary& summary) {
  std::vector<double> losses;
  for (size_t i = 0; i + 1 < summary.history.size(); ++i) losses.push_back(summary.history[i].loss);
  return losses;
}

// How many updates at the end of `losses` in a row did not improve the best before them by
// `min_relative_improvement`.
int TrailingStalls(const std::vector<double>& losses, double min_relative_improvement) {
  double best = std::numeric_limits<double>::infinity();
  int stalled = 0;
  for (double loss : losses) {
    stalled = loss < best * (1 - min_relative_improvement) ? 0 : stalled + 1;
    best = std::min(best, loss);
  }
  return stalled;
}

FitSummary FitTwistedBox(int max_stalled_updates) {
  Sequence truth = ParseSequence(Json::parse(kTwistedBox));
  const Target target(EvaluateSequence(&truth).back(), {}, TargetOptions());
  // Too few loop cuts for the twist: the loss levels off well above zero, where updates stall.
  Json skeleton = Json::parse(kTwistedBox);
  skeleton["operations"][1]["params"]["cuts"] = 2;
  Sequence sequence = ParseSequence(skeleton);
  FitterOptions options;
  options.num_output_samples = options.num_target_samples = 1500;
  options.max_stalled_updates = max_stalled_updates;
  Fitter fitter(target, &sequence, options);
  PerturbParameters(fitter.program(), sequence, 3);
  return fitter.Fit();
}

TEST(StalledUpdates, StageStopsAfterTheAllowedStallsAndKeepsItsBest) {
  const FitterOptions defaults;
  const FitSummary impatient = FitTwistedBox(0);
  const FitSummary patient = FitTwistedBox(2);
  const std::vector<double> impatient_losses = UpdateLosses(impatient), patient_losses = UpdateLosses(patient);
  ASSERT_LT(static_cast<int>(patient_losses.size()), defaults.max_outer_iterations) << "stopped by the update limit";
  EXPECT_EQ(TrailingStalls(impatient_losses, defaults.min_relative_improvement), 1);
  EXPECT_EQ(TrailingStalls(patient_losses, defaults.min_relative_improvement), 3);
  // Both went the same way until the first stall.
  ASSERT_GT(patient_losses.size(), impatient_losses.size());
  for (size_t i = 0; i < impatient_losses.size(); ++i) EXPECT_EQ(patient_losses[i], impatient_losses[i]) << i;
  // The result is the best point passed; the last three stalled, so it is not the last.
  const double best = *std::min_element(patient_losses.begin(), patient_losses.end());
  EXPECT_NEAR(patient.final_loss, best, 1e-9 * best);
  EXPECT_LT(patient.final_loss, patient_losses.back());
  EXPECT_LE(patient.final_loss, impatient.final_loss);
}

}  // namespace
}  // namespace opgraph
