#include "io/orient_normals.h"

#include <algorithm>
#include <cstddef>
#include <tuple>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/property_map.h>

namespace opgraph {

void OrientNormalsConsistently(const Positions<double>& points, int k, Positions<double>* normals) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Entry = std::tuple<Kernel::Point_3, Kernel::Vector_3, std::size_t>;
  if (points.size() < 3 || normals->size() != points.size()) return;
  std::vector<Entry> entries;
  entries.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3d& p = points[i];
    const Vec3d& n = (*normals)[i];
    entries.emplace_back(Kernel::Point_3(p.x(), p.y(), p.z()), Kernel::Vector_3(n.x(), n.y(), n.z()), i);
  }
  // Reorders `entries`: the oriented ones first.
  const auto unoriented = CGAL::mst_orient_normals(
      entries, std::min<int>(k, static_cast<int>(points.size()) - 1),
      CGAL::parameters::point_map(CGAL::Nth_of_tuple_property_map<0, Entry>())
          .normal_map(CGAL::Nth_of_tuple_property_map<1, Entry>()));
  for (auto it = entries.begin(); it != unoriented; ++it) {
    const Kernel::Vector_3& n = std::get<1>(*it);
    (*normals)[std::get<2>(*it)] = Vec3d(n.x(), n.y(), n.z()).normalized();
  }
}

}  // namespace opgraph
