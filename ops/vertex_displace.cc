#include "ops/vertex_displace.h"

#include "core/printable.h"

namespace opgraph {

VertexDisplaceOp::VertexDisplaceOp(const Json& params) {
  ParamReader reader(params);
  const Json& groups = reader.Raw("groups");
  if (!groups.is_array() || groups.empty()) throw FieldError("groups", "must be a non-empty array");
  for (size_t g = 0; g < groups.size(); ++g) {
    const std::string field = "groups[" + std::to_string(g) + "]";
    if (!groups[g].is_object() || !groups[g].contains("verts") || !groups[g].contains("offset")) {
      throw FieldError(field, "needs 'verts' and 'offset'");
    }
    for (auto it = groups[g].begin(); it != groups[g].end(); ++it) {
      if (it.key() != "verts" && it.key() != "offset") throw FieldError(field + "." + Printable(it.key()), "unknown key");
    }
    selectors_.emplace_back(groups[g]["verts"], field + ".verts");
    const Vec3d offset = CheckedVector3(groups[g]["offset"], field + ".offset", -1e6, 1e6);
    const char* axes[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) AddParam("offset_" + std::to_string(g) + "_" + axes[k], -1e6, 1e6, 0, offset[k]);
  }
  reader.Finish();
}

void VertexDisplaceOp::Prepare(const Mesh& input) {
  KeepTopology(input);
  resolved_.clear();
  for (const VertexSelector& s : selectors_) resolved_.push_back(s.Resolve(input));
}

template <typename T>
void VertexDisplaceOp::Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const {
  *out = in;
  for (size_t g = 0; g < resolved_.size(); ++g) {
    const Vec3<T> offset(gate * p[3 * g], gate * p[3 * g + 1], gate * p[3 * g + 2]);
    for (int v : resolved_[g]) (*out)[v] += offset;
  }
}

template void VertexDisplaceOp::Apply<double>(const double*, const double&, const Positions<double>&,
                                              Positions<double>*) const;
template void VertexDisplaceOp::Apply<JetT>(const JetT*, const JetT&, const Positions<JetT>&,
                                            Positions<JetT>*) const;

Json VertexDisplaceOp::ParamsToJson() const {
  Json groups = Json::array();
  for (size_t g = 0; g < selectors_.size(); ++g) {
    groups.push_back({{"verts", selectors_[g].ToJson()},
                      {"offset", ToJson(Vec3d(params_[3 * g], params_[3 * g + 1], params_[3 * g + 2]))}});
  }
  return {{"groups", groups}};
}

std::string VertexDisplaceOp::BlenderCode() const {
  // Resolve every group on the input first, as the C++ pass does, then move.
  std::string code = "me = edit_mesh(obj)\ngroups = [\n";
  for (size_t g = 0; g < selectors_.size(); ++g) {
    code += "    (" + selectors_[g].PythonExpr("me") + ", Vector(" +
            PyVec(Vec3d(params_[3 * g], params_[3 * g + 1], params_[3 * g + 2])) + ")),\n";
  }
  code += "]\nfor verts, offset in groups:\n    for i in verts:\n        me.vertices[i].co += offset\nme.update()\n";
  return code;
}

}  // namespace opgraph
