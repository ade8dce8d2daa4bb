// The hole family on a block with a slot through it, off its centre and turned: the holes
// through the target's surface inside the cage land on the slot before any fit.
#include <gtest/gtest.h>

#include "core/metrics.h"
#include "ops/builders.h"
#include "ops/sequence.h"
#include "search/pose.h"
#include "search/proposals.h"
#include "tests/known_shapes.h"

namespace opgraph {
namespace {

Mesh Build(const Json& document) {
  Sequence sequence = ParseSequence(document);
  return EvaluateSequence(&sequence).back();
}

// The lowest Chamfer distance to `target` over the alternatives of `rounds` applied to `layout`.
double BestChamfer(const Layout& layout, const std::vector<Round>& rounds, const Mesh& target) {
  double best = std::numeric_limits<double>::infinity();
  for (const Round& round : rounds) {
    for (const Edit& edit : round.alternatives) {
      Layout changed = layout;
      if (edit(&changed).empty()) continue;
      best = std::min(best, ComputeShapeMetrics(Build(changed.Document()), target).chamfer.Sum());
    }
  }
  return best;
}

TEST(ProposeHoles, ThroughTheTargetsSurfaceInsideTheCage) {
  const Mesh target_mesh = Build(build::Document(SlottedBlock()));
  const Target target(target_mesh, {}, TargetOptions());
  const Layout pose = PoseLayoutOnBox(Eigen::Matrix3d::Identity(), Vec3d(-1, -0.8, -0.6), Vec3d(1, 0.8, 0.6));
  std::vector<ResidualCluster> interior;
  FindResidualClusters(target, pose, &interior);
  ASSERT_FALSE(interior.empty());
  EXPECT_TRUE(interior[0].excess);
  EXPECT_NEAR(interior[0].centre.x(), 0.45, 0.05);
  EXPECT_NEAR(interior[0].centre.y(), -0.35, 0.05);
  const std::vector<Round> through = ProposeThroughHoles(pose, interior);
  ASSERT_FALSE(through.empty());
  // Unfitted, a hole through the cluster is already close to the slot; a centred one is not.
  const double on_cluster = BestChamfer(pose, through, target_mesh);
  const double at_centre = BestChamfer(pose, ProposeHoles(pose), target_mesh);
  EXPECT_LT(on_cluster, 0.25 * at_centre) << on_cluster << " vs " << at_centre;
  // Nothing is cut into a bevelled cage.
  Layout bevelled = pose;
  bevelled.details.push_back(build::Bevel(0.05, 3));
  EXPECT_TRUE(ProposeThroughHoles(bevelled, interior).empty());
}

}  // namespace
}  // namespace opgraph
