#include "benchmarks/synth/synth_draft.h"

#include <algorithm>

#include "core/geometry.h"
#include "ops/face_selector.h"
#include "ops/op.h"
#include "ops/sequence.h"

namespace opgraph {
namespace synth {

Draft::Draft() : start_(MakeCube(2.0)) {}

bool Draft::TryAppend(const std::vector<Json>& ops) {
  std::vector<Mesh> added;
  try {
    for (const Json& entry : ops) {
      std::unique_ptr<Op> op = CreateOp(entry.at("op"), entry.at("params"));
      added.push_back(ApplyOp(op.get(), 1.0, added.empty() ? mesh() : added.back()));
      if (!added.back().Validate().empty()) return false;
    }
  } catch (const std::exception&) {  // the engine refuses the op here: the draft stays as it is
    return false;
  }
  ops_.insert(ops_.end(), ops.begin(), ops.end());
  steps_.insert(steps_.end(), added.begin(), added.end());
  return true;
}

bool Draft::Has(const std::string& op_name) const {
  for (const Json& op : ops_) {
    if (op.at("op") == op_name) return true;
  }
  return false;
}

Vec3d Draft::Lo() const {
  Vec3d lo = mesh().vertices[0];
  for (const Vec3d& v : mesh().vertices) lo = lo.cwiseMin(v);
  return lo;
}

Vec3d Draft::Hi() const {
  Vec3d hi = mesh().vertices[0];
  for (const Vec3d& v : mesh().vertices) hi = hi.cwiseMax(v);
  return hi;
}

Vec3d Draft::FaceCenter(int face) const {
  Vec3d sum = Vec3d::Zero();
  for (int v : mesh().faces[face]) sum += mesh().vertices[v];
  return sum / static_cast<double>(mesh().faces[face].size());
}

Vec3d Draft::FaceNormal(int face) const { return FaceAreaNormal(mesh().vertices, mesh().faces[face]).normalized(); }

double Draft::FaceArea(int face) const { return FaceAreaNormal(mesh().vertices, mesh().faces[face]).norm(); }

std::vector<int> Draft::FacesFacing(const Vec3d& direction, double min_dot) const {
  std::vector<int> faces;
  const Vec3d d = direction.normalized();
  for (int f = 0; f < mesh().NumFaces(); ++f) {
    const Polygon& loop = mesh().faces[f];
    double span = 0;
    for (int a : loop) {
      for (int b : loop) span = std::max(span, (mesh().vertices[a] - mesh().vertices[b]).squaredNorm());
    }
    // Twice the margin of the selectors' sliver rule, so float32 rounding cannot flip it.
    if (FaceArea(f) <= 2 * kMinFaceShape * span) continue;
    if (FaceNormal(f).dot(d) >= min_dot) faces.push_back(f);
  }
  return faces;
}

build::FaceTarget Draft::TargetOf(int face) const {
  build::FaceTarget target;
  target.normals = {FaceNormal(face)};
  target.centers = {FaceCenter(face)};
  target.expect = 1;
  return target;
}

int Draft::ExtremeFace(const Vec3d& direction) const {
  int best = -1;
  for (int f : FacesFacing(direction)) {
    if (best < 0 || FaceCenter(f).dot(direction) > FaceCenter(best).dot(direction) + 1e-9) best = f;
  }
  return best;
}

std::vector<double> Draft::LoopLevels(int axis) const {
  const double lo = Lo()[axis], hi = Hi()[axis], tol = 1e-6 * Diagonal();
  std::vector<double> values;
  for (const Vec3d& v : mesh().vertices) {
    if (v[axis] > lo + 1e-3 * Diagonal() && v[axis] < hi - 1e-3 * Diagonal()) values.push_back(v[axis]);
  }
  std::sort(values.begin(), values.end());
  std::vector<double> levels;
  for (size_t i = 0; i < values.size();) {
    size_t j = i;
    while (j < values.size() && values[j] - values[i] < tol) ++j;
    if (j - i >= 3) levels.push_back(values[i]);
    i = j;
  }
  return levels;
}

build::VertexTarget Draft::LoopTarget(int axis, double level) const {
  double gap = Extent()[axis];
  for (const Vec3d& v : mesh().vertices) {
    const double d = std::abs(v[axis] - level);
    if (d > 1e-6 * Diagonal()) gap = std::min(gap, d);
  }
  build::VertexTarget target;
  target.box.lo[axis] = level - 0.25 * gap;
  target.box.hi[axis] = level + 0.25 * gap;
  target.expect = CountInside(target.box);
  return target;
}

build::VertexTarget Draft::BoxAround(const std::vector<Vec3d>& points) const {
  Vec3d lo = points[0], hi = points[0];
  for (const Vec3d& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double margin = 1e-3 * Diagonal();
  build::VertexTarget target;
  for (int k = 0; k < 3; ++k) target.box.lo[k] = lo[k] - margin, target.box.hi[k] = hi[k] + margin;
  target.expect = CountInside(target.box);
  return target;
}

int Draft::CountInside(const Box& box) const {
  int count = 0;
  for (const Vec3d& v : mesh().vertices) count += box.Contains(v);
  return count;
}

}  // namespace synth
}  // namespace opgraph
