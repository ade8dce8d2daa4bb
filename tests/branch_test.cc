// Softmax branch weights for discrete choices (program/program.h): the Jacobian columns of the
// branch logits against central finite differences, and fits that must pick the mirror axis a
// known sequence used and recover its shape.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "core/metrics.h"
#include "solver/fitter.h"
#include "tests/jacobian_check.h"

namespace opgraph {
namespace {

// A box moved off every mirror plane (no vertex is welded by any axis, so every option of the
// Mirror has one topology; the X and Y copies do not overlap it), then mirrored and twisted.
const char* kBranchSequence = R"({"operations": [
  {"op": "GlobalAffineScale", "params": {"scale": [0.5, 0.6, 0.6]}},
  {"op": "GlobalAffineTranslate", "params": {"offset": [1.2, 1.0, 0.3]}},
  {"op": "Mirror", "params": {"axes": ["X"]}},
  {"op": "SimpleDeformTwist", "params": {"axis": "Z", "angle_deg": 30}}]})";

std::vector<BranchChoice> MirrorAndTwistBranches() {
  return {{2, "axes", {Json::array({"X"}), Json::array({"Y"}), Json::array({"Z"})}},
          {3, "axis", {"X", "Y", "Z"}}};
}

// Every Jacobian column (op parameters, gates, both branches' logits) against central
// differences of the output positions, at non-uniform branch weights.
TEST(Branch, JacobianColumnsMatchCentralDifferences) {
  Sequence sequence = ParseSequence(Json::parse(kBranchSequence));
  Program program(&sequence, /*free_gates=*/true, MirrorAndTwistBranches());
  ASSERT_EQ(program.num_branches(), 2);
  const double logits[2][3] = {{0.3, -0.5, 0.8}, {-0.2, 0.6, 0.1}};
  int branch_blocks = 0;
  for (const ProgramBlock& block : program.blocks()) {
    if (!block.is_branch) continue;
    ASSERT_EQ(block.size, 3);
    for (int i = 0; i < 3; ++i) block.data[i] = logits[branch_blocks][i];
    ++branch_blocks;
  }
  ASSERT_EQ(branch_blocks, 2);
  program.PrepareForEvaluation(true, true);
  ASSERT_TRUE(program.valid());
  const std::vector<double> analytic_rows = [&] {
    std::vector<double> rows;
    for (size_t v = 0; v < program.positions().size(); ++v) {
      const double* row = program.JacobianRows(static_cast<int>(v));
      rows.insert(rows.end(), row, row + 3 * program.num_columns());
    }
    return rows;
  }();
  int compared = 0, nonzero_branch = 0;
  for (const ProgramBlock& block : program.blocks()) {
    for (int j = 0; j < block.size; ++j) {
      if (std::count(block.constant.begin(), block.constant.end(), j)) continue;
      const double saved = block.data[j];
      const double h = 1e-6 * std::max(1.0, std::abs(saved));
      block.data[j] = saved + h;
      program.PrepareForEvaluation(false, true);
      const Positions<double> plus = program.positions();
      block.data[j] = saved - h;
      program.PrepareForEvaluation(false, true);
      const Positions<double> minus = program.positions();
      block.data[j] = saved;
      for (size_t v = 0; v < plus.size(); ++v) {
        for (int d = 0; d < 3; ++d) {
          const double numeric = (plus[v][d] - minus[v][d]) / (2 * h);
          const double analytic = analytic_rows[(3 * v + d) * program.num_columns() + block.column + j];
          ASSERT_NEAR(analytic, numeric, 1e-6 * std::max(1.0, std::abs(numeric)))
              << "op " << block.op << (block.is_branch ? " branch logit " : " column ") << j << " vertex " << v;
          ++compared;
          nonzero_branch += block.is_branch && std::abs(numeric) > 1e-3;
        }
      }
    }
  }
  EXPECT_GT(compared, 0);
  EXPECT_GT(nonzero_branch, 100);  // the logits do move the output
}

