#include "ops/knife_cut.h"

#include <limits>

namespace opgraph {

KnifeCutOp::KnifeCutOp(const Json& params) : selector_(MemberOrNull(params, "face"), "face") {
  ParamReader reader(params);
  reader.Raw("face");
  const Json& points = reader.Raw("edge_points");
  if (!points.is_array() || points.size() != 2) throw FieldError("edge_points", "must be an array of 2 points");
  for (int k = 0; k < 2; ++k) points_[k] = CheckedVector3(points[k], "edge_points[" + std::to_string(k) + "]", -1e9, 1e9);
  reader.Finish();
}

void KnifeCutOp::Prepare(const Mesh& input) {
  const std::vector<int> faces = selector_.Resolve(input);
  if (faces.size() != 1) throw FieldError("face", "selects " + std::to_string(faces.size()) + " faces, expected 1");
  const Polygon& face = input.faces[faces[0]];
  const int n = static_cast<int>(face.size());
  int positions[2];
  for (int k = 0; k < 2; ++k) {
    double best = std::numeric_limits<double>::max();
    for (int i = 0; i < n; ++i) {
      const double d = (0.5 * (input.vertices[face[i]] + input.vertices[face[(i + 1) % n]]) - points_[k]).norm();
      if (d < best) best = d, positions[k] = i;
    }
  }
  if (positions[0] == positions[1]) throw FieldError("edge_points", "both points name the same edge");
  const int mid[2] = {input.NumVertices(), input.NumVertices() + 1};
  for (int k = 0; k < 2; ++k) cut_edges_[k] = {face[positions[k]], face[(positions[k] + 1) % n]};
  output_faces_.clear();
  for (int f = 0; f < input.NumFaces(); ++f) {
    if (f == faces[0]) {
      // Walk from each midpoint to the other along the loop: two faces.
      for (int k = 0; k < 2; ++k) {
        Polygon part = {mid[k]};
        for (int i = (positions[k] + 1) % n;; i = (i + 1) % n) {
          part.push_back(face[i]);
          if (i == positions[1 - k]) break;
        }
        part.push_back(mid[1 - k]);
        output_faces_.push_back(part);
      }
      continue;
    }
    Polygon loop;
    const Polygon& p = input.faces[f];
    for (size_t i = 0; i < p.size(); ++i) {
      loop.push_back(p[i]);
      const int a = p[i], b = p[(i + 1) % p.size()];
      for (int k = 0; k < 2; ++k) {
        if (EdgeKey(a, b) == EdgeKey(cut_edges_[k].first, cut_edges_[k].second)) loop.push_back(mid[k]);
      }
    }
    output_faces_.push_back(loop);
  }
  num_output_vertices_ = input.NumVertices() + 2;
}

template <typename T>
void KnifeCutOp::Apply(const T*, const T&, const Positions<T>& in, Positions<T>* out) const {
  *out = in;
  for (int k = 0; k < 2; ++k) out->push_back((in[cut_edges_[k].first] + in[cut_edges_[k].second]) * T(0.5));
}

template void KnifeCutOp::Apply<double>(const double*, const double&, const Positions<double>&,
                                        Positions<double>*) const;
template void KnifeCutOp::Apply<JetT>(const JetT*, const JetT&, const Positions<JetT>&, Positions<JetT>*) const;

Json KnifeCutOp::ParamsToJson() const {
  return {{"face", selector_.ToJson()}, {"edge_points", {ToJson(points_[0]), ToJson(points_[1])}}};
}

std::string KnifeCutOp::BlenderCode() const {
  return "me, bm = open_bmesh(obj)\nface = " + selector_.PythonExpr("bm") +
         "[0]\n"
         "edges = [min(face.edges, key=lambda e: ((e.verts[0].co + e.verts[1].co) / 2 - Vector(p)).length)\n"
         "         for p in (" + PyVec(points_[0]) + ", " + PyVec(points_[1]) + ")]\n"
         "ret = bmesh.ops.bisect_edges(bm, edges=edges, cuts=1)\n"
         "mids = [g for g in ret['geom_split'] if isinstance(g, bmesh.types.BMVert)]\n"
         "bmesh.ops.connect_vert_pair(bm, verts=mids)\n"
         "close_bmesh(me, bm)\n";
}

}  // namespace opgraph
