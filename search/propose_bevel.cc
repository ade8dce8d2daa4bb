// Bevels (search/proposals.h).
#include "search/proposals.h"

namespace opgraph {

std::vector<Round> ProposeBevels(const Layout& best) {
  if (best.HasDetail("Bevel")) return {};
  constexpr double kAngleLimitDeg = 30.0;
  const double width = 0.05 * best.half_extent.minCoeff();
  std::vector<Round> rounds;
  rounds.push_back(Round{{[width](Layout* l) -> std::string {
    l->details.push_back(build::Bevel(width, 5, kAngleLimitDeg));
    return "+Bevel (5 segments)";
  }}});
  // Extrusions can imitate rounded edges (a slab's rim grown outward): a bevel alone may
  // explain them with fewer ops.
  rounds.push_back(Round{{[width](Layout* l) -> std::string {
    if (l->details.empty() || l->details.back()["op"] == "Bevel") return "";
    l->details = {build::Bevel(4 * width, 5, kAngleLimitDeg)};
    l->grid.clear();  // the grid was there for the extrusions
    return "Bevel (5 segments) instead of the extrusions";
  }}});
  // The segment count (same op count, so the lowest loss wins).
  for (int segments : {1, 2, 3, 4, 6, 9}) {
    rounds.push_back(Round{{[segments](Layout* l) -> std::string {
      if (l->details.empty() || l->details.back()["op"] != "Bevel") return "";
      l->details.back()["params"]["segments"] = segments;
      return "segments " + std::to_string(segments);
    }}});
  }
  return rounds;
}

}  // namespace opgraph
