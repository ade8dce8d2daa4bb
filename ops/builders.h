// Typed builders of operation entries ({"op": name, "params": {...}}): the one place outside
// the ops themselves that knows each op's JSON names, so code that makes sequences (the
// synthetic corpus, the search) gets a compile error, not a silently rejected op, when a
// schema changes. Every builder's output parses (ops/builders_test.cc).
#pragma once

#include <vector>

#include "ops/box.h"
#include "ops/params.h"

namespace opgraph {
namespace build {

enum class Axis { kX, kY, kZ };
std::string AxisName(Axis axis);
// The axis AxisName gives `name` ("X", "Y" or "Z"); Z for any other name.
Axis AxisNamed(const std::string& name);
Vec3d AxisVector(Axis axis);

// Faces named geometrically (ops/face_selector.h).
struct FaceTarget {
  std::vector<Vec3d> normals;  // one: "normal"; several: "normal_any"; none: any direction
  double min_dot = 0.99;
  Box box;                     // on the face's median centre
  std::vector<Vec3d> centers;  // the face nearest each point
  int expect = -1;             // required count (< 0: any)
  Json ToJson() const;
};

// Vertices inside an axis-aligned box (ops/vertex_selector.h).
struct VertexTarget {
  Box box;
  int expect = -1;
  Json ToJson() const;
};

Json GlobalScale(const Vec3d& scale);
Json GlobalRotate(const Vec3d& rotation_deg);
Json GlobalTranslate(const Vec3d& offset);

enum class Deform { kTwist, kBend, kTaper, kStretch };
// `amount`: degrees for Twist and Bend, the factor for Taper and Stretch.
Json SimpleDeform(Deform kind, Axis axis, double amount, double limit_lo = 0, double limit_hi = 1);

Json Subdivision(int levels);
Json Mirror(const std::vector<Axis>& axes);
Json LoopCut(Axis axis, int cuts, const Vec3d& near);
Json KnifeEdges(const FaceTarget& face, const Vec3d& edge_point_a, const Vec3d& edge_point_b);
Json KnifePlane(const Vec3d& plane_co, const Vec3d& plane_no);

struct ExtrudeArgs {
  FaceTarget faces;
  bool individual = false;  // each face along its own normal, else one region
  double height = 0;
  double width = 1;
  double tilt_deg[2] = {0, 0};
};
Json Extrude(const ExtrudeArgs& args);
Json Inset(const FaceTarget& faces, double thickness, double depth = 0);

Json EdgeLoopScale(const VertexTarget& verts, const Vec3d& scale);
Json EdgeLoopRotate(const VertexTarget& verts, const Vec3d& rotation_deg);
Json EdgeLoopTranslate(const VertexTarget& verts, const Vec3d& offset);

struct DisplaceGroup {
  VertexTarget verts;
  Vec3d offset;
};
Json VertexDisplace(const std::vector<DisplaceGroup>& groups);

// `angle_limit_deg` < 0: every edge (limit NONE), else the ANGLE limit.
Json Bevel(double width, int segments, double angle_limit_deg = -1);

enum class Primitive { kCube, kPrism6, kPrism8, kCylinder };
std::string PrimitiveName(Primitive primitive);
struct BooleanArgs {
  bool difference = false;  // else union
  Primitive primitive = Primitive::kCube;
  Vec3d size = Vec3d::Ones();  // full extents
  Vec3d rotation_deg = Vec3d::Zero();
  Vec3d location = Vec3d::Zero();
};
Json Boolean(const BooleanArgs& args);

// A whole sequence document from the default cube.
Json Document(const std::vector<Json>& operations);

}  // namespace build
}  // namespace opgraph