// Fits `start` (its op 2 a Mirror, fitted as a branch over X, Y, Z from uniform weights) to the
// shape `truth` builds: the fit must pick `axis` (truth's), recover the shape, and the written
// sequence must re-evaluate to the program's fitted result with truth's topology.
void ExpectBranchFitPicksTheAxis(const Json& truth_json, const char* start, const char* axis, bool mixed,
                                 bool fit_gates = false) {
  Sequence truth = ParseSequence(truth_json);
  const Mesh target_mesh = EvaluateSequence(&truth).back();
  TargetOptions target_options;
  target_options.num_samples = 5000;
  const Target target(target_mesh, {}, target_options);

  Sequence sequence = ParseSequence(Json::parse(start));
  FitterOptions options;
  options.num_output_samples = 2000;
  options.num_target_samples = 2000;
  options.branches = {MirrorAndTwistBranches()[0]};
  options.fit_gates = fit_gates;  // the gate stage and finalisation run after the commit
  if (std::getenv("OPGRAPH_FIT_VERBOSE")) options.progress = &std::cout;
  Fitter fitter(target, &sequence, options);
  ASSERT_EQ(fitter.program().MixedBranchBlock() >= 0, mixed);
  const FitSummary summary = fitter.Fit();
  ASSERT_EQ(summary.branch_choices.size(), 1u);
  const std::vector<double>& w = summary.branch_weights[0];
  const char* kind = mixed ? "mixed" : (fit_gates ? "blended, with gates" : "blended");
  std::printf("[branch] %s, target Mirror %s: weights X %.3f Y %.3f Z %.3f -> %s, loss %.3e -> %.3e\n", kind, axis, w[0],
              w[1], w[2], SequenceToJson(sequence)["operations"][2]["params"]["axes"].dump().c_str(), summary.initial_loss,
              summary.final_loss);
  EXPECT_EQ(summary.branch_choices[0], axis[0] - 'X') << axis;
  EXPECT_EQ(SequenceToJson(sequence)["operations"][2]["params"]["axes"], Json::array({axis}));

  const Mesh fitted = EvaluateSequence(&sequence).back();  // the sequence as written
  EXPECT_EQ(fitted.faces, target_mesh.faces) << axis;
  const Mesh program_output = fitter.program().OutputMesh();
  ASSERT_EQ(fitted.vertices.size(), program_output.vertices.size());
  for (size_t v = 0; v < fitted.vertices.size(); ++v) {
    EXPECT_LT((fitted.vertices[v] - program_output.vertices[v]).norm(), 1e-9);
  }
  MetricsOptions metrics_options;
  metrics_options.num_samples = 5000;
  const double chamfer = ComputeShapeMetrics(fitted, target_mesh, metrics_options).chamfer.Sum();
  std::printf("[branch] %s, target Mirror %s: Chamfer %.2e\n", kind, axis, chamfer);
  EXPECT_LT(chamfer, 1e-4) << axis;
}

// Targets from the same box mirrored about X and about Y: from uniform weights over X, Y, Z and
// perturbed parameters the fit picks the target's axis, recovers the shape, and the written
// sequence re-evaluates to the fitted result.
TEST(Branch, SoftmaxBranchPicksTheMirrorAxis) {
  const char* start = R"({"operations": [
    {"op": "GlobalAffineScale", "params": {"scale": [0.6, 0.5, 0.7]}},
    {"op": "GlobalAffineTranslate", "params": {"offset": [1.0, 0.8, 0.2]}},
    {"op": "Mirror", "params": {"axes": ["Z"]}}]})";
  for (const char* axis : {"X", "Y"}) {
    Json truth_json = Json::parse(kBranchSequence);
    truth_json["operations"].erase(3);
    truth_json["operations"][2]["params"]["axes"] = Json::array({axis});
    ExpectBranchFitPicksTheAxis(truth_json, start, axis, /*mixed=*/false);
    ExpectBranchFitPicksTheAxis(truth_json, start, axis, /*mixed=*/false, /*fit_gates=*/true);
  }
}

// A box touching the X plane: Mirror X welds it to its copy, Y and Z do not, so the options'
// topologies differ (a mixed branch, only as the last op).
const char* kTouchingStart = R"({"operations": [
  {"op": "GlobalAffineScale", "params": {"scale": [0.5, 0.5, 0.7]}},
  {"op": "GlobalAffineTranslate", "params": {"offset": [0.5, 0.8, 0.2]}},
  {"op": "Mirror", "params": {"axes": ["Y"]}}]})";

