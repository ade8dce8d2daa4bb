// The merging steps of BooleanOp::Prepare (ops/boolean.h): CGAL's triangles made as Blender's
// exact boolean makes them, merged back into polygons, and the crossings it dissolves.
#pragma once

#include <vector>

#include "ops/boolean_provenance.h"

namespace opgraph {

// A cut non-planar input polygon: which diagonal Blender's triangulation takes follows its
// loop start, which the ops before need not reproduce, and the two diagonals are different
// surfaces there (the cut's vertices, and their count, move with it).
void RefuseCutNonPlanarFaces(const Mesh& input, const TriangleSoup& result, const std::vector<int>& source_face,
                             const std::vector<BooleanOp::Source>& sources);

// Whether an input polygon's triangles fold past a right angle against its first (a quad: along
// either diagonal; a larger polygon: as the boolean triangulates it): Blender's merge joins only
// triangles facing the first one's way, so it splits such a polygon, cut or not, along the
// diagonal its loop start gives.
bool HasFoldedFace(const Mesh& input, const std::vector<SourceTriangle>& input_triangles);

// Blender retriangulates each operand triangle with a constrained Delaunay triangulation; CGAL's
// retriangulation need not be Delaunay, and the merge depends on the triangles.
void MakeDelaunay(const Operands& ops, const std::vector<int>& source_triangle, TriangleSoup* result);

// The triangles of each source polygon merged back into polygons (ops/boolean.h); `whole[i]`:
// merged polygon i is a source polygon the other operand left whole.
std::vector<Polygon> MergeTriangles(const Mesh& input, const Mesh& primitive, const TriangleSoup& result,
                                    const std::vector<int>& source_face, const std::vector<BooleanOp::Source>& sources,
                                    std::vector<bool>* whole);

// The input faces of 4 or more corners whose triangles in `result` enclose a hole (their Euler
// characteristic below their count of pieces): Blender splits such a face along triangulation
// edges, and its triangulation follows the face's loop start.
std::vector<int> HoledInputFaces(const Mesh& input, const TriangleSoup& result, const std::vector<int>& source_face);

// The crossings to dissolve: those that only continue a straight chain between the same two
// polygons.
std::vector<bool> StraightCrossings(const std::vector<Polygon>& merged, const TriangleSoup& result,
                                    const std::vector<BooleanOp::Source>& sources);

}  // namespace opgraph
