// Program evaluation and residual Jacobians against central finite differences, through the
// shared EvaluationCallback cache, with every kind of parameter block (op parameters, gate
// logits, held parameters).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <random>

#include "core/nearest.h"
#include "residuals/correspondence_cost.h"
#include "program/program.h"
#include "tests/jacobian_check.h"

namespace opgraph {
namespace {

const char* kSequence = R"({"operations": [
  {"op": "GlobalAffineScale", "params": {"scale": [1.2, 0.8, 1.5]}},
  {"op": "LoopCut", "params": {"axis": "Z", "cuts": 2, "near": [1, 1, 0]}},
  {"op": "Extrude", "params": {"faces": {"normal": [1, 0, 0], "centers": [[1.2, 0, 0]], "expect": 1}, "height": 0.7, "width": 0.8, "tilt_deg": [5, -10]}},
  {"op": "SimpleDeformTwist", "params": {"axis": "Z", "angle_deg": 40}},
  {"op": "Mirror", "params": {"axes": ["Y"]}},
  {"op": "SimpleDeformBend", "params": {"axis": "X", "angle_deg": 25}},
  {"op": "Subdivision", "params": {"levels": 1}}]})";

void ExpectFittedColumnsMatch(Program* program, const ceres::CostFunction& cost, const char* what) {
  const JacobianComparison result = ExpectJacobianMatchesCentralDifferences(program, cost, what, 1e-5);
  EXPECT_EQ(result.compared, 13 * cost.num_residuals()) << what;  // the 13 fitted columns
  EXPECT_GT(result.nonzero(), 3) << what;
}

TEST(Program, BlocksFollowTheJsonAndGates) {
  Sequence sequence = ParseSequence(Json::parse(kSequence));
  Program program(&sequence, /*free_gates=*/true);
  // Scale(3) + gate, Extrude(4) + gate, Twist(1) + gate, Bend(1) + gate; Subdivision's
  // level_blend is not in the JSON and LoopCut/Mirror have no parameters: fixed gates.
  ASSERT_EQ(program.blocks().size(), 8u);
  EXPECT_EQ(program.num_free_columns(), 3 + 1 + 4 + 1 + 1 + 1 + 1 + 1);
  EXPECT_FALSE(program.GateIsFree(1));
  EXPECT_FALSE(program.GateIsFree(4));
  EXPECT_FALSE(program.GateIsFree(6));
  EXPECT_NEAR(program.Gate(0), 0.98, 1e-12);
  EXPECT_TRUE(program.EvaluateValues());
  // Same as the engine with the same gates.
  program.StoreGates();
  Sequence copy = ParseSequence(SequenceToJson(sequence));
  copy.gates = sequence.gates;
  const Mesh expected = EvaluateSequence(&copy).back();
  ASSERT_EQ(expected.NumVertices(), static_cast<int>(program.positions().size()));
  for (int v = 0; v < expected.NumVertices(); ++v) {
    EXPECT_LT((expected.vertices[v] - program.positions()[v]).norm(), 1e-9);
  }
}

// A pinned op keeps its parameters and its gate while the others (gates too) are fitted: it has
// no gate block, so it is evaluated at its own gate (1), not at the clamped 0.98 of a free one.
TEST(Program, PinnedOpHasNoGateBlock) {
  Json document = Json::parse(kSequence);
  document["operations"][3]["pinned"] = true;  // the twist
  Sequence sequence = ParseSequence(document);
  Program program(&sequence, /*free_gates=*/true);
  EXPECT_TRUE(program.GateIsFree(0));
  EXPECT_FALSE(program.GateIsFree(3));
  EXPECT_EQ(program.Gate(3), 1.0);
  ASSERT_EQ(program.blocks().size(), 7u);  // the twist's parameter block, and no gate block
  program.StoreGates();
  EXPECT_EQ(sequence.gates[3], 1.0);
}

