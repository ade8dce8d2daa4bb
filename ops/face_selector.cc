#include "ops/face_selector.h"

#include <algorithm>
#include <limits>

#include <Eigen/Geometry>

#include "core/geometry.h"
#include "core/printable.h"

namespace opgraph {

const char* kFaceSelectorPython = R"PY(
def select_faces(bm, normals, min_dot, lo, hi, centers, indices, expect):
    bm.faces.ensure_lookup_table()
    if indices is not None:
        found = [bm.faces[i] for i in indices if i < len(bm.faces)]
    else:
        def inside(f):
            c = f.calc_center_median()
            return all((lo[k] is None or c[k] >= lo[k]) and (hi[k] is None or c[k] <= hi[k]) for k in range(3))
        def well_shaped(f):
            span = max((a.co - b.co).length_squared for a in f.verts for b in f.verts)
            return 2 * f.calc_area() > kMinFaceShape * span
        found = [f for f in bm.faces
                 if well_shaped(f)
                 and (not normals or any(f.normal.dot(Vector(n).normalized()) >= min_dot for n in normals))
                 and inside(f)]
        if centers:
            picked = []
            for p in centers:
                if found:
                    best = min(found, key=lambda f: (f.calc_center_median() - Vector(p)).length)
                    if best not in picked:
                        picked.append(best)
            found = sorted(picked, key=lambda f: f.index)
    if not found or (expect >= 0 and len(found) != expect):
        raise RuntimeError('face selection found %d faces, expected %d' % (len(found), expect))
    return found
)PY";

FaceSelector::FaceSelector(const Json& json, const std::string& field) : field_(field) {
  if (!json.is_object()) throw FieldError(field, "must be a face selector object");
  for (auto it = json.begin(); it != json.end(); ++it) {
    static const std::vector<std::string> kKeys = {"normal", "normal_any", "min_dot", "box", "centers", "indices", "expect"};
    if (std::find(kKeys.begin(), kKeys.end(), it.key()) == kKeys.end()) {
      throw FieldError(field + "." + Printable(it.key()), "unknown key");
    }
  }
  if (json.contains("normal")) normals_.push_back(CheckedVector3(json["normal"], field + ".normal", -1e6, 1e6));
  if (json.contains("normal_any")) {
    if (!json["normal_any"].is_array()) throw FieldError(field + ".normal_any", "must be a list of vectors");
    for (const Json& n : json["normal_any"]) normals_.push_back(CheckedVector3(n, field + ".normal_any", -1e6, 1e6));
  }
  for (const Vec3d& n : normals_) {
    if (n.norm() < 1e-9) throw FieldError(field + ".normal", "must not be zero");
  }
  if (json.contains("min_dot")) min_dot_ = CheckedNumber(json["min_dot"], field + ".min_dot", -1, 1);
  if (json.contains("box")) {
    box_ = Box::Parse(json["box"], field + ".box");
  }
  if (json.contains("centers")) {
    if (!json["centers"].is_array()) throw FieldError(field + ".centers", "must be a list of points");
    for (const Json& c : json["centers"]) centers_.push_back(CheckedVector3(c, field + ".centers", -1e9, 1e9));
  }
  if (json.contains("indices")) {
    indices_ = CheckedIndices(json["indices"], field + ".indices");
  }
  if (json.contains("expect")) expect_ = CheckedInteger(json["expect"], field + ".expect", 1, 1000000000);
}

std::vector<int> FaceSelector::Resolve(const Mesh& mesh) const {
  std::vector<int> found;
  if (!indices_.empty()) {
    for (int i : indices_) {
      if (i >= mesh.NumFaces()) throw FieldError(field_, "face " + std::to_string(i) + " does not exist at this step");
      found.push_back(i);
    }
  } else {
    for (int f = 0; f < mesh.NumFaces(); ++f) {
      // A sliver (a side of a near-zero-height extrusion, a folded quad) has an ill-conditioned
      // normal: in Blender's float32 coordinates it is noise, so it is never selected.
      const Polygon& face = mesh.faces[f];
      double span = 0;
      for (int a : face) {
        for (int b : face) span = std::max(span, (mesh.vertices[a] - mesh.vertices[b]).squaredNorm());
      }
      const Vec3d area_normal = FaceAreaNormal(mesh.vertices, face);  // length: twice the area
      if (!(area_normal.norm() > kMinFaceShape * span)) continue;
      const Vec3d normal = area_normal.normalized();
      const Vec3d c = FaceCentroid(mesh.vertices, mesh.faces[f]);
      bool ok = normals_.empty();
      for (const Vec3d& n : normals_) ok = ok || normal.dot(n.normalized()) >= min_dot_;
      ok = ok && box_.Contains(c);
      if (ok) found.push_back(f);
    }
    if (!centers_.empty()) {
      // A point (nearly) as near to two faces names neither: Blender's float32 centres could
      // pick the other one.
      Eigen::AlignedBox3d bounds;
      for (const Vec3d& v : mesh.vertices) bounds.extend(v);
      const double tie = 1e-5 * bounds.diagonal().norm();
      std::vector<int> picked;
      for (const Vec3d& p : centers_) {
        int best = -1;
        double best_d = std::numeric_limits<double>::max(), second_d = best_d;
        for (int f : found) {
          const double d = (FaceCentroid(mesh.vertices, mesh.faces[f]) - p).norm();
          if (d < best_d) {
            second_d = best_d, best_d = d, best = f;
          } else if (d < second_d) {
            second_d = d;
          }
        }
        if (best >= 0 && second_d - best_d < tie) {
          throw FieldError(field_ + ".centers", "a point is as near to two faces; it names neither");
        }
        if (best >= 0 && std::find(picked.begin(), picked.end(), best) == picked.end()) picked.push_back(best);
      }
      std::sort(picked.begin(), picked.end());
      found = picked;
    }
  }
  CheckSelectionCount(found.size(), expect_, field_, "faces");
  return found;
}

Json FaceSelector::ToJson() const {
  Json j;
  if (!indices_.empty()) j["indices"] = indices_;
  if (normals_.size() == 1) j["normal"] = opgraph::ToJson(normals_[0]);
  if (normals_.size() > 1) {
    j["normal_any"] = Json::array();
    for (const Vec3d& n : normals_) j["normal_any"].push_back(opgraph::ToJson(n));
  }
  if (!normals_.empty()) j["min_dot"] = min_dot_;
  if (box_.Bounded()) j["box"] = box_.ToJson();
  if (!centers_.empty()) {
    j["centers"] = Json::array();
    for (const Vec3d& c : centers_) j["centers"].push_back(opgraph::ToJson(c));
  }
  if (expect_ >= 0) j["expect"] = expect_;
  return j;
}

std::string FaceSelector::PythonExpr(const std::string& bm_var) const {
  auto list = [](const std::vector<Vec3d>& vs) {
    std::string s = "[";
    for (const Vec3d& v : vs) s += PyVec(v) + ", ";
    return s + "]";
  };
  std::string indices = "None";
  if (!indices_.empty()) {
    indices = "[";
    for (int i : indices_) indices += std::to_string(i) + ", ";
    indices += "]";
  }
  return "select_faces(" + bm_var + ", " + list(normals_) + ", " + Py(min_dot_) + ", " + box_.PythonArgs() + ", " + list(centers_) + ", " + indices + ", " + std::to_string(expect_) + ")";
}

}  // namespace opgraph
