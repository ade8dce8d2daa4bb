#include "ops/boolean_cgal.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <tuple>

namespace opgraph {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

// Empty on success, else why `soup` is not a closed, manifold, non-self-intersecting volume.
std::string ToSurfaceMesh(const TriangleSoup& soup, const std::string& name, SurfaceMesh* mesh) {
  std::vector<SurfaceMesh::Vertex_index> handles;
  handles.reserve(soup.vertices.size());
  for (const Vec3d& p : soup.vertices) handles.push_back(mesh->add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
  for (const std::array<int, 3>& t : soup.triangles) {
    if (mesh->add_face(handles[t[0]], handles[t[1]], handles[t[2]]) == SurfaceMesh::null_face()) {
      return name + " is not a manifold surface";
    }
  }
  if (!CGAL::is_closed(*mesh)) return name + " is not closed";
  if (PMP::does_self_intersect(*mesh)) return name + " intersects itself";
  if (!PMP::does_bound_a_volume(*mesh)) return name + " does not bound a volume (inconsistent orientation or nesting)";
  return "";
}

// CGAL's output order follows its internal containers, some of them ordered by address (so by
// the heap's layout, which differs between runs and machines): the result is renumbered into an
// order its geometry alone fixes, vertices by coordinates, each triangle from its lowest vertex
// (orientation kept), triangles by their vertices; so a fit's topology, and the search, are the
// same in every process (test FitSequence.SameOutputForAnyHeapLayout).
void CanonicalOrder(TriangleSoup* soup) {
  const int n = static_cast<int>(soup->vertices.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [soup](int a, int b) {
    const Vec3d& p = soup->vertices[a];
    const Vec3d& q = soup->vertices[b];
    return std::tie(p.x(), p.y(), p.z()) < std::tie(q.x(), q.y(), q.z());
  });
  std::vector<int> new_index(n);
  std::vector<Vec3d> vertices(n);
  for (int k = 0; k < n; ++k) new_index[order[k]] = k, vertices[k] = soup->vertices[order[k]];
  soup->vertices = std::move(vertices);
  for (std::array<int, 3>& t : soup->triangles) {
    for (int& v : t) v = new_index[v];
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  }
  std::sort(soup->triangles.begin(), soup->triangles.end());
}

std::string CgalBooleanUnchecked(const TriangleSoup& a, const TriangleSoup& b, BooleanKind kind, TriangleSoup* out) {
  SurfaceMesh mesh_a, mesh_b, result;
  std::string problem = ToSurfaceMesh(a, "the input mesh", &mesh_a);
  if (problem.empty()) problem = ToSurfaceMesh(b, "the primitive", &mesh_b);
  if (!problem.empty()) return problem;
  const bool ok = kind == BooleanKind::kUnion ? PMP::corefine_and_compute_union(mesh_a, mesh_b, result)
                                              : PMP::corefine_and_compute_difference(mesh_a, mesh_b, result);
  if (!ok) return "CGAL cannot compute the boolean (the result would not be manifold)";
  result.collect_garbage();
  out->vertices.clear();
  out->triangles.clear();
  for (SurfaceMesh::Vertex_index v : result.vertices()) {
    const Kernel::Point_3& p = result.point(v);
    out->vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (SurfaceMesh::Face_index f : result.faces()) {
    std::array<int, 3> t;
    int k = 0;
    for (SurfaceMesh::Vertex_index v : CGAL::vertices_around_face(result.halfedge(f), result)) {
      if (k == 3) return "CGAL returned a non-triangle face";
      t[k++] = static_cast<int>(v);
    }
    out->triangles.push_back(t);
  }
  CanonicalOrder(out);
  return "";
}

}  // namespace

std::string CgalSolidProblem(const TriangleSoup& soup, const std::string& name) {
  try {
    SurfaceMesh mesh;
    return ToSurfaceMesh(soup, name, &mesh);
  } catch (const std::exception& e) {  // CGAL's failed preconditions, on degenerate input
    const std::string what = e.what();
    return name + " cannot be checked: " + what.substr(0, std::min(what.find('\n'), size_t{120}));
  }
}

std::string CgalBoolean(const TriangleSoup& a, const TriangleSoup& b, BooleanKind kind, TriangleSoup* out) {
  try {
    return CgalBooleanUnchecked(a, b, kind, out);
  } catch (const std::exception& e) {  // CGAL's failed preconditions, on degenerate input
    const std::string what = e.what();
    return "CGAL cannot compute the boolean: " + what.substr(0, std::min(what.find('\n'), size_t{120}));
  }
}

}  // namespace opgraph
