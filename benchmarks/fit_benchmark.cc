// Levenberg-Marquardt (our dense normal-equations path, and Ceres' solver) vs Adam over the
// same objective and gradients, side by side:
// per gt-dev model the engine reproduces, its ground-truth skeleton with every parameter
// perturbed (as the recovery test), fitted to the Blender-built model.obj by both. Then the
// Jacobian throughput for a ~2,000-vertex program with 10,000 samples.
// Prints Markdown (docs/benchmarks.md holds a copy).
//
// usage: fit_benchmark [--models a,b] [--nothroughput] [--profile_lm N] [GT_DEV_DIR]
//        (default: ../shared/data/gt-dev beside the source tree)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>

#include <ceres/crs_matrix.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>
#include <gflags/gflags.h>

#include "apps/cli_flags.h"
#include "core/nearest.h"
#include "residuals/correspondence_cost.h"
#include "solver/fitter.h"
#include "tests/gt_convert.h"
#include "tests/perturb.h"

DEFINE_string(models, "", "comma-separated gt-dev model names to run (empty: all; each keeps its perturbation)");
DEFINE_bool(throughput, true, "also measure the Jacobian throughput");
DEFINE_int32(max_stalled_updates, opgraph::FitterOptions().max_stalled_updates,
             "stalled correspondence updates a stage carries on through (FitterOptions), for every optimizer");
DEFINE_bool(progress, false, "print each fit's correspondence updates on stderr (FitterOptions::progress)");
DEFINE_bool(count_unreproducible, false,
            "also count points where the sequence as written does not rebuild the program (no fit returns "
            "them; FitSummary::Point::reproducible), as the table did before 2026-12-08");
DEFINE_int32(profile_lm, 0, "for a profiler: fit each model this many times with the dense LM only, print their time");

