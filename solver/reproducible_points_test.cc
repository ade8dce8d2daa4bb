// A fit's history marks the points where the sequence as written rebuilds the program
// (FitSummary::Point::reproducible): a fit may return only those, and fit_benchmark counts only
// those.
#include <gtest/gtest.h>

#include "ops/builders.h"
#include "solver/fitter.h"

namespace opgraph {
namespace {

// A box scaled by `scale_x` along X, its +X face extruded: the face is selected by a box around
// x = 1 (its centre at the unit scale), so the sequence evaluates only while the scale keeps
// that centre inside it.
Json ExtrudedBox(double scale_x) {
  build::ExtrudeArgs extrude;
  extrude.faces.box.lo[0] = 0.9;
  extrude.faces.box.hi[0] = 1.1;
  extrude.faces.expect = 1;
  extrude.height = 0.5;
  extrude.width = 0.8;
  return build::Document({build::GlobalScale(Vec3d(scale_x, 1, 1)), build::Extrude(extrude)});
}

// Fits the extruded box to itself from its X scale set to `start_scale_x` in the program (where
// the sequence as written may not evaluate).
FitSummary FitFromScale(double start_scale_x) {
  Sequence truth = ParseSequence(ExtrudedBox(1.0));
  const Target target(EvaluateSequence(&truth).back(), {}, TargetOptions());
  Sequence sequence = ParseSequence(ExtrudedBox(1.0));
  FitterOptions options;
  options.num_output_samples = options.num_target_samples = 1500;
  Fitter fitter(target, &sequence, options);
  for (const ProgramBlock& block : fitter.program().blocks()) {
    if (!block.holds_op_params() || block.op != 0) continue;
    const std::vector<ParamSpec>& specs = sequence.ops[0]->specs();
    for (int i = 0; i < block.size; ++i) {
      if (specs[i].name == "scale_x") block.data[i] = start_scale_x;
    }
  }
  return fitter.Fit();
}

TEST(ReproduciblePoints, AStartWhereTheSelectionFindsNothingIsNotReproducible) {
  // At X scale 1.3 the +X face's centre lies at 1.3, outside the selection box: the sequence as
  // written does not evaluate, though the program (built at scale 1) does.
  const FitSummary outside = FitFromScale(1.3);
  ASSERT_GE(outside.history.size(), 2u);
  EXPECT_FALSE(outside.history.front().reproducible);
  // The fit brings the scale back; its result is a point the sequence rebuilds.
  EXPECT_TRUE(outside.history.back().reproducible);
  EXPECT_LT(outside.final_loss, 1e-3 * outside.initial_loss);
  // At X scale 1.05 the centre stays inside: every point is reproducible.
  const FitSummary inside = FitFromScale(1.05);
  ASSERT_GE(inside.history.size(), 2u);
  for (const FitSummary::Point& point : inside.history) EXPECT_TRUE(point.reproducible) << point.loss;
}

}  // namespace
}  // namespace opgraph
