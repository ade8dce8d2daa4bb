// Levenberg-Marquardt (our dense normal-equations path, and Ceres' solver) vs Adam over the
// same objective and gradients, side by side:
// per gt-dev model the engine reproduces, its ground-truth skeleton with every parameter
// perturbed (as the recovery test), fitted to the Blender-built model.obj by both. Then the
// Jacobian throughput for a ~2,000-vertex program with 10,000 samples.
// Prints Markdown (docs/benchmarks.md holds a copy).
//
// usage: fit_benchmark [--models a,b] [--nothroughput] [--profile_lm N] [--returnable_only] [GT_DEV_DIR]
//        (default: ../shared/data/gt-dev beside the source tree)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>

#include <gflags/gflags.h>

#include "apps/cli_flags.h"
#include "benchmarks/jacobian_throughput.h"
#include "solver/fitter.h"
#include "tests/gt_convert.h"
#include "tests/perturb.h"

DEFINE_string(models, "", "comma-separated gt-dev model names to run (empty: all; each keeps its perturbation)");
DEFINE_bool(throughput, true, "also measure the Jacobian throughput");
DEFINE_int32(max_stalled_updates, opgraph::FitterOptions().max_stalled_updates,
             "stalled correspondence updates a stage carries on through (FitterOptions), for every optimizer");
DEFINE_bool(progress, false, "print each fit's correspondence updates on stderr (FitterOptions::progress)");
DEFINE_bool(returnable_only, false,
            "count only points where the sequence as written rebuilds the program (FitSummary::Point::"
            "reproducible): the points a fit may return");
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

// A point the table counts: any, or with --returnable_only one a fit may return.
bool Counted(const FitSummary::Point& point) { return point.reproducible || !FLAGS_returnable_only; }

// First counted history point within 1 % of `best` (or below an absolute 1e-10: an RMS distance
// of 1e-5 of the unit box, where relative comparisons stop meaning anything).
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
              "at which the loss is within 1 %% of the best either optimizer found (or below 1e-10)%s.\n\n",
              FLAGS_returnable_only ? ", counting only points where the sequence as written rebuilds the program "
                                      "(points a fit may return; --returnable_only)"
                                    : "");
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
  std::vector<std::string> never_returnable;  // models no optimizer passed a returnable point on
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
    if (std::none_of(runs.begin(), runs.end(), [](const Run& run) {
          return std::any_of(run.summary.history.begin(), run.summary.history.end(),
                             [](const FitSummary::Point& p) { return p.reproducible; });
        })) {
      never_returnable.push_back(model.filename().string());
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
  std::printf("\nModels where no optimizer passed a point the sequence as written rebuilds (its targets select "
              "otherwise along every path, so no fit can return its point):");
  for (const std::string& name : never_returnable) std::printf(" %s", name.c_str());
  std::printf("%s\n", never_returnable.empty() ? " none" : "");
}

}  // namespace
}  // namespace opgraph

int main(int argc, char** argv) {
  const std::vector<std::string> arguments = opgraph::ParseCommandLineOrExit(
      argc, argv,
      {"fit_benchmark",
       "usage: fit_benchmark [--models a,b] [--nothroughput] [--profile_lm N] [--max_stalled_updates N] "
       "[--progress] [--returnable_only] [GT_DEV_DIR]   "
       "(default: ../shared/data/gt-dev beside the source tree)",
       /*flags_file=*/__FILE__, /*max_arguments=*/1});
  const std::filesystem::path root =
      !arguments.empty() ? std::filesystem::path(arguments[0])
                         : std::filesystem::path(OPGRAPH_SOURCE_DIR) / ".." / "shared" / "data" / "gt-dev";
  try {
    opgraph::CompareOptimizers(root);
    if (FLAGS_throughput) opgraph::PrintJacobianThroughput();
  } catch (const std::exception& e) {
    return opgraph::BadInput("fit_benchmark", e.what());
  }
  return 0;
}
