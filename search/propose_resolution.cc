// Loop-cut counts (search/proposals.h).
#include <algorithm>

#include "search/loop_ops.h"
#include "search/proposals.h"

namespace opgraph {
namespace {

// The counts tried for a bare LoopCut: from a coarse ring to finer than the deform stage's
// first guess (x7); for a profile with a scale per loop, up to the profile family's finest (x8).
constexpr int kMinCuts = 1;
constexpr int kMaxBareCuts = 12;
constexpr int kMaxScaledCuts = 8;

// The profile's loop scales at `count` evenly spaced loops (position in (-1, 1) along the axis),
// interpolated linearly from the fitted scales of the current loops, the cube's end faces
// (unscaled) at the ends; so a finer or coarser profile starts from the fitted shape.
std::vector<Vec3d> ResampledScales(const std::vector<Vec3d>& scales, int count) {
  std::vector<double> at = {-1.0};
  std::vector<Vec3d> value = {Vec3d::Ones()};
  for (size_t i = 0; i < scales.size(); ++i) {
    at.push_back(-1.0 + 2.0 * (i + 1) / (scales.size() + 1));
    value.push_back(scales[i]);
  }
  at.push_back(1.0);
  value.push_back(Vec3d::Ones());
  std::vector<Vec3d> resampled;
  for (int k = 0; k < count; ++k) {
    const double p = -1.0 + 2.0 * (k + 1) / (count + 1);
    const size_t hi = std::upper_bound(at.begin(), at.end(), p) - at.begin();
    const size_t lo = hi - 1;
    const double t = (p - at[lo]) / (at[hi] - at[lo]);
    resampled.push_back((1 - t) * value[lo] + t * value[hi]);
  }
  return resampled;
}

// The fitted scale of each loop of a profile with one EdgeLoopAffineScale per loop, or empty
// when the profile is not of that form.
std::vector<Vec3d> PerLoopScales(const std::vector<Json>& profile, int cuts) {
  if (static_cast<int>(profile.size()) != cuts + 1) return {};
  std::vector<Vec3d> scales;
  for (size_t i = 1; i < profile.size(); ++i) {
    if (profile[i]["op"] != "EdgeLoopAffineScale") return {};
    const Json& s = profile[i]["params"]["scale"];
    scales.emplace_back(s[0].get<double>(), s[1].get<double>(), s[2].get<double>());
  }
  return scales;
}

}  // namespace

std::vector<Round> ProposeLoopCounts(const Layout& best) {
  if (best.profile.empty() || best.profile[0]["op"] != "LoopCut") return {};
  const Json& cut = best.profile[0];
  const int current = cut["params"]["cuts"].get<int>();
  const int axis = static_cast<int>(build::AxisNamed(cut["params"]["axis"].get<std::string>()));
  const std::string axis_name = build::AxisName(static_cast<build::Axis>(axis));
  // A bare LoopCut is a deformation's resolution: nothing else addresses its loops.
  const bool bare = best.profile.size() == 1 && !best.deforms.empty();
  const std::vector<Vec3d> scales = PerLoopScales(best.profile, current);
  if (!bare && scales.empty()) return {};
  Round round;
  for (int cuts = kMinCuts; cuts <= (bare ? kMaxBareCuts : kMaxScaledCuts); ++cuts) {
    if (cuts == current) continue;
    round.alternatives.push_back([=](Layout* l) -> std::string {
      const std::string name = "LoopCut " + axis_name + " x" + std::to_string(cuts);
      if (bare) {
        l->profile = {build::LoopCut(static_cast<build::Axis>(axis), cuts, Vec3d::Zero())};
        l->profile_name = name;
        return name;
      }
      l->profile = LoopCutWithScales(axis, cuts, 4);
      const std::vector<Vec3d> start = ResampledScales(scales, cuts);
      for (int k = 0; k < cuts; ++k) l->profile[k + 1]["params"]["scale"] = ToJson(start[k]);
      l->profile_name = name + ", each loop scaled";
      return l->profile_name + " (from x" + std::to_string(current) + ")";
    });
  }
  return {round};
}

}  // namespace opgraph