namespace opgraph {
namespace {

namespace fs = std::filesystem;

double Now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

const char* OptimizerLabel(Optimizer optimizer) {
  switch (optimizer) {
    case Optimizer::kLm:
      return "LM (dense normal equations)";
    case Optimizer::kCeres:
      return "Ceres LM (dense QR)";
    case Optimizer::kAdam:
      break;
  }
  return "Adam";
}

struct Run {
  FitSummary summary;
  const char* name;
};

// The default fitter options with this benchmark's flags.
FitterOptions BenchmarkOptions(Optimizer optimizer) {
  FitterOptions options;
  options.optimizer = optimizer;
  options.max_stalled_updates = FLAGS_max_stalled_updates;
  if (FLAGS_progress) options.progress = &std::cerr;
  return options;
}

// First history point within 1 % of `best` (or below an absolute 1e-10: an RMS distance of
// 1e-5 of the unit box, where relative comparisons stop meaning anything).

// A point the table counts: one a fit may return (unless --count_unreproducible).
bool Counted(const FitSummary::Point& point) { return point.reproducible || FLAGS_count_unreproducible; }

const FitSummary::Point* Reached(const FitSummary& summary, double best) {
  const double threshold = std::max(1.01 * best, 1e-10);
  for (const FitSummary::Point& p : summary.history) {
    if (Counted(p) && p.loss <= threshold) return &p;
  }
  return nullptr;
}

void PrintOptimizerTableHead() {
  std::printf("## Levenberg-Marquardt vs Adam (lr 0.01), same objective\n\n");
  std::printf("Start: the ground-truth skeleton, every parameter perturbed (+-30 %%, +-0.3 rad); target: gt-dev "
              "`model.obj` (built by Blender). Loss: the objective with fresh correspondences (mean squared "
              "point-to-plane distances, both directions, unit box). \"To 1 %%\": the first correspondence update "
              "at which the loss is within 1 %% of the best either optimizer found (or below 1e-10), counting only "
              "points where the sequence as written rebuilds the program (points a fit may return)%s.\n\n",
              FLAGS_count_unreproducible ? "; here every point (--count_unreproducible)" : "");
  std::printf("| model | params | optimizer | to 1 %%: time (s) | to 1 %%: iterations | final loss | total time (s) | "
              "iterations | Jacobian evaluations |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
}

void CompareOptimizers(const fs::path& root) {
  std::vector<fs::path> models;
  for (const auto& entry : fs::directory_iterator(root)) models.push_back(entry.path());
  std::sort(models.begin(), models.end());
  if (FLAGS_max_stalled_updates < 0) throw std::invalid_argument("--max_stalled_updates: expected >= 0");
  const std::string named = FLAGS_models;
  for (size_t start = 0; start < named.size();) {
    const size_t end = std::min(named.find(',', start), named.size());
    const std::string name = named.substr(start, end - start);
    if (std::none_of(models.begin(), models.end(), [&](const fs::path& m) { return m.filename() == name; })) {
      throw std::invalid_argument("--models: no model '" + name + "' in " + root.string());
    }
    start = end + 1;
  }
  if (FLAGS_profile_lm > 0) {
    std::printf("| model | optimizer | fits | time |\n|---|---|---|---|\n");
  } else {
    PrintOptimizerTableHead();
  }
  int index = 0;
  // Per model and LM path: Adam's time to 1 % over LM's (Adam's total time when it never gets
  // there: a lower bound; 0 when LM does not).
  std::vector<std::vector<double>> speedups(2);
  for (const fs::path& model : models) {
    std::string why_not;
    const Json converted = ConvertGtSequence(model / "sequence.json", &why_not);
    if (converted.is_null()) continue;
    ++index;  // counted over every model, so a model's perturbation does not depend on --models
    if (!FLAGS_models.empty() &&
        ("," + FLAGS_models + ",").find("," + model.filename().string() + ",") == std::string::npos) {
      continue;
    }
    TargetOptions target_options;
    const std::unique_ptr<Target> target = LoadTarget((model / "model.obj").string(), target_options);
    if (FLAGS_profile_lm > 0) {
      double seconds = 0;
      for (int repeat = 0; repeat < FLAGS_profile_lm; ++repeat) {
        Sequence sequence = ParseSequence(converted);
        Fitter fitter(*target, &sequence, BenchmarkOptions(Optimizer::kLm));
        PerturbParameters(fitter.program(), sequence, 1000 + index);
        seconds += fitter.Fit().seconds;
      }
      std::printf("| %s | dense LM | %d | %.3f s |\n", model.filename().c_str(), FLAGS_profile_lm, seconds);
      continue;
    }
    std::vector<Run> runs;
    int num_params = 0;
    for (Optimizer optimizer : {Optimizer::kLm, Optimizer::kCeres, Optimizer::kAdam}) {
      Sequence sequence = ParseSequence(converted);
      Fitter fitter(*target, &sequence, BenchmarkOptions(optimizer));
      num_params = PerturbParameters(fitter.program(), sequence, 1000 + index);
      runs.push_back({fitter.Fit(), OptimizerLabel(optimizer)});
    }
    double best = std::numeric_limits<double>::infinity();
    for (const Run& run : runs) {
      for (const FitSummary::Point& p : run.summary.history) {
        if (Counted(p)) best = std::min(best, p.loss);
      }
    }
    const FitSummary::Point* adam = Reached(runs[2].summary, best);
    for (int lm = 0; lm < 2; ++lm) {
      const FitSummary::Point* reached = Reached(runs[lm].summary, best);
      speedups[lm].push_back(!reached ? 0 : (adam ? adam->seconds : runs[2].summary.seconds) / reached->seconds);
    }
    for (const Run& run : runs) {
      const FitSummary::Point* reached = Reached(run.summary, best);
      char time[32] = "not reached", iterations[32] = "not reached";
      if (reached) {
        std::snprintf(time, sizeof(time), "%.3f", reached->seconds);
        std::snprintf(iterations, sizeof(iterations), "%d", reached->iterations);
      }
      std::printf("| %s | %d | %s | %s | %s | %.3e | %.3f | %d | %d |\n", model.filename().c_str(), num_params, run.name,
                  time, iterations, run.summary.final_loss, run.summary.seconds, run.summary.inner_iterations,
                  run.summary.jacobian_evaluations);
      std::fflush(stdout);
    }
  }
  if (FLAGS_profile_lm > 0) return;
  std::printf("\nMedian over the %zu models of Adam's time to 1 %% over LM's (Adam's total time where it never gets "
              "there, 0 where LM does not):\n\n| LM path | median speed-up over Adam |\n|---|---|\n",
              speedups[0].size());
  for (int lm = 0; lm < 2; ++lm) {
    std::vector<double> values = speedups[lm];
    if (values.empty()) continue;
    std::sort(values.begin(), values.end());
    const size_t half = values.size() / 2;
    const double median = values.size() % 2 ? values[half] : 0.5 * (values[half - 1] + values[half]);
    std::printf("| %s | %.1fx |\n", OptimizerLabel(lm == 0 ? Optimizer::kLm : Optimizer::kCeres), median);
  }
}

void JacobianThroughput() {
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

}  // namespace
}  // namespace opgraph

int main(int argc, char** argv) {
  const std::vector<std::string> arguments = opgraph::ParseCommandLineOrExit(
      argc, argv,
      {"fit_benchmark",
       "usage: fit_benchmark [--models a,b] [--nothroughput] [--profile_lm N] [--max_stalled_updates N] "
       "[--progress] [GT_DEV_DIR]   "
       "(default: ../shared/data/gt-dev beside the source tree)",
       /*flags_file=*/__FILE__, /*max_arguments=*/1});
  const std::filesystem::path root =
      !arguments.empty() ? std::filesystem::path(arguments[0])
                         : std::filesystem::path(OPGRAPH_SOURCE_DIR) / ".." / "shared" / "data" / "gt-dev";
  try {
    opgraph::CompareOptimizers(root);
    if (FLAGS_throughput) opgraph::JacobianThroughput();
  } catch (const std::exception& e) {
    return opgraph::BadInput("fit_benchmark", e.what());
  }
  return 0;
}
