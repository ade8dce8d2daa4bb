// Box bodies (search/proposals.h).
#include "search/box_body.h"
#include "search/pose.h"
#include "search/proposals.h"

namespace opgraph {

std::vector<Expansion> ProposeBoxBodies(const Target& target, const Layout& pose) {
  Vec3d lo, hi;
  LocalBox(target, pose.world_from_local, &lo, &hi);
  std::vector<Expansion> expansions;
  for (const auto& [axis, body] : FindBoxBodies(LocalSamples(target, pose.world_from_local), lo, hi)) {
    expansions.push_back({PoseLayoutOnBox(pose.world_from_local, body.lo, body.hi),
                          "box body along " + build::AxisName(static_cast<build::Axis>(axis))});
  }
  return expansions;
}

}  // namespace opgraph
