// The topology passes (Op::Prepare) of the ops that navigate connectivity, timed with Google
// Benchmark on a lattice cube: Blender's default cube loop-cut along X, Y and Z into n x n
// quads per side (6 n^2 quads). Not a test; docs/benchmarks.md ("Topology pass") holds the
// numbers before and after the ops moved onto the half-edge mesh (ops/halfedge_topology.h).
//
// usage: prepare_benchmark [--benchmark_filter=REGEX] [--benchmark_repetitions=N ...]
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>

#include "ops/op.h"

namespace opgraph {
namespace {

// Runs `op` (Prepare, then Evaluate at gate 1) on `mesh`.
Mesh Apply(Op* op, const Mesh& mesh) {
  op->Prepare(mesh);
  Mesh out;
  const double gate = 1;
  op->Evaluate(op->params().data(), gate, mesh.vertices, &out.vertices);
  out.faces = op->output_faces();
  return out;
}

// Blender's cube (side 2) with n - 1 loop cuts along each axis: n x n quads per side.
Mesh LatticeCube(int n) {
  Mesh mesh = MakeCube(2);
  if (n < 2) return mesh;
  for (const char* axis : {"X", "Y", "Z"}) {
    // On the cube (and after the earlier cuts) one ring holds every edge along `axis`.
    const Json params = {{"axis", axis}, {"cuts", n - 1}};
    mesh = Apply(CreateOp("LoopCut", params).get(), mesh);
  }
  return mesh;
}

const Mesh& CachedLatticeCube(int n) {
  static std::map<int, Mesh> meshes;
  auto it = meshes.find(n);
  if (it == meshes.end()) it = meshes.emplace(n, LatticeCube(n)).first;
  return it->second;
}

// One benchmark: Prepare of the op `name` with `params` on the lattice cube of side range(0).
void PrepareOp(benchmark::State& state, const std::string& name, const Json& params) {
  const Mesh& mesh = CachedLatticeCube(static_cast<int>(state.range(0)));
  std::unique_ptr<Op> op = CreateOp(name, params);
  for (auto _ : state) {
    op->Prepare(mesh);
    benchmark::DoNotOptimize(op->output_faces().data());
  }
  state.counters["faces"] = mesh.NumFaces();
}

void Register() {
  const Json up = {{"normal", {0, 0, 1}}};
  const struct {
    std::string label, op;
    Json params;
  } cases[] = {
      {"LoopCut", "LoopCut", {{"axis", "X"}, {"cuts", 3}, {"near", {0.01, 0.3, 0.2}}}},
      {"KnifeCutPlane", "KnifeCut", {{"plane_co", {0.013, 0.021, 0.034}}, {"plane_no", {1, 0.3, 0.2}}}},
      {"KnifeCutEdge", "KnifeCut", {{"face", {{"normal", {0, 0, 1}}, {"centers", {{0.01, 0.02, 1}}}}},
                                    {"edge_points", {{-1, 0, 1}, {1, 0, 1}}}}},
      {"ExtrudeRegion", "Extrude", {{"faces", up}, {"height", 0.3}}},
      {"ExtrudeIndividual", "Extrude", {{"faces", up}, {"mode", "individual"}, {"height", 0.3}}},
      {"Inset", "Inset", {{"faces", up}, {"thickness", 0.05}}},
      {"BevelAngle", "Bevel", {{"width", 0.02}, {"segments", 3}, {"limit_method", "ANGLE"}}},
      {"BevelAll", "Bevel", {{"width", 0.01}, {"segments", 2}}},
      // Through the lattice cube (side 2) off its axes: cuts the side faces and leaves holes in
      // the caps, so every step of the topology pass (provenance, merge, dissolve) has work.
      {"BooleanDifference", "Boolean", {{"operation", "DIFFERENCE"}, {"primitive", "cylinder"},
                                        {"size", {0.9, 0.9, 3}}, {"rotation_deg", {10, 5, 0}},
                                        {"location", {0.13, 0.07, 0}}}},
  };
  for (const auto& c : cases) {
    benchmark::RegisterBenchmark(("Prepare/" + c.label).c_str(), PrepareOp, c.op, c.params)
        ->Arg(8)
        ->Arg(32)
        ->Unit(benchmark::kMicrosecond);
  }
}

}  // namespace
}  // namespace opgraph

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  opgraph::Register();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
