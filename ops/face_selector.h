// Names a set of faces so that it survives edits of the sequence, geometrically:
//   "normal": [x, y, z] with "min_dot" (default 0.99): faces whose unit normal . n >= min_dot;
//   "normal_any": [[...], ...]: the normal test against any of several directions;
//   "box": [[xmin, ymin, zmin], [xmax, ymax, zmax]] on the face's median centre (null = open);
//   "centers": [[x, y, z], ...]: of the faces passing the other tests, the one whose median
//              centre is nearest each point;
//   "expect": n: the required count (a changed count is an error, not a wrong edit);
//   "indices": [...]: explicit face indices (for generated sequences).
// Slivers are skipped by the geometric tests (kMinFaceShape).
// Blender: the same rule in Python (kFaceSelectorPython), run on Blender's own mesh.
#pragma once

#include <optional>
#include <vector>

#include "core/mesh.h"
#include "ops/box.h"
#include "ops/params.h"

namespace opgraph {

class FaceSelector {
 public:
  FaceSelector(const Json& json, const std::string& field);

  // Selected face indices, ascending. Throws FieldError(field) when none is selected, an index
  // does not exist, or the count differs from `expect`.
  std::vector<int> Resolve(const Mesh& mesh) const;
  Json ToJson() const;
  // Python expression: the list of selected BMFaces of bmesh `bm`.
  std::string PythonExpr(const std::string& bm_var) const;

 private:
  std::string field_;
  std::vector<Vec3d> normals_;
  double min_dot_ = 0.99;
  bool normal_any_ = false;
  Box box_;
  std::vector<Vec3d> centers_;
  std::vector<int> indices_;
  int expect_ = -1;
};

// Slivers are never selected by the geometric tests (explicit indices still select them): a
// face is selectable when twice its area exceeds this fraction of its largest vertex distance
// squared (1 for a square, 0.2 for a 10:1 rectangle). Below it the normal is ill-conditioned:
// Blender's float32 coordinates turn it into noise of up to 1e-4, which moves an extrusion.
constexpr double kMinFaceShape = 0.05;

// Python for select_faces(...); expects kMinFaceShape defined before it (ops/sequence.cc).
extern const char* kFaceSelectorPython;

}  // namespace opgraph
