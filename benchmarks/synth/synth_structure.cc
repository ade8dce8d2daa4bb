#include <algorithm>

#include "benchmarks/synth/synth_moves.h"

namespace opgraph {
namespace synth {
namespace {

const Vec3d kDirections[6] = {Vec3d::UnitX(), -Vec3d::UnitX(), Vec3d::UnitY(),
                              -Vec3d::UnitY(), Vec3d::UnitZ(),  -Vec3d::UnitZ()};

// A face to build on: the extreme face along a random axis direction, or any face facing it.
int PickFace(Draft* draft, Random* random, Vec3d* direction) {
  for (int attempt = 0; attempt < 6; ++attempt) {
    *direction = kDirections[random->Int(0, 5)];
    std::vector<int> faces = draft->FacesFacing(*direction, 0.95);
    if (faces.empty()) continue;
    if (random->Chance(0.6)) return draft->ExtremeFace(*direction);
    return faces[random->Int(0, static_cast<int>(faces.size()) - 1)];
  }
  return -1;
}

// The face's smallest half size: the distance from its centre to its nearest vertex.
double HalfSize(const Draft& draft, int face) {
  const Vec3d c = draft.FaceCenter(face);
  double size = 1e300;
  for (int v : draft.mesh().faces[face]) size = std::min(size, (draft.mesh().vertices[v] - c).norm());
  return size / std::sqrt(2.0);
}

// The object's depth behind `face` along -normal (how deep a cavity may go).
double DepthBehind(const Draft& draft, int face) {
  const Vec3d n = draft.FaceNormal(face), c = draft.FaceCenter(face);
  double depth = 0;
  for (const Vec3d& v : draft.mesh().vertices) depth = std::max(depth, (c - v).dot(n));
  return depth;
}

}  // namespace

bool ExtrudeFace(Draft* draft, Random* random) {
  Vec3d direction;
  const int face = PickFace(draft, random, &direction);
  if (face < 0) return false;
  build::ExtrudeArgs args;
  args.faces = draft->TargetOf(face);
  args.height = random->Uniform(0.15, 0.6) * draft->Extent().maxCoeff();
  args.width = random->Chance(0.5) ? 1.0 : random->Uniform(0.6, 1.2);
  if (random->Chance(0.25)) args.tilt_deg[random->Int(0, 1)] = random->SignedUniform(8, 25);
  return draft->TryAppend(build::Extrude(args));
}

bool InsetExtrude(Draft* draft, Random* random, bool deep_cavity) {
  Vec3d direction;
  int face = -1;
  if (deep_cavity) {
    face = draft->ExtremeFace(Vec3d::UnitZ());
  } else {
    face = PickFace(draft, random, &direction);
  }
  if (face < 0) return false;
  const build::FaceTarget target = draft->TargetOf(face);
  const double half = HalfSize(*draft, face);
  const double thickness = (deep_cavity ? random->Uniform(0.08, 0.2) : random->Uniform(0.12, 0.4)) * half;
  if (!draft->TryAppend(build::Inset(target, thickness))) return false;
  build::ExtrudeArgs args;
  args.faces = target;  // the inner face keeps the normal and centre
  const double depth = DepthBehind(*draft, face);
  if (deep_cavity) {
    args.height = -random->Uniform(0.55, 0.85) * depth;
  } else if (random->Chance(0.5)) {
    args.height = -random->Uniform(0.1, 0.35) * depth;
  } else {
    args.height = random->Uniform(0.08, 0.4) * draft->Extent().maxCoeff();
    if (random->Chance(0.3)) args.width = random->Uniform(0.6, 0.9);
  }
  return draft->TryAppend(build::Extrude(args));
}

bool Panels(Draft* draft, Random* random) {
  build::FaceTarget target;
  if (random->Chance(0.5)) {  // every face of the block
    for (const Vec3d& d : kDirections) target.normals.push_back(d);
    target.min_dot = 0.95;
  } else {  // the faces of one side
    target.normals = {kDirections[random->Int(0, 5)]};
  }
  int count = 0;
  for (const Vec3d& d : target.normals) count += static_cast<int>(draft->FacesFacing(d, target.min_dot).size());
  if (count < 2 || count > 60) return false;
  target.expect = count;
  build::ExtrudeArgs args;
  args.faces = target;
  args.individual = true;
  args.height = random->SignedUniform(0.03, 0.1) * draft->Extent().minCoeff();
  args.width = random->Uniform(0.6, 0.9);
  return draft->TryAppend(build::Extrude(args));
}

bool Chain(Draft* draft, Random* random) {
  Vec3d direction;
  int face = PickFace(draft, random, &direction);
  if (face < 0) return false;
  const int links = random->Int(2, 4);
  const double step = random->Uniform(0.2, 0.45) * draft->Extent().maxCoeff();
  std::vector<std::vector<Vec3d>> joints;  // each intermediate cap's corners
  for (int k = 0; k < links; ++k) {
    build::ExtrudeArgs args;
    args.faces = draft->TargetOf(face);
    args.height = step * random->Uniform(0.7, 1.3);
    args.width = random->Uniform(0.75, 1.05);
    if (random->Chance(0.5)) args.tilt_deg[random->Int(0, 1)] = random->SignedUniform(8, 25);
    const Vec3d normal = draft->FaceNormal(face);
    if (!draft->TryAppend(build::Extrude(args))) return k > 0;
    face = draft->ExtremeFace(normal);  // the new cap (tilts stay within 25 degrees)
    if (face < 0) return true;
    for (int f : draft->FacesFacing(normal, 0.8)) {
      if (draft->FaceCenter(f).dot(normal) > draft->FaceCenter(face).dot(normal)) face = f;
    }
    if (k + 1 < links) {
      std::vector<Vec3d> corners;
      for (int v : draft->mesh().faces[face]) corners.push_back(draft->mesh().vertices[v]);
      joints.push_back(corners);
    }
  }
  if (!joints.empty() && random->Chance(0.6)) {
    const build::VertexTarget ring = draft->BoxAround(joints[random->Int(0, static_cast<int>(joints.size()) - 1)]);
    if (ring.expect == 4) {
      const double f = random->Chance(0.5) ? random->Uniform(0.55, 0.85) : random->Uniform(1.15, 1.4);
      draft->TryAppend(build::EdgeLoopScale(ring, Vec3d::Constant(f)));
    }
  }
  return true;
}

bool BooleanFeature(Draft* draft, Random* random, bool difference) {
  const int axis = random->Int(0, 2);
  const double side = random->Sign();
  const Vec3d lo = draft->Lo(), hi = draft->Hi(), extent = draft->Extent(), centre = 0.5 * (lo + hi);
  build::BooleanArgs args;
  args.difference = difference;
  args.primitive = static_cast<build::Primitive>(random->Weighted({1, 0.6, 0.6, 1}));
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  // The primitive's own axis (+Z) along `axis`.
  if (axis == 0) args.rotation_deg = Vec3d(0, 90, 0);
  if (axis == 1) args.rotation_deg = Vec3d(90, 0, 0);
  // Turned about its own axis: prisms by a visible angle; cylinders slightly, so that no vertex of
  // theirs lies exactly on a face diagonal of the block (a degenerate contact the engine refuses).
  args.rotation_deg.z() = args.primitive == build::Primitive::kCylinder || random->Chance(0.6) ? random->Uniform(2, 9)
                                                                                               : random->Uniform(10, 45);
  const double across = random->Uniform(0.15, 0.5);
  Vec3d size;
  size.x() = across * std::min(extent[u], extent[v]);
  size.y() = args.primitive == build::Primitive::kCube ? random->Uniform(0.6, 1.6) * size.x() : size.x();
  Vec3d location = centre;
  location[u] += random->Uniform(-0.3, 0.3) * extent[u];
  location[v] += random->Uniform(-0.3, 0.3) * extent[v];
  const double face = side > 0 ? hi[axis] : lo[axis];
  const int kind = random->Weighted({difference ? 1.5 : 0.0, 1.0});
  if (kind == 0) {  // a hole right through
    size.z() = 1.5 * extent[axis];
    location[axis] = centre[axis];
  } else {  // a pocket, or a boss standing on the face
    const double depth = random->Uniform(0.15, 0.45) * extent[axis];
    size.z() = difference ? 2 * depth : depth + 0.1 * extent[axis];
    location[axis] = difference ? face : face + side * (0.5 * size.z() - 0.1 * extent[axis]);
  }
  // The primitive's local size maps to the world through the axis rotation.
  args.size = Vec3d(size.x(), size.y(), size.z());
  args.location = location;
  return draft->TryAppend(build::Boolean(args));
}

}  // namespace synth
}  // namespace opgraph
