// The topology shared by Extrude and Inset: the faces of a set get copies of the set's
// boundary vertices (interior vertices are reused), and a quad [a, b, b', a'] joins each
// boundary edge a->b to its copy.
#pragma once

#include <vector>

#include "core/mesh.h"

namespace opgraph {

struct RegionCopy {
  std::vector<int> faces;                 // input face indices of the set
  std::vector<std::pair<int, int>> caps;  // (output vertex, input source vertex), every set vertex
  // Boundary edges a->b in the winding of the set's faces, with the face holding each.
  struct BoundaryEdge {
    int a, b, face;
  };
  std::vector<BoundaryEdge> boundary;
};

// Rebuilds `input`'s faces with each set in `sets` copied as above. Unselected faces come first
// (in order), then per set its cap faces and side quads. New vertices are numbered from
// input.NumVertices(); *num_vertices gets the output count.
std::vector<RegionCopy> CopyRegions(const Mesh& input, const std::vector<std::vector<int>>& sets,
                                    std::vector<Polygon>* faces, int* num_vertices);

}  // namespace opgraph
