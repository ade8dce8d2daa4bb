#include "ops/halfedge_topology.h"

#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <mutex>

#include "ops/face_list_cache.h"

namespace opgraph {

namespace {

// OpenMesh reports each refused face on stderr; a refused face is expected here (it is added
// on vertex copies), so its reports are switched off once.
void SilenceOpenMesh() {
  static std::once_flag once;
  std::call_once(once, [] { omerr().disable(); });
}

template <typename Face>
bool RepeatsAVertex(const Face& face) {
  for (size_t i = 0; i < face.size(); ++i) {
    for (size_t j = i + 1; j < face.size(); ++j) {
      if (face[i] == face[j]) return true;
    }
  }
  return false;
}

}  // namespace

std::shared_ptr<const HalfedgeTopology> HalfedgeTopology::Of(const Mesh& mesh) {
  static FaceListCache<HalfedgeTopology> cache(kCached);
  return cache.Get(mesh, /*key=*/0, [&] { return std::make_shared<const HalfedgeTopology>(mesh.faces, mesh.NumVertices()); });
}

HalfedgeTopology::HalfedgeTopology(const std::vector<Polygon>& faces, int num_vertices)
    : num_vertices_(num_vertices) {
  Build(faces);
}

HalfedgeTopology::HalfedgeTopology(const std::vector<std::array<int, 3>>& triangles, int num_vertices)
    : num_vertices_(num_vertices) {
  Build(triangles);
}

template <typename Faces>
void HalfedgeTopology::Build(const Faces& faces) {
  SilenceOpenMesh();
  size_t num_corners = 0;
  for (const auto& face : faces) num_corners += face.size();
  mesh_.reserve(num_vertices_, num_corners / 2 + 1, faces.size());
  for (int v = 0; v < num_vertices_; ++v) mesh_.add_vertex();
  std::vector<VertexHandle> handles;
  for (const auto& face : faces) AddFace(face, &handles);
  NumberCornersAndEdges(faces);
}

// Adds `face` as face mesh_.n_faces(): on its own vertices if OpenMesh takes it, else on copies.
template <typename Face>
void HalfedgeTopology::AddFace(const Face& face, std::vector<VertexHandle>* handles) {
  handles->clear();
  for (int v : face) handles->push_back(VertexHandle(v));
  if (!RepeatsAVertex(face) && mesh_.add_face(*handles).is_valid()) return;
  if (copies_.empty()) copies_.resize(num_vertices_);
  for (size_t i = 0; i < face.size(); ++i) {
    (*handles)[i] = mesh_.add_vertex();
    copies_[face[i]].push_back((*handles)[i].idx());
    copy_of_.push_back(face[i]);
  }
  mesh_.add_face(*handles);
}

// Corners from each face's halfedges (OpenMesh's face halfedge runs from the last vertex to the
// first), and edge numbers: OpenMesh's edge order, copies of one edge sharing its number.
template <typename Faces>
void HalfedgeTopology::NumberCornersAndEdges(const Faces& faces) {
  face_offset_.assign(1, 0);
  for (const auto& face : faces) face_offset_.push_back(face_offset_.back() + static_cast<int>(face.size()));
  corner_halfedge_.resize(face_offset_.back());
  halfedge_corner_.assign(mesh_.n_halfedges(), {-1, -1});
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
    const int n = static_cast<int>(faces[f].size());
    HalfedgeHandle h = mesh_.next_halfedge_handle(mesh_.halfedge_handle(OpenMesh::FaceHandle(f)));
    for (int j = 0; j < n; ++j, h = mesh_.next_halfedge_handle(h)) {
      corner_halfedge_[face_offset_[f] + j] = h.idx();
      halfedge_corner_[h.idx()] = {f, j};
    }
  }
  const int num_openmesh_edges = static_cast<int>(mesh_.n_edges());
  edge_of_openmesh_edge_.resize(num_openmesh_edges);
  edge_vertices_.clear();
  edge_vertices_.reserve(num_openmesh_edges);
  for (int e = 0; e < num_openmesh_edges; ++e) {
    const HalfedgeHandle h = mesh_.halfedge_handle(OpenMesh::EdgeHandle(e), 0);
    const int a = Original(mesh_.from_vertex_handle(h)), b = Original(mesh_.to_vertex_handle(h));
    int earliest = e;  // the first OpenMesh edge joining a and b
    if (!Manifold()) {
      ForEachOutgoing(a, [&](HalfedgeHandle g) {
        if (Original(mesh_.to_vertex_handle(g)) == b) earliest = std::min(earliest, mesh_.edge_handle(g).idx());
      });
    }
    if (earliest < e) {
      edge_of_openmesh_edge_[e] = edge_of_openmesh_edge_[earliest];
    } else {
      edge_of_openmesh_edge_[e] = static_cast<int>(edge_vertices_.size());
      edge_vertices_.push_back({a, b});
    }
  }
  num_edges_ = static_cast<int>(edge_vertices_.size());
  corner_edge_.resize(corner_halfedge_.size());
  for (size_t k = 0; k < corner_halfedge_.size(); ++k) {
    corner_edge_[k] = edge_of_openmesh_edge_[mesh_.edge_handle(HalfedgeHandle(corner_halfedge_[k])).idx()];
  }
}

