#include "ops/knife_cut.h"

#include <limits>

#include "ops/halfedge_topology.h"

namespace opgraph {

KnifeCutOp::KnifeCutOp(const Json& params) {
  ParamReader reader(params);
  if (reader.Has("plane_co") || reader.Has("plane_no")) {
    plane_co_ = reader.Vector3("plane_co", -1e9, 1e9);
    const Vec3d normal = reader.Vector3("plane_no", -1e9, 1e9);
    if (!(normal.norm() > 1e-12)) throw FieldError("plane_no", "must not be zero");
    plane_no_ = normal.normalized();
  } else {
    selector_.emplace(MemberOrNull(params, "face"), "face");
    reader.Raw("face");
    const Json& points = reader.Raw("edge_points");
    if (!points.is_array() || points.size() != 2) throw FieldError("edge_points", "must be an array of 2 points");
    for (int k = 0; k < 2; ++k) points_[k] = CheckedVector3(points[k], "edge_points[" + std::to_string(k) + "]", -1e9, 1e9);
  }
  reader.Finish();
}

void KnifeCutOp::Prepare(const Mesh& input) {
  split_edges_.clear();
  output_faces_.clear();
  if (selector_) {
    PrepareEdgeMode(input);
  } else {
    PreparePlaneMode(input);
  }
  num_output_vertices_ = input.NumVertices() + static_cast<int>(split_edges_.size());
}

void KnifeCutOp::PrepareEdgeMode(const Mesh& input) {
  const std::vector<int> faces = selector_->Resolve(input);
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
  const auto topology = HalfedgeTopology::Of(input);
  int split_edge[2];
  for (int k = 0; k < 2; ++k) {
    split_edges_.push_back({face[positions[k]], face[(positions[k] + 1) % n]});
    split_edge[k] = topology->CornerEdge(faces[0], positions[k]);
  }
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
    for (int i = 0; i < static_cast<int>(p.size()); ++i) {
      loop.push_back(p[i]);
      for (int k = 0; k < 2; ++k) {
        if (topology->CornerEdge(f, i) == split_edge[k]) loop.push_back(mid[k]);
      }
    }
    output_faces_.push_back(loop);
  }
}

void KnifeCutOp::PreparePlaneMode(const Mesh& input) {
  std::vector<int> side(input.NumVertices());
  for (int v = 0; v < input.NumVertices(); ++v) {
    const double d = (input.vertices[v] - plane_co_).dot(plane_no_);
    side[v] = d > kPlaneEpsilon ? 1 : (d < -kPlaneEpsilon ? -1 : 0);
  }
  // New vertices on crossing edges, numbered in face-loop order of first appearance.
  const auto topology = HalfedgeTopology::Of(input);
  std::vector<int> new_vertex_of_edge(topology->NumEdges(), -1);
  for (int f = 0; f < input.NumFaces(); ++f) {
    const Polygon& face = input.faces[f];
    for (int i = 0; i < static_cast<int>(face.size()); ++i) {
      const int a = face[i], b = face[(i + 1) % face.size()];
      int& vertex = new_vertex_of_edge[topology->CornerEdge(f, i)];
      if (side[a] * side[b] >= 0 || vertex >= 0) continue;
      vertex = input.NumVertices() + static_cast<int>(split_edges_.size());
      split_edges_.push_back({a, b});
    }
  }
  for (int f = 0; f < input.NumFaces(); ++f) {
    const Polygon& face = input.faces[f];
    Polygon loop;
    std::vector<int> on_plane;  // positions in `loop`
    for (int i = 0; i < static_cast<int>(face.size()); ++i) {
      const int a = face[i];
      if (side[a] == 0) on_plane.push_back(static_cast<int>(loop.size()));
      loop.push_back(a);
      const int vertex = new_vertex_of_edge[topology->CornerEdge(f, i)];
      if (vertex >= 0) {
        on_plane.push_back(static_cast<int>(loop.size()));
        loop.push_back(vertex);
      }
    }
    const int n = static_cast<int>(loop.size());
    const bool adjacent = on_plane.size() == 2 &&
                          ((on_plane[1] - on_plane[0]) == 1 || (on_plane[0] == 0 && on_plane[1] == n - 1));
    if (on_plane.size() > 2) {
      throw FieldError("plane_co", "the plane crosses face " + std::to_string(f) + " more than twice");
    }
    if (on_plane.size() < 2 || adjacent) {
      output_faces_.push_back(loop);
      continue;
    }
    Polygon first(loop.begin() + on_plane[0], loop.begin() + on_plane[1] + 1);
    Polygon second(loop.begin() + on_plane[1], loop.end());
    second.insert(second.end(), loop.begin(), loop.begin() + on_plane[0] + 1);
    output_faces_.push_back(first);
    output_faces_.push_back(second);
  }
}

template <typename T>
void KnifeCutOp::Apply(const T*, const T&, const Positions<T>& in, Positions<T>* out) const {
  *out = in;
  for (const auto& [a, b] : split_edges_) {
    if (selector_) {
      out->push_back((in[a] + in[b]) * T(0.5));
      continue;
    }
    const Vec3<T> normal = plane_no_.cast<T>();
    const T da = (in[a] - plane_co_.cast<T>()).dot(normal);
    const T db = (in[b] - plane_co_.cast<T>()).dot(normal);
    const T t = da / (da - db);
    out->push_back(in[a] + (in[b] - in[a]) * t);
  }
}

template void KnifeCutOp::Apply<double>(const double*, const double&, const Positions<double>&,
                                        Positions<double>*) const;
template void KnifeCutOp::Apply<JetT>(const JetT*, const JetT&, const Positions<JetT>&, Positions<JetT>*) const;

Json KnifeCutOp::ParamsToJson() const {
  if (!selector_) return {{"plane_co", ToJson(plane_co_)}, {"plane_no", ToJson(plane_no_)}};
  return {{"face", selector_->ToJson()}, {"edge_points", {ToJson(points_[0]), ToJson(points_[1])}}};
}

std::string KnifeCutOp::BlenderCode() const {
  if (!selector_) {
    return "me, bm = open_bmesh(obj)\n"
           "bmesh.ops.bisect_plane(bm, geom=bm.verts[:] + bm.edges[:] + bm.faces[:], dist=" +
           Py(kPlaneEpsilon) + ", plane_co=" + PyVec(plane_co_) + ", plane_no=" + PyVec(plane_no_) +
           ", use_snap_center=False, clear_outer=False, clear_inner=False)\n"
           "close_bmesh(me, bm)\n";
  }
  return "me, bm = open_bmesh(obj)\nface = " + selector_->PythonExpr("bm") +
         "[0]\n"
         "edges = [min(face.edges, key=lambda e: ((e.verts[0].co + e.verts[1].co) / 2 - Vector(p)).length)\n"
         "         for p in (" + PyVec(points_[0]) + ", " + PyVec(points_[1]) + ")]\n"
         "ret = bmesh.ops.bisect_edges(bm, edges=edges, cuts=1)\n"
         "mids = [g for g in ret['geom_split'] if isinstance(g, bmesh.types.BMVert)]\n"
         "bmesh.ops.connect_vert_pair(bm, verts=mids)\n"
         "close_bmesh(me, bm)\n";
}

}  // namespace opgraph
