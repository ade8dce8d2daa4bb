// Holes (search/proposals.h).
#include "search/proposals.h"

namespace opgraph {

std::vector<Round> ProposeHoles(const Layout& best) {
  struct Tool {
    build::Primitive primitive;
    double spin_deg;
  };
  // The prism also turned an eighth of a turn about its axis, so its flat sides face the cube's
  // (sides parallel to the sides around them subdivide evenly).
  const Tool tools[] = {{build::Primitive::kPrism8, 0.0}, {build::Primitive::kPrism8, 22.5}, {build::Primitive::kCube, 0.0}};
  std::vector<Round> rounds;
  for (const Tool& tool : tools) {
    for (int axis = 0; axis < 3; ++axis) {
      build::BooleanArgs hole;
      hole.difference = true;
      hole.primitive = tool.primitive;
      Vec3d size = best.half_extent;  // half the extent across the axis, through it entirely
      size[axis] = 6 * best.half_extent[axis];
      // The primitive's axis is +Z: spin it about that axis, then turn it onto `axis`.
      Eigen::Matrix3d onto_axis = Eigen::Matrix3d::Identity();
      if (axis == 0) onto_axis = Eigen::AngleAxisd(kPi / 2, Vec3d::UnitY()).toRotationMatrix();
      if (axis == 1) onto_axis = Eigen::AngleAxisd(kPi / 2, Vec3d::UnitX()).toRotationMatrix();
      const Eigen::Matrix3d world_from_primitive =
          onto_axis * Eigen::AngleAxisd(DegToRad(tool.spin_deg), Vec3d::UnitZ()).toRotationMatrix();
      const Vec3d zyx = world_from_primitive.eulerAngles(2, 1, 0);  // R = Rz Ry Rx
      hole.rotation_deg = Vec3d(RadToDeg(zyx[2]), RadToDeg(zyx[1]), RadToDeg(zyx[0]));
      hole.size = size;
      if (axis == 0) hole.size = Vec3d(size.z(), size.y(), size.x());
      if (axis == 1) hole.size = Vec3d(size.x(), size.z(), size.y());
      // Just off the centre, not in proportion to the box: a cutter centred on the cube, or
      // moved in its proportions, has corners on the diagonals of the cube's triangulated faces,
      // which the Boolean cannot map back to their faces yet.
      hole.location = 0.01 * best.half_extent.cwiseProduct(Vec3d(1.0, -0.7, 0.4));
      hole.location[axis] = 0;
      const Json op = build::Boolean(hole);
      const std::string what = "+Boolean difference " + build::PrimitiveName(tool.primitive) +
                               (tool.spin_deg != 0 ? " (turned)" : "") + " along " +
                               build::AxisName(static_cast<build::Axis>(axis));
      rounds.push_back(Round{{[op, what](Layout* l) -> std::string {
                               if (l->HasDetail("Boolean")) return "";
                               l->details.push_back(op);
                               return what;
                             }},
                             kStructureGainPerOp});
    }
  }
  return rounds;
}

}  // namespace opgraph
