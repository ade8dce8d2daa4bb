#include "benchmarks/jacobian_throughput.h"

#include <chrono>
#include <cstdio>
#include <memory>
#include <vector>

#include <ceres/crs_matrix.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>

#include "core/nearest.h"
#include "residuals/correspondence_cost.h"

namespace opgraph {
namespace {

double Now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

void PrintJacobianThroughput() {
  const char* document = R"({"operations": [
    {"op": "GlobalAffineScale", "params": {"scale": [0.7, 0.9, 1.6]}},
    {"op": "LoopCut", "params": {"axis": "Z", "cuts": 5, "near": [0.7, 0.9, 0]}},
    {"op": "Extrude", "params": {"faces": {"normal": [0, 0, 1], "expect": 1}, "height": 0.5, "width": 0.6}},
    {"op": "SimpleDeformTwist", "params": {"axis": "Z", "angle_deg": 50}},
    {"op": "SimpleDeformBend", "params": {"axis": "X", "angle_deg": 30}},
    {"op": "Subdivision", "params": {"levels": 3}}]})";
  Sequence sequence = ParseSequence(Json::parse(document));
  Program program(&sequence, /*free_gates=*/false);
  program.EvaluateValues();
  const int num_vertices = static_cast<int>(program.positions().size());
  constexpr int kSamples = 10000;
  const std::vector<MeshTriangle> triangles = FanTriangulate(program.faces());
  const SurfaceSamples samples = SampleSurface(program.positions(), triangles, kSamples, 1);
  std::vector<std::unique_ptr<CorrespondenceCost>> costs;
  for (int i = 0; i < kSamples; ++i) {
    SurfaceCorrespondence c;
    for (int k = 0; k < 3; ++k) c.vertices[k] = triangles[samples.triangles[i]].v[k], c.weights[k] = samples.barycentrics[i][k];
    c.target_point = samples.points[i] + samples.normals[i] * 0.01;
    c.target_normal = samples.normals[i];
    costs.push_back(std::make_unique<CorrespondenceCost>(&program, c, ChamferMetric::kPointToPlane, 0.01));
  }
  const std::vector<double*> blocks = program.BlockPointers();
  std::vector<std::vector<double>> jacobian_storage;
  std::vector<double*> jacobians;
  for (int size : program.BlockSizes()) {
    jacobian_storage.emplace_back(3 * size);
    jacobians.push_back(jacobian_storage.back().data());
  }
  double residuals[3];

  int program_runs = 0;
  double start = Now();
  while (Now() - start < 2.0) {
    program.PrepareForEvaluation(true, true);
    ++program_runs;
  }
  const double program_rate = program_runs / (Now() - start);

  int full_runs = 0;
  start = Now();
  while (Now() - start < 2.0) {
    program.PrepareForEvaluation(true, true);
    for (const auto& cost : costs) cost->Evaluate(blocks.data(), residuals, jacobians.data());
    ++full_runs;
  }
  const double full_rate = full_runs / (Now() - start);

  // The same through Ceres (its evaluator and block-sparse Jacobian assembly), as in a solve.
  ceres::Problem::Options problem_options;
  problem_options.evaluation_callback = &program;
  problem_options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  for (const auto& cost : costs) problem.AddResidualBlock(cost.get(), nullptr, blocks);
  for (const ProgramBlock& block : program.blocks()) {
    if (!block.constant.empty()) problem.SetManifold(block.data, new ceres::SubsetManifold(block.size, block.constant));
  }
  ceres::CRSMatrix jacobian;
  std::vector<double> residual_values;
  double cost_value = 0;
  int ceres_runs = 0;
  start = Now();
  while (Now() - start < 2.0) {
    problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost_value, &residual_values, nullptr, &jacobian);
    ++ceres_runs;
  }
  const double ceres_rate = ceres_runs / (Now() - start);

  std::printf("\n## Jacobian throughput\n\n");
  std::printf("Program: scale, loop cut, extrude, twist, bend, Subdivision level 3: %d vertices, %d fitted parameters "
              "(%d forward-mode passes of 4 directions); %d point-to-plane samples. One thread.\n\n",
              num_vertices, program.num_free_columns(), (program.num_free_columns() + 3) / 4, kSamples);
  std::printf("| what | evaluations per second |\n|---|---|\n");
  std::printf("| program values + Jacobian d(positions)/d(params) | %.1f |\n", program_rate);
  std::printf("| the above + %d residual Jacobians (chain rule through barycentrics) | %.1f |\n", kSamples, full_rate);
  std::printf("| the above through Ceres' Problem::Evaluate (its evaluator, plus conversion to a CRSMatrix) | %.1f |\n", ceres_rate);
}

}  // namespace opgraph