TEST(Residuals, JacobiansMatchCentralDifferences) {
  Sequence sequence = ParseSequence(Json::parse(kSequence));
  Program program(&sequence, /*free_gates=*/true);
  ASSERT_TRUE(program.EvaluateValues());
  const std::vector<MeshTriangle> triangles = FanTriangulate(program.faces());
  const SurfaceSamples samples = SampleSurface(program.positions(), triangles, 6, 11);
  std::mt19937_64 rng(5);
  for (int s = 0; s < 6; ++s) {
    SurfaceCorrespondence c;
    for (int k = 0; k < 3; ++k) {
      c.vertices[k] = triangles[samples.triangles[s]].v[k];
      c.weights[k] = samples.barycentrics[s][k];
    }
    c.target_point = samples.points[s] + Vec3d(UnitRandom(rng()), UnitRandom(rng()), UnitRandom(rng())) * 0.3;
    c.target_normal = Vec3d(UnitRandom(rng()) - 0.5, 1, UnitRandom(rng())).normalized();
    const CorrespondenceCost to_point(&program, c, ChamferMetric::kPointToPoint, 0.7);
    const CorrespondenceCost to_plane(&program, c, ChamferMetric::kPointToPlane, 1.3);
    ExpectFittedColumnsMatch(&program, to_point, "point-to-point");
    ExpectFittedColumnsMatch(&program, to_plane, "point-to-plane");
    const CorrespondenceCost to_both(&program, c, ChamferMetric::kPlaneAndPoint, 0.9);
    ExpectFittedColumnsMatch(&program, to_both, "plane and point");
  }
}

TEST(Residuals, GateAndRangeCostsMatchCentralDifferences) {
  const double weight = 0.3;
  const GateSparsityCost gate(&weight);
  for (double w : {-3.0, 0.0, 1.5}) {
    const double* parameters[] = {&w};
    double r, j;
    double* jacobians[] = {&j};
    ASSERT_TRUE(gate.Evaluate(parameters, &r, jacobians));
    EXPECT_NEAR(r, std::sqrt(weight) / (1 + std::exp(-w)), 1e-15);
    const double h = 1e-6, wp = w + h, wm = w - h;
    double rp, rm;
    const double* pp[] = {&wp};
    const double* pm[] = {&wm};
    gate.Evaluate(pp, &rp, nullptr);
    gate.Evaluate(pm, &rm, nullptr);
    EXPECT_NEAR(j, (rp - rm) / (2 * h), 1e-8);
  }
  const ParameterRangeCost range({0, 1, 0.5, 2.0, 4.0}, 3);
  for (double x : {0.2, 1.0, 3.0}) {
    const double block[3] = {9, x, 9};
    const double* parameters[] = {block};
    double r, j[3];
    double* jacobians[] = {j};
    ASSERT_TRUE(range.Evaluate(parameters, &r, jacobians));
    EXPECT_NEAR(r, 2.0 * (std::max(0.0, 0.5 - x) + std::max(0.0, x - 2.0)), 1e-15);
    EXPECT_EQ(j[1], x < 0.5 ? -2.0 : (x > 2.0 ? 2.0 : 0.0));
    EXPECT_EQ(j[0], 0.0);
  }
}

}  // namespace
}  // namespace opgraph

// Counts heap allocations (operator new) so the hot loop can be checked allocation-free.
namespace {
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace opgraph {
namespace {

// After the first evaluation has sized every buffer, evaluating the program (values and
// Jacobian) and every residual block with its Jacobian allocates nothing.
TEST(Program, HotLoopDoesNotAllocate) {
  Sequence sequence = ParseSequence(Json::parse(kSequence));
  Program program(&sequence, /*free_gates=*/true);
  program.PrepareForEvaluation(true, true);
  const std::vector<MeshTriangle> triangles = FanTriangulate(program.faces());
  const SurfaceSamples samples = SampleSurface(program.positions(), triangles, 100, 3);
  std::vector<std::unique_ptr<CorrespondenceCost>> costs;
  for (size_t i = 0; i < samples.points.size(); ++i) {
    SurfaceCorrespondence c;
    for (int k = 0; k < 3; ++k) c.vertices[k] = triangles[samples.triangles[i]].v[k], c.weights[k] = samples.barycentrics[i][k];
    c.target_point = samples.points[i];
    c.target_normal = samples.normals[i];
    costs.push_back(std::make_unique<CorrespondenceCost>(&program, c, ChamferMetric::kPointToPoint, 1.0));
  }
  const std::vector<double*> blocks = program.BlockPointers();
  std::vector<std::vector<double>> storage;
  std::vector<double*> jacobians;
  for (int size : program.BlockSizes()) storage.emplace_back(3 * size);
  for (auto& s : storage) jacobians.push_back(s.data());
  double residuals[3];
  const long before = g_allocations.load();
  for (int round = 0; round < 3; ++round) {
    blocks[0][0] += 0.01;
    program.PrepareForEvaluation(true, true);
    for (const auto& cost : costs) ASSERT_TRUE(cost->Evaluate(blocks.data(), residuals, jacobians.data()));
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
  // The counter does see allocations.
  const long counted = g_allocations.load();
  auto probe = std::make_unique<std::vector<double>>(10);
  EXPECT_GT(g_allocations.load(), counted);
}

}  // namespace
}  // namespace opgraph