int HalfedgeTopology::Original(VertexHandle vertex) const {
  return vertex.idx() < num_vertices_ ? vertex.idx() : copy_of_[vertex.idx() - num_vertices_];
}

template <typename Visit>
void HalfedgeTopology::ForEachOutgoing(int v, Visit visit) const {
  for (auto it = mesh_.cvoh_iter(VertexHandle(v)); it.is_valid(); ++it) visit(*it);
  if (Manifold()) return;
  for (int copy : copies_[v]) {
    for (auto it = mesh_.cvoh_iter(VertexHandle(copy)); it.is_valid(); ++it) visit(*it);
  }
}

int HalfedgeTopology::Edge(int a, int b) const {
  if (Manifold()) {
    const HalfedgeHandle h = mesh_.find_halfedge(VertexHandle(a), VertexHandle(b));
    return h.is_valid() ? edge_of_openmesh_edge_[mesh_.edge_handle(h).idx()] : -1;
  }
  int edge = -1;
  ForEachOutgoing(a, [&](HalfedgeHandle h) {
    if (Original(mesh_.to_vertex_handle(h)) == b) edge = edge_of_openmesh_edge_[mesh_.edge_handle(h).idx()];
  });
  return edge;
}

int HalfedgeTopology::EdgeFace(int from, int to) const {
  if (Manifold()) {
    const HalfedgeHandle h = mesh_.find_halfedge(VertexHandle(from), VertexHandle(to));
    return h.is_valid() ? halfedge_corner_[h.idx()].face : -1;
  }
  const int e = Edge(from, to);
  if (e < 0) return -1;
  int face = -1;
  for (const Corner& corner : EdgeCorners(e)) {  // by face: the last one wins
    if (CornerVertex(corner) == from) face = corner.face;
  }
  return face;
}

bool HalfedgeTopology::Closed() const {
  if (Manifold()) {
    // Every edge then has at most two corners, running opposite ways: closed when no halfedge
    // lies on a boundary.
    for (const Corner& corner : halfedge_corner_) {
      if (corner.face < 0) return false;
    }
    return true;
  }
  for (int e = 0; e < num_edges_; ++e) {
    const Corners corners = EdgeCorners(e);
    if (corners.size() != 2 || CornerVertex(corners[0]) == CornerVertex(corners[1])) return false;
  }
  return true;
}

int HalfedgeTopology::CornerVertex(const Corner& corner) const {
  const HalfedgeHandle h(corner_halfedge_[face_offset_[corner.face] + corner.corner]);
  return Original(mesh_.from_vertex_handle(h));
}

HalfedgeTopology::Corners HalfedgeTopology::EdgeCorners(int e) const {
  Corners corners;
  auto add = [&](HalfedgeHandle h) {
    if (halfedge_corner_[h.idx()].face >= 0) corners.push_back(halfedge_corner_[h.idx()]);
  };
  // Named copies, not a structured binding: the lambda below captures them (C++17).
  const int a = edge_vertices_[e].first, b = edge_vertices_[e].second;
  // Each OpenMesh edge joining (copies of) a and b is met once as a halfedge a -> b.
  ForEachOutgoing(a, [&](HalfedgeHandle h) {
    if (Original(mesh_.to_vertex_handle(h)) != b) return;
    add(h);
    if (a != b) add(mesh_.opposite_halfedge_handle(h));
  });
  std::sort(corners.begin(), corners.end());
  return corners;
}

HalfedgeTopology::Corners HalfedgeTopology::VertexCorners(int v) const {
  Corners corners;
  ForEachOutgoing(v, [&](HalfedgeHandle h) {
    if (halfedge_corner_[h.idx()].face >= 0) corners.push_back(halfedge_corner_[h.idx()]);
  });
  std::sort(corners.begin(), corners.end());
  return corners;
}

std::vector<HalfedgeTopology::Corner> HalfedgeTopology::RegionBoundary(const std::vector<int>& region) const {
  // Not a mask over all faces: Extrude "individual" asks once per face. A small region is
  // searched as it is, a larger one sorted.
  constexpr size_t kSmallRegion = 8;
  std::vector<int> sorted;
  if (region.size() > kSmallRegion) {
    sorted = region;
    std::sort(sorted.begin(), sorted.end());
  }
  auto in_region = [&](int f) {
    return sorted.empty() ? std::find(region.begin(), region.end(), f) != region.end()
                          : std::binary_search(sorted.begin(), sorted.end(), f);
  };
  std::vector<Corner> boundary;
  for (int f : region) {
    for (int c = 0; c < face_offset_[f + 1] - face_offset_[f]; ++c) {
      bool reversed = false;  // run b -> a by a face of the region
      if (Manifold()) {
        // The edge's only other corner is across its halfedge, and runs the other way.
        const HalfedgeHandle h(corner_halfedge_[face_offset_[f] + c]);
        const int other = halfedge_corner_[mesh_.opposite_halfedge_handle(h).idx()].face;
        reversed = other >= 0 && in_region(other);
      } else {
        const int from = CornerVertex({f, c});
        for (const Corner& other : EdgeCorners(CornerEdge(f, c))) {
          reversed = reversed || (in_region(other.face) && CornerVertex(other) != from);
        }
      }
      if (!reversed) boundary.push_back({f, c});
    }
  }
  return boundary;
}

}  // namespace opgraph
