// The fitter takes the loss before a stage's first correspondence update and after its last
// from the updates' own measurements (solver/fresh_points.h). Those must be the losses a fitter
// measures afresh at the same parameters, to the last bit.
#include <gtest/gtest.h>

#include "solver/fitter.h"
#include "tests/perturb.h"
#include "tests/twisted_box.h"

namespace opgraph {
namespace {

// The twisted box's skeleton with too few loop cuts for the twist (so the losses compared stay
// well above rounding) and a bend the target does not have (its gate is pruned when gates are
// fitted, so the program is rebuilt before the last stage).
Json SkeletonWithDecoy() {
  Json skeleton = Json::parse(kTwistedBox);
  skeleton["operations"][1]["params"]["cuts"] = 2;
  skeleton["operations"].push_back(Json::parse(R"({"op": "SimpleDeformBend", "params": {"axis": "X", "angle_deg": 4}})"));
  return skeleton;
}

// The loss a new fitter measures at `document`'s parameters. Its program is prepared at them
// (the fitter's was prepared at the start), so the two agree to rounding, not to the bit.
double FreshLoss(const Target& target, const Json& document, const FitterOptions& options) {
  Sequence sequence = ParseSequence(document);
  Fitter fitter(target, &sequence, options);
  return fitter.CurrentLoss();
}

TEST(FreshPoints, FitLossesEqualLossesMeasuredAfresh) {
  Sequence truth = ParseSequence(Json::parse(kTwistedBox));
  const Target target(EvaluateSequence(&truth).back(), {}, TargetOptions());
  for (bool fit_gates : {false, true}) {
    FitterOptions options;
    options.num_output_samples = options.num_target_samples = 1500;
    options.fit_gates = fit_gates;
    Sequence sequence = ParseSequence(SkeletonWithDecoy());
    Fitter fitter(target, &sequence, options);
    PerturbParameters(fitter.program(), sequence, 3);
    const Json start = SequenceToJson(sequence);
    const FitSummary summary = fitter.Fit();
    ASSERT_GE(summary.history.size(), 3u);
    EXPECT_EQ(summary.initial_loss, FreshLoss(target, start, options)) << "fit_gates " << fit_gates;
    EXPECT_EQ(summary.history.front().loss, summary.initial_loss) << "fit_gates " << fit_gates;
    FitterOptions fitted = options;
    fitted.fit_gates = false;  // the fitted sequence's gates are folded into its parameters
    const double final_loss = FreshLoss(target, SequenceToJson(sequence), fitted);
    EXPECT_NEAR(summary.final_loss, final_loss, 1e-9 * final_loss) << "fit_gates " << fit_gates;
    EXPECT_LT(summary.final_loss, 0.5 * summary.initial_loss) << "fit_gates " << fit_gates;
    EXPECT_GT(summary.final_loss, 1e-8) << "fit_gates " << fit_gates;
    if (fit_gates) EXPECT_EQ(summary.pruned_ops, std::vector<int>{3});
  }
}

}  // namespace
}  // namespace opgraph
