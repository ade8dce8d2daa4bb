// Holes (search/proposals.h).
#include <algorithm>

#include "search/proposals.h"

namespace opgraph {
namespace {

// A through cutter is this many of the cube's largest half extents long: through it entirely
// from anywhere on it.
constexpr double kThroughLength = 6;
// Holes through at most this many clusters (largest first) per decision.
constexpr size_t kMaxHoleClusters = 2;

// The rotation (Blender's XYZ Euler angles) that spins a primitive about its +Z axis by
// `spin_deg`, then turns that axis onto the cage's `axis`.
Vec3d RotationOntoAxis(int axis, double spin_deg) {
  Eigen::Matrix3d onto_axis = Eigen::Matrix3d::Identity();
  if (axis == 0) onto_axis = Eigen::AngleAxisd(kPi / 2, Vec3d::UnitY()).toRotationMatrix();
  if (axis == 1) onto_axis = Eigen::AngleAxisd(kPi / 2, Vec3d::UnitX()).toRotationMatrix();
  const Eigen::Matrix3d world_from_primitive =
      onto_axis * Eigen::AngleAxisd(DegToRad(spin_deg), Vec3d::UnitZ()).toRotationMatrix();
  const Vec3d zyx = world_from_primitive.eulerAngles(2, 1, 0);  // R = Rz Ry Rx
  return Vec3d(RadToDeg(zyx[2]), RadToDeg(zyx[1]), RadToDeg(zyx[0]));
}

// The primitive's own extents (x, y across its axis, z along it) for `extents` along the cage's
// axes, the primitive's axis turned onto `axis`.
Vec3d AcrossAndAlong(const Vec3d& extents, int axis) {
  if (axis == 0) return Vec3d(extents.z(), extents.y(), extents.x());
  if (axis == 1) return Vec3d(extents.x(), extents.z(), extents.y());
  return extents;
}

// Adds the cutter `op`: the only Boolean (a centred hole), or one more up to the sequence's limit.
Edit AddHole(const Json& op, const std::string& what, bool only_boolean) {
  return [op, what, only_boolean](Layout* l) -> std::string {
    if (only_boolean ? l->HasDetail("Boolean") : CountBooleans(*l) >= kMaxBooleans) return "";
    l->details.push_back(op);
    return what;
  };
}

// Through the centre along each axis; the fit sizes and places it.
void CentredHoles(const Layout& best, std::vector<Round>* rounds) {
  struct Tool {
    build::Primitive primitive;
    double spin_deg;
  };
  // The prism also turned an eighth of a turn about its axis, so its flat sides face the cube's
  // (sides parallel to the sides around them subdivide evenly).
  const Tool tools[] = {{build::Primitive::kPrism8, 0.0}, {build::Primitive::kPrism8, 22.5}, {build::Primitive::kCube, 0.0}};
  for (const Tool& tool : tools) {
    for (int axis = 0; axis < 3; ++axis) {
      build::BooleanArgs hole;
      hole.difference = true;
      hole.primitive = tool.primitive;
      Vec3d size = best.half_extent;  // half the extent across the axis, through it entirely
      size[axis] = kThroughLength * best.half_extent[axis];
      hole.rotation_deg = RotationOntoAxis(axis, tool.spin_deg);
      hole.size = AcrossAndAlong(size, axis);
      // Just off the centre, not in proportion to the box: a cutter centred on the cube, or
      // moved in its proportions, has corners on the diagonals of the cube's triangulated faces,
      // which the Boolean cannot map back to their faces yet.
      hole.location = 0.01 * best.half_extent.cwiseProduct(Vec3d(1.0, -0.7, 0.4));
      hole.location[axis] = 0;
      const std::string what = "+Boolean difference " + build::PrimitiveName(tool.primitive) +
                               (tool.spin_deg != 0 ? " (turned)" : "") + " along " +
                               build::AxisName(static_cast<build::Axis>(axis));
      rounds->push_back(Round{{AddHole(build::Boolean(hole), what, true)}, kStructureGainPerOp});
    }
  }
}

// Through a cluster of the target's surface inside the cage (a hole's walls, a notch's sides,
// anywhere): along its thinnest principal axis (a short ring's axis) and its longest (a long
// bore's), its section the cluster's, as a box in the cluster's principal frame (a slot turned
// about its axis), a cylinder, a prism of 6 or 8 sides, or a box square to the cage along the
// cage axis nearest.
Round HoleThroughCluster(const ResidualCluster& cluster, double length) {
  Round round{{}, kStructureGainPerOp};
  const std::string where = " through a cluster of " + std::to_string(cluster.num_samples) + " samples inside";
  int thinnest = 0, longest = 0;
  cluster.extents.minCoeff(&thinnest);
  cluster.extents.maxCoeff(&longest);
  for (int along : {thinnest, longest}) {
    const std::string how = along == thinnest ? " across it" : " along it";
    for (build::Primitive primitive : {build::Primitive::kCube, build::Primitive::kCylinder, build::Primitive::kPrism6,
                                       build::Primitive::kPrism8}) {
      build::BooleanArgs hole = PrimitiveOnClusterBox(cluster, primitive, along);
      hole.size.z() = length;
      round.alternatives.push_back(
          AddHole(build::Boolean(hole), "+Boolean difference " + build::PrimitiveName(primitive) + where + how, false));
    }
    // The box's extents along the cage's axes, from its corners.
    int axis = 0;
    cluster.axes.col(along).cwiseAbs().maxCoeff(&axis);
    Vec3d extents = Vec3d::Zero();
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3d sign((corner & 1) ? 1 : -1, (corner & 2) ? 1 : -1, (corner & 4) ? 1 : -1);
      extents = extents.cwiseMax((cluster.axes * sign.cwiseProduct(cluster.extents)).cwiseAbs());
    }
    extents[axis] = length;
    build::BooleanArgs square;
    square.difference = true;
    square.size = AcrossAndAlong(extents, axis);
    square.rotation_deg = RotationOntoAxis(axis, 0);
    square.location = cluster.centre;
    const std::string what = "+Boolean difference cube" + where + how + ", square along " +
                             build::AxisName(static_cast<build::Axis>(axis));
    round.alternatives.push_back(AddHole(build::Boolean(square), what, false));
  }
  return round;
}

}  // namespace

std::vector<Round> ProposeHoles(const Layout& best) {
  std::vector<Round> rounds;
  CentredHoles(best, &rounds);
  return rounds;
}

std::vector<Round> ProposeThroughHoles(const Layout& best, const std::vector<ResidualCluster>& interior) {
  std::vector<Round> rounds;
  // A modeller bevels last, and a Boolean cut into a bevelled cage can differ from Blender's.
  if (best.HasDetail("Bevel") || CountBooleans(best) >= kMaxBooleans) return rounds;
  for (size_t c = 0; c < interior.size() && c < kMaxHoleClusters; ++c) {
    rounds.push_back(HoleThroughCluster(interior[c], kThroughLength * best.half_extent.maxCoeff()));
  }
  return rounds;
}

}  // namespace opgraph
