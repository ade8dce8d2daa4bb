#include "ops/vertex_selector.h"

#include "core/printable.h"

namespace opgraph {

const char* kVertexSelectorPython = R"PY(
def select_verts(me, lo, hi, indices, expect):
    if indices is not None:
        found = [i for i in indices if i < len(me.vertices)]
    else:
        found = [v.index for v in me.vertices
                 if all((lo[k] is None or v.co[k] >= lo[k]) and (hi[k] is None or v.co[k] <= hi[k])
                        for k in range(3))]
    if not found or (expect >= 0 and len(found) != expect):
        raise RuntimeError('vertex selection found %d vertices, expected %d' % (len(found), expect))
    return found
)PY";

VertexSelector::VertexSelector(const Json& json, const std::string& field) : field_(field) {
  if (!json.is_object()) throw FieldError(field, "must be an object with 'box' or 'indices'");
  for (auto it = json.begin(); it != json.end(); ++it) {
    if (it.key() != "box" && it.key() != "indices" && it.key() != "expect") {
      throw FieldError(field + "." + Printable(it.key()), "unknown key");
    }
  }
  if (json.contains("indices")) {
    indices_ = CheckedIndices(json["indices"], field + ".indices");
  } else if (json.contains("box")) {
    box_ = Box::Parse(json["box"], field + ".box");
  } else {
    throw FieldError(field, "needs 'box' or 'indices'");
  }
  if (json.contains("expect")) expect_ = CheckedInteger(json["expect"], field + ".expect", 1, 1000000000);
}

std::vector<int> VertexSelector::Resolve(const Mesh& mesh) const {
  std::vector<int> found;
  if (!indices_.empty()) {
    for (int i : indices_) {
      if (i >= mesh.NumVertices()) throw FieldError(field_, "vertex " + std::to_string(i) + " does not exist at this step");
      found.push_back(i);
    }
  } else {
    for (int v = 0; v < mesh.NumVertices(); ++v) {
      if (box_.Contains(mesh.vertices[v])) found.push_back(v);
    }
  }
  CheckSelectionCount(found.size(), expect_, field_, "vertices");
  return found;
}

Json VertexSelector::ToJson() const {
  Json j;
  if (!indices_.empty()) {
    j["indices"] = indices_;
  } else {
    j["box"] = box_.ToJson();
  }
  if (expect_ >= 0) j["expect"] = expect_;
  return j;
}

std::string VertexSelector::PythonExpr(const std::string& mesh_var) const {
  std::string indices = "None";
  if (!indices_.empty()) {
    indices = "[";
    for (int i : indices_) indices += std::to_string(i) + ", ";
    indices += "]";
  }
  return "select_verts(" + mesh_var + ", " + box_.PythonArgs() + ", " + indices + ", " + std::to_string(expect_) + ")";
}

}  // namespace opgraph
