// The provenance steps of BooleanOp::Prepare (ops/boolean.h): where each vertex and triangle of
// CGAL's result comes from, recovered geometrically from the two operands.
#pragma once

#include <initializer_list>

#include <Eigen/Geometry>
#include <vector>

#include "ops/boolean.h"
#include "ops/boolean_cgal.h"
#include "ops/boolean_triangulation.h"

namespace opgraph {

// Both operands as CGAL takes them (input, then primitive), with what the provenance steps
// look up in them.
struct Operands {
  const TriangleSoup* soups[2];
  const std::vector<SourceTriangle>* triangles[2];
  double tolerance;              // of the geometric tests: 1e-9 of both operands' bounding box
  Eigen::AlignedBox3d boxes[2];  // each operand's bounding box, grown by the tolerance

  Operands(const TriangleSoup& a, const std::vector<SourceTriangle>& a_triangles, const TriangleSoup& b,
           const std::vector<SourceTriangle>& b_triangles)
      : soups{&a, &b}, triangles{&a_triangles, &b_triangles} {
    Vec3d lo = a.vertices[0], hi = a.vertices[0];
    for (const Vec3d& v : a.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    for (const Vec3d& v : b.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    tolerance = 1e-9 * std::max((hi - lo).norm(), 1e-12);
    for (int m = 0; m < 2; ++m) {
      for (const Vec3d& v : soups[m]->vertices) boxes[m].extend(v);
      boxes[m].extend(boxes[m].min() - Vec3d::Constant(tolerance)).extend(boxes[m].max() + Vec3d::Constant(tolerance));
    }
  }
  // Whether these corners of operand m come near the other operand (its box): only edges and
  // triangles that do can take part in crossings.
  bool NearOther(int m, std::initializer_list<int> corners) const {
    Eigen::AlignedBox3d box;
    for (int v : corners) box.extend(soups[m]->vertices[v]);
    return box.intersects(boxes[1 - m]);
  }
};


// CGAL can return one point twice, a rounding apart (a primitive's edge through the diagonal of a
// triangulated input face, met from both triangles), where Blender's exact boolean has one
// vertex: triangles are remapped to the first of points within `tolerance` of each other, and
// those that collapse are dropped (the unused duplicates stay, unreferenced).
void WeldCoincidentPoints(double tolerance, TriangleSoup* soup);

// Provenance of CGAL's vertices, recovered geometrically (CGAL's points are its exact ones
// rounded to double): an operand vertex at the same coordinates, else the best conditioned
// crossing of an edge of one operand with a triangle of the other through the point.
std::vector<BooleanOp::Source> VertexSources(const Operands& ops, const TriangleSoup& result);

// The source polygon (input's, then primitive's) and operand triangle (likewise) of each result
// triangle: the operand triangle it is (uncut), else the one its centroid lies on, parallel to
// it; the input mesh wins where both operands overlap.
void TriangleSources(const Operands& ops, int num_input_faces, const TriangleSoup& result,
                     const std::vector<BooleanOp::Source>& sources, std::vector<int>* source_face,
                     std::vector<int>* source_triangle);

}  // namespace opgraph
