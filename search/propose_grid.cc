// Loop-cut grids (search/proposals.h).
#include "search/loop_ops.h"
#include "search/proposals.h"

namespace opgraph {

std::vector<Expansion> ProposeGrids(const Layout& best) {
  if (!best.grid.empty()) return {};
  std::vector<Expansion> expansions;
  for (int a = 0; a < 3; ++a) {
    for (int b = a + 1; b < 3; ++b) {
      Expansion expansion{best, "LoopCut grid " + build::AxisName(static_cast<build::Axis>(a)) +
                                    build::AxisName(static_cast<build::Axis>(b))};
      expansion.layout.grid = LoopCutGrid(a, b, best.profile.empty() ? 4 : -1);
      expansions.push_back(expansion);
    }
  }
  return expansions;
}

}  // namespace opgraph
