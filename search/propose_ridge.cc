// Ridges (search/proposals.h).
#include <cmath>

#include "search/proposals.h"

namespace opgraph {

std::vector<Round> ProposeRidges(const Layout& best) {
  if (!best.ridge.empty()) return {};
  Round round{{}, kStructureGainPerOp};
  const Json& scale = best.scale["params"]["scale"];
  for (int cut = 0; cut < 3; ++cut) {
    for (int up = 0; up < 3; ++up) {
      if (up == cut) continue;
      for (int sign : {1, -1}) {
        const double cut_half = std::abs(scale[cut].get<double>()), up_half = std::abs(scale[up].get<double>());
        build::DisplaceGroup raised;
        raised.verts.box.lo[cut] = -0.25 * cut_half, raised.verts.box.hi[cut] = 0.25 * cut_half;
        (sign > 0 ? raised.verts.box.lo : raised.verts.box.hi)[up] = sign * 0.5 * up_half;
        raised.offset = Vec3d::Zero();
        raised.offset[up] = sign * 0.5 * up_half;
        const build::Axis cut_axis = static_cast<build::Axis>(cut), up_axis = static_cast<build::Axis>(up);
        const std::vector<Json> ridge = {build::LoopCut(cut_axis, 1, Vec3d::Zero()), build::VertexDisplace({raised})};
        const std::string what = "LoopCut " + build::AxisName(cut_axis) + " x1, its vertices raised along " +
                                 (sign > 0 ? "+" : "-") + build::AxisName(up_axis);
        round.alternatives.push_back([ridge, what](Layout* l) -> std::string {
          if (!l->ridge.empty()) return "";
          l->ridge = ridge;
          return what;
        });
      }
    }
  }
  return {round};
}

}  // namespace opgraph
