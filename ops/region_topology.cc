#include "ops/region_topology.h"

#include <map>

#include "ops/halfedge_topology.h"

namespace opgraph {

std::vector<RegionCopy> CopyRegions(const Mesh& input, const std::vector<std::vector<int>>& sets,
                                    std::vector<Polygon>* faces, int* num_vertices) {
  const auto topology = HalfedgeTopology::Of(input);
  std::vector<RegionCopy> regions;
  std::vector<bool> copied(input.NumFaces(), false);
  std::vector<Polygon> new_faces;
  int next_vertex = input.NumVertices();
  for (const std::vector<int>& set : sets) {
    RegionCopy region;
    region.faces = set;
    for (int f : set) copied[f] = true;
    for (const HalfedgeTopology::Corner& corner : topology->RegionBoundary(set)) {
      const Polygon& p = input.faces[corner.face];
      region.boundary.push_back({p[corner.corner], p[(corner.corner + 1) % p.size()], corner.face});
    }
    std::map<int, int> cap;
    for (const RegionCopy::BoundaryEdge& e : region.boundary) {
      for (int v : {e.a, e.b}) {
        if (!cap.count(v)) cap[v] = next_vertex++;
      }
    }
    for (int f : set) {
      for (int v : input.faces[f]) {
        if (!cap.count(v)) cap[v] = v;
      }
    }
    for (const auto& [source, target] : cap) region.caps.push_back({target, source});
    for (int f : set) {
      Polygon p = input.faces[f];
      for (int& v : p) v = cap[v];
      new_faces.push_back(p);
    }
    for (const RegionCopy::BoundaryEdge& e : region.boundary) new_faces.push_back({e.a, e.b, cap[e.b], cap[e.a]});
    regions.push_back(region);
  }
  faces->clear();
  for (int f = 0; f < input.NumFaces(); ++f) {
    if (!copied[f]) faces->push_back(input.faces[f]);
  }
  faces->insert(faces->end(), new_faces.begin(), new_faces.end());
  *num_vertices = next_vertex;
  return regions;
}

}  // namespace opgraph
