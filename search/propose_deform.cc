// Simple deformations (search/proposals.h).
#include "search/pose.h"
#include "search/proposals.h"

namespace opgraph {

std::vector<Round> ProposeDeforms(const Layout& best) {
  using build::Deform;
  const int axis = LongAxis(best);
  struct Candidate {
    Deform kind;
    int axis;
    double amount;
  };
  // Starts on both sides of the identity, and a large twist (LM does not cross the twist of a
  // square section by a quarter turn from a small start).
  std::vector<Candidate> candidates = {{Deform::kTwist, axis, 30.0},  {Deform::kTwist, axis, -30.0},
                                       {Deform::kTwist, axis, 150.0}, {Deform::kTwist, axis, -150.0},
                                       {Deform::kTaper, axis, 0.2},   {Deform::kTaper, axis, -0.2},
                                       {Deform::kStretch, axis, 0.2}, {Deform::kStretch, axis, -0.2}};
  for (int a = 0; a < 3; ++a) {
    if (a == axis) continue;
    candidates.push_back({Deform::kBend, a, 30.0});
    candidates.push_back({Deform::kBend, a, -30.0});
  }
  std::vector<Round> rounds;
  for (const Candidate& c : candidates) {
    rounds.push_back(Round{{[c, axis](Layout* l) -> std::string {
      const Json op = build::SimpleDeform(c.kind, static_cast<build::Axis>(c.axis), c.amount);
      for (const Json& existing : l->deforms) {
        if (existing["op"] == op["op"] && existing["params"]["axis"] == op["params"]["axis"]) return "";
      }
      l->deforms.push_back(op);
      std::string what = "+" + op["op"].get<std::string>() + " " + op["params"]["axis"].get<std::string>();
      // Deformations need rings along the long axis to bend smoothly.
      if (l->profile.empty()) {
        l->profile = {build::LoopCut(static_cast<build::Axis>(axis), 7, Vec3d::Zero())};
        l->profile_name = "LoopCut x7";
        what += " (with LoopCut " + build::AxisName(static_cast<build::Axis>(axis)) + " x7)";
      }
      return what;
    }}});
  }
  return rounds;
}

}  // namespace opgraph
