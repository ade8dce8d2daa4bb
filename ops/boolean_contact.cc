#include "ops/boolean_contact.h"

#include <Eigen/Geometry>
#include <cmath>

#include "ops/boolean_triangulation.h"

namespace opgraph {
namespace {

// Adds to `contacts` the vertices of `points` within `reach` of a triangle of `solid`'s plane and
// over that triangle (its edges widened by `reach`).
void AddContacts(const Mesh& points, const Mesh& solid, double reach, OperandContacts* contacts) {
  Eigen::AlignedBox3d solid_box;
  for (const Vec3d& v : solid.vertices) solid_box.extend(v);
  solid_box.extend(solid_box.min() - Vec3d::Constant(reach)).extend(solid_box.max() + Vec3d::Constant(reach));
  const std::vector<SourceTriangle> triangles = Triangulate(solid);
  for (const Vec3d& p : points.vertices) {
    if (!solid_box.contains(p)) continue;
    for (const SourceTriangle& t : triangles) {
      const Vec3d& a = solid.vertices[t.corners[0]];
      const Vec3d& b = solid.vertices[t.corners[1]];
      const Vec3d& c = solid.vertices[t.corners[2]];
      const Vec3d area_normal = (b - a).cross(c - a);
      const double twice_area = area_normal.norm();
      if (!(twice_area > 0)) continue;
      const Vec3d normal = area_normal / twice_area;
      const double off_plane = normal.dot(p - a);
      if (std::abs(off_plane) > reach) continue;
      bool over = true;
      for (int k = 0; k < 3 && over; ++k) {
        const Vec3d& u = solid.vertices[t.corners[k]];
        const Vec3d& w = solid.vertices[t.corners[(k + 1) % 3]];
        over = (w - u).cross(p - u).dot(normal) / (w - u).norm() >= -reach;
      }
      if (!over) continue;
      if (off_plane == 0) {
        ++contacts->exact;
      } else {
        ++contacts->near;
      }
      break;
    }
  }
}

}  // namespace

OperandContacts CountOperandContacts(const Mesh& input, const Mesh& primitive) {
  double scale = 0;
  for (const Mesh* mesh : {&input, &primitive}) {
    for (const Vec3d& v : mesh->vertices) scale = std::max(scale, v.cwiseAbs().maxCoeff());
  }
  const double reach = kFloat32Contact * scale;
  OperandContacts contacts;
  AddContacts(primitive, input, reach, &contacts);
  AddContacts(input, primitive, reach, &contacts);
  return contacts;
}

}  // namespace opgraph
