// Smoothing and profiles (search/proposals.h).
#include "search/loop_ops.h"
#include "search/pose.h"
#include "search/proposals.h"

namespace opgraph {

std::vector<Round> ProposeSmoothing(const Layout& best) {
  if (best.subdivide) return {};
  return {Round{{[](Layout* l) -> std::string {
    l->subdivide = true;
    return "+Subdivision(2)";
  }}}};
}

std::vector<int> ProfileAxes(const Layout& best, const Vec3d& section_changes) {
  // A change this large, and this many times the long axis's, marks a profile across it.
  constexpr double kMinChange = 0.1, kClearly = 1.5;
  const int long_axis = LongAxis(best);
  int changing = 0;
  for (int a = 1; a < 3; ++a) {
    if (section_changes[a] > section_changes[changing]) changing = a;
  }
  if (changing != long_axis && section_changes[changing] >= kMinChange &&
      section_changes[changing] >= kClearly * section_changes[long_axis]) {
    return {long_axis, changing};
  }
  return {long_axis};
}

std::vector<Round> ProposeProfiles(const Layout& best, const Vec3d& section_changes) {
  const std::vector<int> axes = ProfileAxes(best, section_changes);
  struct Profile {
    int cuts;
    std::vector<std::vector<int>> groups;  // empty: one scale per loop
    std::string name;
  };
  const std::vector<Profile> profiles = {{1, {}, "x1, its loop scaled"},
                                         {2, {{0, 1}}, "x2, the two loops scaled together"},
                                         {4, {{1, 2}}, "x4, the inner two loops scaled together"},
                                         {2, {}, "x2, each loop scaled"},
                                         {4, {{0}, {1, 2}, {3}}, "x4, ends and middle scaled"},
                                         {4, {}, "x4, each loop scaled"},
                                         {8, {}, "x8, each loop scaled"}};
  std::vector<Round> rounds;
  for (const Profile& profile : profiles) {
    Round round;
    for (const int axis : axes) {
      const std::string name = "LoopCut " + build::AxisName(static_cast<build::Axis>(axis)) + " " + profile.name;
      for (bool subdivide : {false, true}) {
        round.alternatives.push_back([=](Layout* l) -> std::string {
          // Tried again in every pass (a bend or a hole accepted since can make it pay), but
          // not as a change to itself.
          if (l->profile_name == name || (subdivide && l->subdivide)) return "";
          l->profile = LoopCutWithScales(axis, profile.cuts, 4, profile.groups);
          l->profile_name = name;
          l->subdivide = l->subdivide || subdivide;
          return name + (subdivide ? " + Subdivision(2)" : "");
        });
      }
    }
    rounds.push_back(round);
  }
  return rounds;
}

}  // namespace opgraph
