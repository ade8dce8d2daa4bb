#include "ops/boolean_contact.h"

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "ops/boolean_triangulation.h"

namespace opgraph {
namespace {

// A triangle of an operand with what the contact test needs, computed once.
struct ContactTriangle {
  Vec3d corners[3];
  Vec3d normal;               // unit
  Eigen::AlignedBox3d reach;  // its box grown by the reach: a vertex outside cannot touch it
};

// The triangles of `solid` (as Blender's exact boolean triangulates it) with a non-zero area.
std::vector<ContactTriangle> ContactTriangles(const Mesh& solid, double reach) {
  std::vector<ContactTriangle> triangles;
  for (const SourceTriangle& t : Triangulate(solid)) {
    ContactTriangle triangle;
    for (int k = 0; k < 3; ++k) triangle.corners[k] = solid.vertices[t.corners[k]];
    const Vec3d area_normal = (triangle.corners[1] - triangle.corners[0]).cross(triangle.corners[2] - triangle.corners[0]);
    const double twice_area = area_normal.norm();
    if (!(twice_area > 0)) continue;
    triangle.normal = area_normal / twice_area;
    for (const Vec3d& corner : triangle.corners) triangle.reach.extend(corner);
    triangle.reach.extend(triangle.reach.min() - Vec3d::Constant(reach)).extend(triangle.reach.max() + Vec3d::Constant(reach));
    triangles.push_back(triangle);
  }
  return triangles;
}

// Adds to `contacts` the vertices of `points` within `reach` of a triangle of `solid`'s plane and
// over that triangle (its edges widened by `reach`): as near when off some such plane at all,
// else as exact.
void AddContacts(const Mesh& points, const Mesh& solid, double reach, OperandContacts* contacts) {
  const std::vector<ContactTriangle> triangles = ContactTriangles(solid, reach);
  Eigen::AlignedBox3d solid_box;
  for (const ContactTriangle& t : triangles) solid_box.extend(t.reach);
  for (const Vec3d& p : points.vertices) {
    if (!solid_box.contains(p)) continue;
    bool exact = false, near = false;
    for (const ContactTriangle& t : triangles) {
      if (!t.reach.contains(p)) continue;
      const double off_plane = t.normal.dot(p - t.corners[0]);
      if (std::abs(off_plane) > reach) continue;
      bool over = true;
      for (int k = 0; k < 3 && over; ++k) {
        const Vec3d& u = t.corners[k];
        const Vec3d& w = t.corners[(k + 1) % 3];
        over = (w - u).cross(p - u).dot(t.normal) / (w - u).norm() >= -reach;
      }
      if (!over) continue;
      (off_plane == 0 ? exact : near) = true;
      if (near) break;
    }
    if (near) {
      ++contacts->near;
    } else if (exact) {
      ++contacts->exact;
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
