// Booleans on residual clusters (search/proposals.h).
#include <string>

#include "search/proposals.h"

namespace opgraph {

int CountBooleans(const Layout& layout) {
  int count = 0;
  for (const Json& op : layout.details) count += op["op"] == "Boolean" ? 1 : 0;
  return count;
}

build::BooleanArgs PrimitiveOnClusterBox(const ResidualCluster& cluster, build::Primitive primitive, int axis) {
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  Eigen::Matrix3d frame;
  frame << cluster.axes.col(a), cluster.axes.col(b), cluster.axes.col(axis);
  const Vec3d zyx = frame.eulerAngles(2, 1, 0);  // R = Rz Ry Rx
  build::BooleanArgs args;
  args.difference = cluster.excess;
  args.primitive = primitive;
  args.size = Vec3d(cluster.extents[a], cluster.extents[b], cluster.extents[axis]);
  args.rotation_deg = Vec3d(RadToDeg(zyx[2]), RadToDeg(zyx[1]), RadToDeg(zyx[0]));
  args.location = cluster.centre;
  return args;
}

std::vector<Round> ProposeBooleans(const Layout& best, const std::vector<ResidualCluster>& clusters) {
  std::vector<Round> rounds;
  // A modeller bevels last, and a Boolean cut into a bevelled cage can differ from Blender's.
  if (CountBooleans(best) >= kMaxBooleans || best.HasDetail("Bevel")) return rounds;
  for (size_t c = 0; c < clusters.size() && c < kMaxClusters; ++c) {
    const ResidualCluster& cluster = clusters[c];
    Round round;
    // A box on the cluster, or a cylinder along each of its axes (a boss, a bore, a rod).
    std::vector<std::pair<build::Primitive, int>> shapes = {{build::Primitive::kCube, 2}};
    for (int axis = 0; axis < 3; ++axis) shapes.push_back({build::Primitive::kCylinder, axis});
    for (const auto& [primitive, axis] : shapes) {
      const Json op = build::Boolean(PrimitiveOnClusterBox(cluster, primitive, axis));
      const std::string what = std::string("+Boolean ") + (cluster.excess ? "difference " : "union ") +
                               build::PrimitiveName(primitive) + " on a residual cluster of " +
                               std::to_string(cluster.num_samples) + " samples" +
                               (primitive == build::Primitive::kCube ? "" : " (axis " + std::to_string(axis) + ")");
      round.alternatives.push_back([op, what](Layout* l) -> std::string {
        if (CountBooleans(*l) >= kMaxBooleans) return "";
        l->details.push_back(op);
        return what;
      });
    }
    rounds.push_back(round);
  }
  return rounds;
}

}  // namespace opgraph
