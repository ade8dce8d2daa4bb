// Prints, for each sequence.json given, which replay guards (ops/replay_guards.h) flag it, and
// how many each flags in all: how conservative a guard is on sequences real Blender rebuilds
// (the synthetic corpus).  Usage: build/replay_guard_scan out/synth/*/sequence.json
#include <iostream>
#include <map>

#include "apps/cli_flags.h"
#include "ops/replay_guards.h"
#include "ops/sequence.h"

int main(int argc, char** argv) {
  constexpr const char* kUsage = "usage: replay_guard_scan SEQUENCE.json...";
  const std::vector<std::string> paths = opgraph::ParseCommandLineOrExit(
      argc, argv, {"replay_guard_scan", kUsage, /*flags_file=*/"", /*max_arguments=*/1 << 20});
  if (paths.empty()) return opgraph::BadInput("replay_guard_scan", std::string(kUsage) + " (see --help)");
  std::map<std::string, int> flagged;
  for (const std::string& path : paths) {
    try {
      opgraph::Sequence sequence = opgraph::LoadSequence(path);
      const std::vector<opgraph::Mesh> steps = opgraph::EvaluateSequence(&sequence);
      const std::map<std::string, bool> guards = {
          {"collapsed_edge", opgraph::HasCollapsedEdge(steps)},
          {"two_edge_vertex", opgraph::SubdividesTwoEdgeVertex(opgraph::SequenceToJson(sequence), steps)},
          {"near_branch", opgraph::NearGeometricBranch(sequence, steps)},
          {"hole_unknown_loop_start", opgraph::HolesAFaceOfUnknownLoopStart(sequence, steps)}};
      std::cout << path;
      for (const auto& [name, hit] : guards) {
        if (hit) std::cout << " " << name, ++flagged[name];
      }
      std::cout << "\n";
    } catch (const std::exception& e) {
      return opgraph::BadInput("replay_guard_scan", path + ": " + e.what());
    }
  }
  std::cout << "flagged of " << paths.size() << ":";
  for (const auto& [name, count] : flagged) std::cout << " " << name << " " << count;
  std::cout << "\n";
  return 0;
}
