#include <algorithm>

#include "benchmarks/synth/synth_moves.h"

namespace opgraph {
namespace synth {

bool BevelFinish(Draft* draft, Random* random) {
  // Not after a Boolean: on the n-gons a Boolean leaves, our Bevel and Blender's differ (two of
  // 200 sampled models rebuilt 1.8e-4 and 9.5e-4 of the diagonal apart; docs/corpus.md).
  if (draft->Has("Boolean")) return false;
  const double width = random->Uniform(0.02, 0.1) * draft->Extent().minCoeff();
  const int segments = random->Weighted({0, 0.4, 0.25, 0.2, 0.15});
  return draft->TryAppend(build::Bevel(width, segments, random->Chance(0.5) ? 30.0 : -1.0));
}

bool SubdivisionFinish(Draft* draft, Random* random) {
  // Level 2 only on small cages, so a model stays a few thousand faces.
  const int levels = draft->mesh().NumFaces() <= 150 && random->Chance(0.6) ? 2 : 1;
  return draft->TryAppend(build::Subdivision(levels));
}

bool Pose(Draft* draft, Random* random) {
  std::vector<Json> ops;
  if (random->Chance(0.6)) {
    Vec3d rotation = Vec3d::Zero();
    rotation[random->Int(0, 2)] = random->SignedUniform(10, 60);
    if (random->Chance(0.3)) rotation[random->Int(0, 2)] += random->SignedUniform(10, 30);
    ops.push_back(build::GlobalRotate(rotation));
  }
  if (ops.empty() || random->Chance(0.5)) {
    const Vec3d extent = draft->Extent();
    ops.push_back(build::GlobalTranslate(Vec3d(random->Uniform(-0.5, 0.5) * extent.x(), random->Uniform(-0.5, 0.5) * extent.y(),
                                               random->Uniform(0, 0.5) * extent.z())));
  }
  return draft->TryAppend(ops);
}

}  // namespace synth
}  // namespace opgraph
