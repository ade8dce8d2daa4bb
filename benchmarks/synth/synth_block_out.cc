#include <algorithm>

#include "benchmarks/synth/synth_moves.h"

namespace opgraph {
namespace synth {
namespace {

build::Axis ToAxis(int axis) { return static_cast<build::Axis>(axis); }

// A factor away from 1 by at least `min_change`.
double Factor(Random* random, double lo, double hi, double min_change) {
  for (;;) {
    const double f = random->Uniform(lo, hi);
    if (std::abs(f - 1) >= min_change) return f;
  }
}

// Vertex levels across `axis` after cutting, so a profile has loops to shape.
bool EnsureLoops(Draft* draft, Random* random, int axis, int min_levels, int max_cuts) {
  if (static_cast<int>(draft->LoopLevels(axis).size()) >= min_levels) return true;
  return draft->TryAppend(build::LoopCut(ToAxis(axis), random->Int(min_levels, std::max(min_levels, max_cuts)),
                                         Vec3d::Zero()));
}

}  // namespace

bool ScaleBlock(Draft* draft, Random* random, Proportion proportion) {
  Vec3d s(random->Uniform(0.4, 1.5), random->Uniform(0.4, 1.5), random->Uniform(0.4, 1.5));
  if (proportion == Proportion::kColumn) s = Vec3d(random->Uniform(0.35, 0.8), 0, random->Uniform(0.9, 1.7)), s.y() = s.x() * random->Uniform(0.8, 1.25);
  if (proportion == Proportion::kSlab) s = Vec3d(random->Uniform(0.8, 1.6), random->Uniform(0.6, 1.3), random->Uniform(0.06, 0.16));
  if (proportion == Proportion::kLong) s = Vec3d(random->Uniform(1.2, 1.8), random->Uniform(0.3, 0.6), random->Uniform(0.3, 0.6));
  if ((s - Vec3d::Ones()).cwiseAbs().maxCoeff() < 0.1) s.x() += 0.3;
  return draft->TryAppend(build::GlobalScale(s));
}

bool Profile(Draft* draft, Random* random, int axis) {
  const int cuts = random->Weighted({0, 3, 3, 2, 1});
  if (!draft->TryAppend(build::LoopCut(ToAxis(axis), cuts, Vec3d::Zero()))) return false;
  const std::vector<double> levels = draft->LoopLevels(axis);
  if (levels.empty()) return false;
  const int shaped = random->Int(1, std::min<int>(3, levels.size()));
  std::vector<int> order(levels.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  for (size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[random->Int(0, static_cast<int>(i) - 1)]);
  bool any = false;
  for (int k = 0; k < shaped; ++k) {
    const build::VertexTarget loop = draft->LoopTarget(axis, levels[order[k]]);
    if (loop.expect < 3) continue;
    const int kind = random->Weighted({0.64, 0.16, 0.2});
    Json op;
    if (kind == 0) {
      Vec3d scale = Vec3d::Constant(Factor(random, 0.5, 1.5, 0.12));
      if (random->Chance(0.25)) scale[(axis + 1) % 3] *= random->Uniform(0.75, 1.25);
      scale[axis] = 1;
      op = build::EdgeLoopScale(loop, scale);
    } else if (kind == 1) {  // a stepped or offset profile
      Vec3d offset = Vec3d::Zero();
      const int across = (axis + random->Int(1, 2)) % 3;
      offset[across] = random->SignedUniform(0.12, 0.3) * draft->Extent()[across];
      if (random->Chance(0.3)) offset[axis] = random->SignedUniform(0.1, 0.2) * draft->Extent()[axis] / (cuts + 1);
      op = build::EdgeLoopTranslate(loop, offset);
    } else {  // a tilted loop
      Vec3d rotation = Vec3d::Zero();
      rotation[(axis + random->Int(1, 2)) % 3] = random->SignedUniform(8, 25);
      op = build::EdgeLoopRotate(loop, rotation);
    }
    any = draft->TryAppend(op) || any;
  }
  return any;
}

bool Deform(Draft* draft, Random* random, int main_axis) {
  const int kind = random->Weighted({2.0, 1.2, 1.1, 1.5});
  const build::Deform deform = static_cast<build::Deform>(kind);
  int axis = main_axis;
  // Bend about X or Y deforms along Z, about Z along X (ops/simple_deform.h).
  int along = axis;
  if (deform == build::Deform::kBend) {
    axis = main_axis == 2 ? random->Int(0, 1) : 2;
    along = axis == 2 ? 0 : 2;
  }
  if (deform != build::Deform::kTaper && !EnsureLoops(draft, random, along, 3, 6)) return false;
  double amount = 0;
  switch (deform) {
    case build::Deform::kTwist: amount = random->SignedUniform(25, 110); break;
    case build::Deform::kBend: amount = random->SignedUniform(25, 90); break;
    case build::Deform::kTaper: amount = random->SignedUniform(0.3, 0.9); break;
    case build::Deform::kStretch: amount = random->SignedUniform(0.15, 0.4); break;
  }
  return draft->TryAppend(build::SimpleDeform(deform, ToAxis(axis), amount));
}

bool SlabGrid(Draft* draft, Random* random) {
  for (int axis : {0, 1}) {
    if (!draft->TryAppend(build::LoopCut(ToAxis(axis), 2, Vec3d::Zero()))) return false;
    // The two loops (at +-1/3 of the half extent) pushed out towards the rim.
    build::VertexTarget loops;
    loops.box.lo[axis] = -0.5 * draft->Extent()[axis] / 2;
    loops.box.hi[axis] = 0.5 * draft->Extent()[axis] / 2;
    loops.expect = draft->CountInside(loops.box);
    Vec3d scale = Vec3d::Ones();
    scale[axis] = random->Uniform(1.9, 2.6);
    if (!draft->TryAppend(build::EdgeLoopScale(loops, scale))) return false;
  }
  return true;
}

}  // namespace synth
}  // namespace opgraph
