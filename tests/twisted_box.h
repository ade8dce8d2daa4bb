// The twisted box the fitter tests fit: a scaled cube, loop-cut along Z and twisted.
#pragma once

namespace opgraph {

inline constexpr const char* kTwistedBox = R"({"operations": [
  {"op": "GlobalAffineScale", "params": {"scale": [0.6, 0.8, 1.8]}},
  {"op": "LoopCut", "params": {"axis": "Z", "cuts": 6, "near": [0.6, 0.8, 0]}},
  {"op": "SimpleDeformTwist", "params": {"axis": "Z", "angle_deg": 70}}]})";

}  // namespace opgraph
