// Ridges (search/proposals.h).
#include <cmath>

#include "search/loop_ops.h"
#include "search/proposals.h"

namespace opgraph {

std::vector<Round> ProposeRidges(const Layout& best) {
  if (!best.ridge.empty()) return {};
  Round round{{}, kStructureGainPerOp};
  const Json& scale = best.scale["params"]["scale"];
  const Vec3d half = Vec3d(scale[0].get<double>(), scale[1].get<double>(), scale[2].get<double>()).cwiseAbs();
  for (int cut = 0; cut < 3; ++cut) {
    for (int up = 0; up < 3; ++up) {
      if (up == cut) continue;
      for (int sign : {1, -1}) {
        const std::vector<Json> ridge = RaisedRidge(cut, up, sign, half, 0.5 * half[up]);
        const build::Axis cut_axis = static_cast<build::Axis>(cut), up_axis = static_cast<build::Axis>(up);
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
