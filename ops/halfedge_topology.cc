#include "ops/halfedge_topology.h"

#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <deque>
#include <mutex>

namespace opgraph {

namespace {

// OpenMesh reports each refused face on stderr; a refused face is expected here (it is added
// on vertex copies), so its reports are switched off once.
void SilenceOpenMesh() {
  static std::once_flag once;
  std::call_once(once, [] { omerr().disable(); });
}

bool RepeatsAVertex(const Polygon& face) {
  for (size_t i = 0; i < face.size(); ++i) {
    for (size_t j = i + 1; j < face.size(); ++j) {
      if (face[i] == face[j]) return true;
    }
  }
  return false;
}

}  // namespace

std::shared_ptr<const HalfedgeTopology> HalfedgeTopology::Of(const Mesh& mesh) {
  struct Entry {
    int num_vertices;
    std::vector<Polygon> faces;
    std::shared_ptr<const HalfedgeTopology> topology;
  };
  static std::mutex mutex;
  static std::deque<Entry> cache;  // most recent first
  {
    // A plain comparison, no hash: a hit reads the face list once (a hash would read it again),
    // and a miss mostly stops at the first differing face, then costs a build anyway.
    std::lock_guard<std::mutex> lock(mutex);
    for (const Entry& entry : cache) {
      if (entry.num_vertices == mesh.NumVertices() && entry.faces == mesh.faces) return entry.topology;
    }
  }
  auto topology = std::make_shared<const HalfedgeTopology>(mesh.faces, mesh.NumVertices());
  std::lock_guard<std::mutex> lock(mutex);
  cache.push_front({mesh.NumVertices(), mesh.faces, topology});
  if (cache.size() > kCached) cache.pop_back();
  return topology;
}

HalfedgeTopology::HalfedgeTopology(const std::vector<Polygon>& faces, int num_vertices)
    : num_vertices_(num_vertices) {
  SilenceOpenMesh();
  size_t num_corners = 0;
  for (const Polygon& face : faces) num_corners += face.size();
  mesh_.reserve(num_vertices, num_corners / 2 + 1, faces.size());
  for (int v = 0; v < num_vertices; ++v) mesh_.add_vertex();
  std::vector<VertexHandle> handles;
  for (const Polygon& face : faces) AddFace(face, &handles);
  NumberCornersAndEdges(faces);
}

// Adds `face` as face mesh_.n_faces(): on its own vertices if OpenMesh takes it, else on copies.
void HalfedgeTopology::AddFace(const Polygon& face, std::vector<VertexHandle>* handles) {
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
void HalfedgeTopology::NumberCornersAndEdges(const std::vector<Polygon>& faces) {
  face_offset_.assign(1, 0);
  for (const Polygon& face : faces) face_offset_.push_back(face_offset_.back() + static_cast<int>(face.size()));
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

int HalfedgeTopology::CornerVertex(const Corner& corner) const {
  const HalfedgeHandle h(corner_halfedge_[face_offset_[corner.face] + corner.corner]);
  return Original(mesh_.from_vertex_handle(h));
}

HalfedgeTopology::Corners HalfedgeTopology::EdgeCorners(int e) const {
  Corners corners;
  auto add = [&](HalfedgeHandle h) {
    if (halfedge_corner_[h.idx()].face >= 0) corners.push_back(halfedge_corner_[h.idx()]);
  };
  const auto [a, b] = edge_vertices_[e];
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

void OrientAgainstNeighbours(int num_oriented, std::vector<Polygon>* faces) {
  // The edges of the faces to orient, listed at their lower vertex (a counting sort, so by face
  // there): a shared edge's faces are found among a vertex's handful of entries.
  struct EdgeUse {
    int high, face;
  };
  const int num_faces = static_cast<int>(faces->size());
  auto for_each_edge = [&](int f, auto visit) {
    const Polygon& face = (*faces)[f];
    for (size_t c = 0; c < face.size(); ++c) visit(face[c], face[(c + 1) % face.size()]);
  };
  int num_vertices = 0;
  for (int f = num_oriented; f < num_faces; ++f) {
    for (int v : (*faces)[f]) num_vertices = std::max(num_vertices, v + 1);
  }
  std::vector<int> first_use(num_vertices + 1, 0);  // vertex v's uses: first_use[v] ...
  for (int f = num_oriented; f < num_faces; ++f) {
    for_each_edge(f, [&](int a, int b) { ++first_use[std::min(a, b) + 1]; });
  }
  for (int v = 0; v < num_vertices; ++v) first_use[v + 1] += first_use[v];
  std::vector<EdgeUse> uses(first_use.back());
  std::vector<int> next_use(first_use.begin(), first_use.end() - 1);
  for (int f = num_oriented; f < num_faces; ++f) {
    for_each_edge(f, [&](int a, int b) { uses[next_use[std::min(a, b)]++] = {std::max(a, b), f}; });
  }
  std::vector<bool> oriented(num_faces, false);
  std::vector<int> queue;  // breadth first: faces in the order they were oriented
  for (int f = 0; f < num_oriented; ++f) {
    oriented[f] = true;
    queue.push_back(f);
  }
  for (size_t next = 0; next < queue.size(); ++next) {
    // Face queue[next] is never reversed again, so for_each_edge reads it while others change.
    for_each_edge(queue[next], [&](int a, int b) {
      const int low = std::min(a, b), high = std::max(a, b);
      if (low >= num_vertices) return;  // on no face to orient
      for (int k = first_use[low]; k < first_use[low + 1]; ++k) {
        const EdgeUse& use = uses[k];
        if (use.high != high || oriented[use.face]) continue;
        Polygon& other = (*faces)[use.face];
        for (size_t d = 0; d < other.size(); ++d) {
          if (other[d] == a && other[(d + 1) % other.size()] == b) {
            std::reverse(other.begin(), other.end());
            break;
          }
        }
        oriented[use.face] = true;
        queue.push_back(use.face);
      }
    });
  }
}

}  // namespace opgraph
