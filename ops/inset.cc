#include "ops/inset.h"

#include <map>

#include "core/geometry.h"

namespace opgraph {

InsetOp::InsetOp(const Json& params) : selector_(MemberOrNull(params, "faces"), "faces") {
  ParamReader reader(params);
  reader.Raw("faces");
  AddParam("thickness", 0, 1e6, 0, reader.Number("thickness", 0, 1e6));
  AddParam("depth", -1e6, 1e6, 0, reader.Number("depth", -1e6, 1e6, 0.0));
  reader.Finish();
}

void InsetOp::Prepare(const Mesh& input) {
  input_faces_ = input.faces;
  region_ = CopyRegions(input, {selector_.Resolve(input)}, &output_faces_, &num_output_vertices_)[0];
  std::map<int, int> in_edge, out_edge;  // vertex -> boundary edge ending / starting there
  for (size_t e = 0; e < region_.boundary.size(); ++e) {
    if (in_edge.count(region_.boundary[e].b) || out_edge.count(region_.boundary[e].a)) {
      throw FieldError("faces", "region boundary is not a set of simple loops (a vertex is on two boundaries)");
    }
    in_edge[region_.boundary[e].b] = static_cast<int>(e);
    out_edge[region_.boundary[e].a] = static_cast<int>(e);
  }
  corners_.clear();
  for (const auto& [target, source] : region_.caps) {
    if (target == source) continue;  // interior vertex: moves by depth only
    corners_.push_back({target, source, in_edge.at(source), out_edge.at(source)});
  }
}

template <typename T>
void InsetOp::Apply(const T* p, const T& gate, const Positions<T>& in, Positions<T>* out) const {
  *out = in;
  out->resize(num_output_vertices_);
  const T thickness = gate * p[0];
  const T depth = gate * p[1];
  Vec3<T> normal(T(0), T(0), T(0));
  for (int f : region_.faces) normal += FaceAreaNormal(in, input_faces_[f]);
  normal = SafeNormalized(normal);
  auto inward = [&](int e) {
    const RegionCopy::BoundaryEdge& edge = region_.boundary[e];
    const Vec3<T> face_normal = SafeNormalized(FaceAreaNormal(in, input_faces_[edge.face]));
    return SafeNormalized<T>(face_normal.cross(in[edge.b] - in[edge.a]));
  };
  for (const auto& [target, source] : region_.caps) (*out)[target] = in[source] + normal * depth;
  for (const Corner& c : corners_) {
    const Vec3<T> t1 = inward(c.in_edge), t2 = inward(c.out_edge);
    (*out)[c.target] += (t1 + t2) * (thickness / (T(1) + t1.dot(t2)));
  }
}

template void InsetOp::Apply<double>(const double*, const double&, const Positions<double>&,
                                     Positions<double>*) const;
template void InsetOp::Apply<JetT>(const JetT*, const JetT&, const Positions<JetT>&, Positions<JetT>*) const;

Json InsetOp::ParamsToJson() const {
  return {{"faces", selector_.ToJson()}, {"thickness", params_[0]}, {"depth", params_[1]}};
}

std::string InsetOp::BlenderCode() const {
  return "me, bm = open_bmesh(obj)\nfaces = " + selector_.PythonExpr("bm") +
         "\nbmesh.ops.inset_region(bm, faces=faces, thickness=" + Py(params_[0]) + ", depth=" + Py(params_[1]) +
         ", use_even_offset=True, use_interpolate=True, use_relative_offset=False, use_edge_rail=False,"
         " use_outset=False, use_boundary=True)\n"
         "close_bmesh(me, bm)\n";
}

}  // namespace opgraph
