// The connectivity the ops' topology passes navigate, in one place: an OpenMesh half-edge mesh
// (OpenMesh::PolyConnectivity, connectivity only: positions stay in core/mesh.h's Mesh) built
// from a polygon list, answering in the list's own vertex, face and corner indices.
//
// Corner (f, c) is face f's halfedge from faces[f][c] to faces[f][(c + 1) % n]. Edges are
// numbered in order of first appearance over the faces' corners (the order OpenMesh creates
// them in, which the ops' output order relies on), each directed as its first corner.
//
// Non-manifold input (a Boolean's or a Mirror's result may have it): OpenMesh refuses a face on
// an edge that already has two faces or one running the same way, a face through a vertex whose
// fan is closed, and a face that repeats a vertex. Such a face is added on fresh copies of its
// vertices, and every query maps the copies back: the answers are those of the polygon list
// (an edge has all its corners, in every fan), exactly as for manifold input, only slower.
#pragma once

#include <OpenMesh/Core/Mesh/PolyConnectivity.hh>
#include <boost/container/small_vector.hpp>

#include <array>
#include <memory>
#include <utility>
#include <vector>

#include "core/mesh.h"

namespace opgraph {

class HalfedgeTopology {
 public:
  // Face f's corner c.
  struct Corner {
    int face, corner;
    bool operator<(const Corner& o) const { return face != o.face ? face < o.face : corner < o.corner; }
  };
  // The corners of an edge or at a vertex: two, or a handful, without a heap allocation.
  using Corners = boost::container::small_vector<Corner, 6>;

  // `faces` index vertices 0 .. num_vertices - 1 (#F loops of at least 3).
  HalfedgeTopology(const std::vector<Polygon>& faces, int num_vertices);
  // The same over a triangle list (Boolean's triangulations), without copying it into polygons.
  HalfedgeTopology(const std::vector<std::array<int, 3>>& triangles, int num_vertices);
  // The half-edge mesh of `mesh`'s faces, built once per distinct face list: a search prepares
  // many ops (every choice it tries) on one mesh, and building costs more than most topology
  // passes. The last kCached face lists are kept (thread-safe).
  static std::shared_ptr<const HalfedgeTopology> Of(const Mesh& mesh);
  static constexpr int kCached = 4;

  int NumFaces() const { return static_cast<int>(face_offset_.size()) - 1; }
  int NumEdges() const { return num_edges_; }
  // Whether OpenMesh took every face as given (no vertex copies).
  bool Manifold() const { return copy_of_.empty(); }

  // The edge joining a and b (either way), or -1.
  int Edge(int a, int b) const;
  // The face whose corner runs from -> to, or -1 (the last such face where several run it).
  int EdgeFace(int from, int to) const;
  // Whether every edge has exactly two corners, running opposite ways: a closed, consistently
  // oriented surface (vertices may be pinched; an edge from a vertex to itself is never closed).
  bool Closed() const;
  // The edge's vertices, directed as its first corner.
  std::pair<int, int> EdgeVertices(int e) const { return edge_vertices_[e]; }
  // The edge of corner c of face f.
  int CornerEdge(int f, int c) const { return corner_edge_[face_offset_[f] + c]; }
  // The vertex corner (f, c) starts at (faces[f][c]).
  int CornerVertex(const Corner& corner) const;

  // The faces around edge e: its corners, in every face that has it, by face then corner.
  Corners EdgeCorners(int e) const;
  // The one-ring of v: the corners at v (faces[f][c] == v), by face then corner.
  Corners VertexCorners(int v) const;
  // The next edge of a ring through a quad: corner c's opposite corner in quad f.
  static Corner AcrossQuad(const Corner& corner) { return {corner.face, (corner.corner + 2) % 4}; }
  // The boundary of the face set `region`: the corners of its faces whose edge is not run the
  // other way by a face of the set, in the order of `region` and of each face's corners.
  std::vector<Corner> RegionBoundary(const std::vector<int>& region) const;

 private:
  using VertexHandle = OpenMesh::VertexHandle;
  using HalfedgeHandle = OpenMesh::HalfedgeHandle;

  // The input vertex an OpenMesh vertex stands for.
  int Original(VertexHandle vertex) const;
  // Calls visit(halfedge) for each OpenMesh halfedge leaving v or one of its copies.
  template <typename Visit>
  void ForEachOutgoing(int v, Visit visit) const;
  // Faces: std::vector<Polygon> or std::vector<std::array<int, 3>>.
  template <typename Faces>
  void Build(const Faces& faces);
  template <typename Face>
  void AddFace(const Face& face, std::vector<VertexHandle>* handles);
  template <typename Faces>
  void NumberCornersAndEdges(const Faces& faces);

  OpenMesh::PolyConnectivity mesh_;
  int num_vertices_ = 0;
  std::vector<int> copy_of_;                 // OpenMesh vertex num_vertices_ + k copies copy_of_[k]
  std::vector<std::vector<int>> copies_;     // input vertex -> its copies (empty when Manifold())
  std::vector<int> face_offset_;             // #F + 1: face f's corners are face_offset_[f] ...
  std::vector<int> corner_halfedge_;         // flat corner -> OpenMesh halfedge
  std::vector<Corner> halfedge_corner_;      // OpenMesh halfedge -> corner ({-1, -1}: boundary)
  std::vector<int> corner_edge_;             // flat corner -> edge
  std::vector<int> edge_of_openmesh_edge_;   // OpenMesh edge -> edge (several when copied)
  std::vector<std::pair<int, int>> edge_vertices_;
  int num_edges_ = 0;
};

}  // namespace opgraph