// The mixed branch's weighted Chamfer residuals (sqrt(w_k) times a correspondence on option
// k's surface): every column, the logits' included, against central differences.
TEST(Branch, MixedBranchResidualJacobiansMatchCentralDifferences) {
  Sequence sequence = ParseSequence(Json::parse(kTouchingStart));
  Program program(&sequence, /*free_gates=*/true, {MirrorAndTwistBranches()[0]});
  ASSERT_GE(program.MixedBranchBlock(), 0);
  const ProgramBlock& logits = program.blocks()[program.MixedBranchBlock()];
  for (int i = 0; i < 3; ++i) logits.data[i] = 0.4 * i - 0.3;
  ASSERT_TRUE(program.EvaluateValues());
  const std::vector<MeshTriangle> triangles = FanTriangulate(program.faces());
  const SurfaceSamples samples = SampleSurface(program.positions(), triangles, 12, 5);
  int nonzero_logits = 0;
  std::vector<int> per_option(3, 0);
  for (size_t s = 0; s < samples.points.size(); ++s) {
    const MeshTriangle& t = triangles[samples.triangles[s]];
    SurfaceCorrespondence c;
    for (int k = 0; k < 3; ++k) c.vertices[k] = t.v[k], c.weights[k] = samples.barycentrics[s][k];
    c.target_point = samples.points[s] + Vec3d(0.1, -0.2, 0.15);
    c.target_normal = Vec3d(0.3, 1, -0.2).normalized();
    const int option = program.face_options()[t.face];
    ++per_option[option];
    const BranchWeightedCost cost(&program, c, ChamferMetric::kPointToPoint, 0.8, program.MixedBranchBlock(), option);
    const JacobianComparison result = ExpectJacobianMatchesCentralDifferences(&program, cost, "mixed branch", 1e-6);
    nonzero_logits += result.nonzero_per_block[program.MixedBranchBlock()];
  }
  EXPECT_GT(nonzero_logits, 12);
  EXPECT_GT(per_option[0] * per_option[1] * per_option[2], 0);  // samples on every option
}

// Targets built by that box mirrored about X (welded) and about Y: the fit mixes the options'
// Chamfer terms from uniform weights, picks the target's axis and recovers the shape.
TEST(Branch, MixedBranchPicksTheMirrorAxis) {
  for (const char* axis : {"X", "Y"}) {
    Json truth_json = Json::parse(kTouchingStart);
    truth_json["operations"][0]["params"]["scale"] = {0.5, 0.6, 0.6};
    truth_json["operations"][1]["params"]["offset"] = {0.5, 1.0, 0.3};
    truth_json["operations"][2]["params"]["axes"] = Json::array({axis});
    ExpectBranchFitPicksTheAxis(truth_json, kTouchingStart, axis, /*mixed=*/true);
  }
}

TEST(Branch, BadChoicesAreOneLineErrors) {
  Sequence sequence = ParseSequence(Json::parse(kBranchSequence));
  const std::vector<BranchChoice> bad[] = {
      {{7, "axes", {Json::array({"X"}), Json::array({"Y"})}}},     // no such op
      {{2, "angle", {Json::array({"X"}), Json::array({"Y"})}}},    // no such field
      {{2, "axes", {Json::array({"X"}), Json::array({"W"})}}},     // bad option
      {{2, "axes", {Json::array({"X"})}}},                         // one option
  };
  for (const auto& branches : bad) {
    try {
      Program program(&sequence, false, branches);
      ADD_FAILURE() << "accepted " << branches[0].field;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
      EXPECT_NE(std::string(e.what()).find("branch choice"), std::string::npos) << e.what();
    }
  }
  // A box touching the X plane: Mirror X welds its vertices there, Mirror Y does not, so the
  // options have different topologies: supported only on the last op (here a Twist follows).
  Json touching = Json::parse(kBranchSequence);
  touching["operations"][1]["params"]["offset"] = {1.0, 1.0, 0.3};
  touching["operations"][0]["params"]["scale"] = {1.0, 0.6, 0.6};
  Sequence welded = ParseSequence(touching);
  EXPECT_THROW(Program(&welded, false, {MirrorAndTwistBranches()[0]}), std::invalid_argument);
}

}  // namespace
}  // namespace opgraph
