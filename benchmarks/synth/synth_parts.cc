#include <algorithm>

#include "benchmarks/synth/synth_moves.h"

namespace opgraph {
namespace synth {
namespace {

build::Axis ToAxis(int axis) { return static_cast<build::Axis>(axis); }

// The faces facing `direction` whose centre is extreme along `along` (within `tol`).
std::vector<int> ExtremeRow(const Draft& draft, const Vec3d& direction, const Vec3d& along, double tol) {
  const std::vector<int> faces = draft.FacesFacing(direction);
  double best = -1e300;
  for (int f : faces) best = std::max(best, draft.FaceCenter(f).dot(along));
  std::vector<int> row;
  for (int f : faces) {
    if (draft.FaceCenter(f).dot(along) > best - tol) row.push_back(f);
  }
  return row;
}

}  // namespace

bool Legs(Draft* draft, Random* random) {
  const double tol = 1e-6 * draft->Diagonal();
  build::FaceTarget corners;
  corners.normals = {-Vec3d::UnitZ()};
  for (double sx : {-1.0, 1.0}) {
    for (double sy : {-1.0, 1.0}) {
      const std::vector<int> row = ExtremeRow(*draft, -Vec3d::UnitZ(), Vec3d(sx, sy, 0).normalized(), tol);
      if (row.size() != 1) return false;
      corners.centers.push_back(draft->FaceCenter(row[0]));
    }
  }
  corners.expect = 4;
  build::ExtrudeArgs args;
  args.faces = corners;
  args.individual = true;
  args.height = random->Uniform(0.5, 1.2) * draft->Extent().head<2>().minCoeff();
  if (random->Chance(0.4)) args.width = random->Uniform(0.6, 0.9);
  return draft->TryAppend(build::Extrude(args));
}

bool Backrest(Draft* draft, Random* random) {
  const Vec3d along = Vec3d::UnitY() * random->Sign();
  const std::vector<int> row = ExtremeRow(*draft, Vec3d::UnitZ(), along, 1e-6 * draft->Diagonal());
  if (row.size() < 2) return false;
  build::ExtrudeArgs args;
  args.faces.normals = {Vec3d::UnitZ()};
  for (int f : row) args.faces.centers.push_back(draft->FaceCenter(f));
  args.faces.expect = static_cast<int>(row.size());
  args.height = random->Uniform(0.5, 1.0) * draft->Extent().x();
  if (random->Chance(0.5)) args.tilt_deg[1] = -along.y() * random->Uniform(5, 15);
  return draft->TryAppend(build::Extrude(args));
}

bool Facets(Draft* draft, Random* random) {
  const int kind = random->Weighted({1, 1, 0.6});
  const Vec3d lo = draft->Lo(), hi = draft->Hi(), extent = draft->Extent();
  if (kind == 0) {  // a ridge across a face: knife between two edge midpoints, midpoints raised
    const Vec3d direction = Vec3d::Unit(random->Int(0, 2)) * random->Sign();
    const int face = draft->ExtremeFace(direction);
    if (face < 0 || draft->mesh().faces[face].size() != 4) return false;
    const Polygon& loop = draft->mesh().faces[face];
    const int first = random->Int(0, 1);
    const Vec3d a = 0.5 * (draft->mesh().vertices[loop[first]] + draft->mesh().vertices[loop[first + 1]]);
    const Vec3d b = 0.5 * (draft->mesh().vertices[loop[first + 2]] + draft->mesh().vertices[loop[(first + 3) % 4]]);
    const Vec3d normal = draft->FaceNormal(face);
    if (!draft->TryAppend(build::KnifeEdges(draft->TargetOf(face), a, b))) return false;
    const double rise = random->Uniform(0.1, 0.3) * extent.minCoeff();
    std::vector<build::DisplaceGroup> groups = {{draft->BoxAround({a}), normal * rise},
                                                {draft->BoxAround({b}), normal * rise * random->Uniform(0.5, 1.5)}};
    if (groups[0].verts.expect != 1 || groups[1].verts.expect != 1) return false;
    return draft->TryAppend(build::VertexDisplace(groups));
  }
  if (kind == 1) {  // a bisecting knife and its new loop scaled: a faceted waist
    const int axis = random->Int(0, 2);
    Vec3d co = 0.5 * (lo + hi);
    co[axis] += random->Uniform(-0.3, 0.3) * extent[axis];
    for (double level : draft->LoopLevels(axis)) {
      if (std::abs(level - co[axis]) < 0.05 * extent[axis]) return false;
    }
    if (!draft->TryAppend(build::KnifePlane(co, Vec3d::Unit(axis)))) return false;
    const build::VertexTarget loop = draft->LoopTarget(axis, co[axis]);
    if (loop.expect < 3) return false;
    Vec3d scale = Vec3d::Constant(random->Chance(0.5) ? random->Uniform(0.6, 0.85) : random->Uniform(1.15, 1.4));
    scale[axis] = 1;
    return draft->TryAppend(build::EdgeLoopScale(loop, scale));
  }
  // Chipped corners: corner vertices pulled in.
  std::vector<build::DisplaceGroup> groups;
  const int count = random->Int(1, 3);
  for (int k = 0; k < count; ++k) {
    const Vec3d corner(random->Chance(0.5) ? lo.x() : hi.x(), random->Chance(0.5) ? lo.y() : hi.y(),
                       random->Chance(0.5) ? lo.z() : hi.z());
    const build::VertexTarget near_corner = draft->BoxAround({corner});
    if (near_corner.expect != 1) continue;
    const Vec3d inward = (0.5 * (lo + hi) - corner).normalized();
    groups.push_back({near_corner, inward * random->Uniform(0.1, 0.25) * extent.minCoeff()});
  }
  return !groups.empty() && draft->TryAppend(build::VertexDisplace(groups));
}

bool Ridge(Draft* draft, Random* random) {
  const int axis = random->Int(0, 1);
  if (!draft->TryAppend(build::LoopCut(ToAxis(axis), 1, Vec3d::Zero()))) return false;
  const std::vector<double> levels = draft->LoopLevels(axis);
  if (levels.size() != 1) return false;
  build::VertexTarget top = draft->LoopTarget(axis, levels[0]);
  top.box.lo[2] = draft->Hi().z() - 1e-3 * draft->Diagonal();
  top.expect = draft->CountInside(top.box);
  if (top.expect != 2) return false;
  return draft->TryAppend(build::VertexDisplace({{top, Vec3d(0, 0, random->Uniform(0.3, 0.8) * draft->Extent().z())}}));
}

bool MirrorPair(Draft* draft, Random* random) {
  std::vector<build::Axis> axes = {build::Axis::kX};
  if (random->Chance(0.3)) axes.push_back(build::Axis::kY);
  Vec3d offset = Vec3d::Zero(), gap = Vec3d::Zero();
  for (build::Axis axis : axes) {
    const int k = static_cast<int>(axis);
    gap[k] = random->Uniform(0.08, 0.4) * draft->Extent()[k];
    offset[k] = gap[k] - draft->Lo()[k];
  }
  if (!draft->TryAppend(std::vector<Json>{build::GlobalTranslate(offset), build::Mirror(axes)})) return false;
  if (axes.size() == 1 && random->Chance(0.5)) {  // a bar joining the pair
    const Vec3d extent = draft->Extent(), centre = 0.5 * (draft->Lo() + draft->Hi());
    build::BooleanArgs bar;
    bar.primitive = random->Chance(0.5) ? build::Primitive::kCube : build::Primitive::kCylinder;
    bar.rotation_deg = Vec3d(0, 90, 0);  // the primitive's axis along X
    const double thickness = random->Uniform(0.2, 0.4) * std::min(extent.y(), extent.z());
    bar.size = Vec3d(thickness, thickness, 2 * gap.x() + 0.3 * (extent.x() / 2 - gap.x()));
    bar.location = Vec3d(0, centre.y(), centre.z());
    draft->TryAppend(build::Boolean(bar));
  }
  return true;
}

}  // namespace synth
}  // namespace opgraph
