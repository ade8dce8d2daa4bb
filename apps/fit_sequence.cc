// fit_sequence --input TARGET --out DIR [--init SEQ.json] [--work-budget N] [--time-budget S]
//              [--max-ops N] [--seed N] [--optimizer ceres|adam] [--fit-gates] [--loss none|huber|cauchy]
//              [--samples N] [--threads N] [--no-freeform] [--blender-axes import|raw] [--quiet]
// Without --init (the main job): recovers a design sequence for TARGET (a mesh or point cloud,
// any format io/read_input reads) from scratch with the zero-shot controller
// (search/zero_shot.h). With --init: fits every continuous parameter of the sequence skeleton
// SEQ.json (ops and discrete choices fixed; its parameters are the start).
// Writes DIR/sequence.json, DIR/result.obj (in the input's frame and units),
// DIR/steps/NN_<op>.obj, DIR/rebuild_blender.py, DIR/metrics.json and DIR/log.txt (the
// controller's decisions), replacing an earlier run's DIR whole (apps/output_folder.h).
// Progress on stdout: a bar on a terminal, plain lines otherwise.
// --work-budget: the search's budget in work units (search/zero_shot.h: Jacobian evaluations
// weighted by the program's size; the same result on any machine);
// --time-budget: a cap in seconds on top of it (none by default).
// --threads: candidate fits in parallel (default: every hardware thread); the result does not
// depend on it.
// --no-freeform: no free-form displacements of the cage as the last stage (search/freeform.h).
// --blender-axes: `import` (default) places the rebuilt Blender object on the input as Blender's
// default importer for its format imports it (io/blender_import_frame.h); `raw` keeps the file's
// axes as Blender's.
// --loss: a robust loss (scale 0.02 of the target's unit box) against outliers in the target.
// Bad input: one line on stderr naming the problem, exit code 2, and nothing written.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>

#include <unistd.h>

#include <glog/logging.h>

#include "apps/output_folder.h"
#include "apps/report_html.h"
#include "apps/search_progress_printer.h"
#include "core/parallel_for.h"
#include "core/metrics.h"
#include "core/obj_io.h"
#include "core/printable.h"
#include "io/blender_import_frame.h"
#include "io/sequence_outputs.h"
#include "solver/fitter.h"
#include "search/zero_shot.h"

namespace {

constexpr const char* kUsage =
    "usage: fit_sequence --input TARGET --out DIR [--init SEQ.json] [--work-budget N] [--time-budget S] [--max-ops N] [--seed N] "
    "[--optimizer ceres|adam] [--fit-gates] [--loss none|huber|cauchy] [--samples N] [--threads N] [--no-freeform] [--blender-axes import|raw] [--quiet]";

// A whole-string non-negative integer in [lower, upper], else false.
bool ParseInteger(const std::string& text, long long lower, long long upper, long long* value) {
  if (text.empty() || text.size() > 18 || text.find_first_not_of("0123456789") != std::string::npos) return false;
  *value = std::stoll(text);
  return *value >= lower && *value <= upper;
}

opgraph::Json Number(double x) { return std::isfinite(x) ? opgraph::Json(x) : opgraph::Json(nullptr); }

// How well the work budget's unit tracked this run's fit times (docs/zero-shot.md).
opgraph::Json WorkPerTime(const std::vector<opgraph::FitCost>& costs) {
  const opgraph::FitCostSummary summary = opgraph::SummariseFitCosts(costs);
  return {{"fits", summary.fits},
          {"microseconds_per_unit", summary.microseconds_per_unit},
          {"fit_ratio_p10", summary.ratio_p10},
          {"fit_ratio_p90", summary.ratio_p90}};
}

}  // namespace

int main(int argc, char** argv) {
  using namespace opgraph;
  // Ceres warns (with a dump of the residual block) when a trial step's Jacobian is not finite,
  // as at a Boolean's degenerate placement; the solver rejects that step by itself, and the
  // dump is noise on a user's terminal. Errors still show.
  FLAGS_minloglevel = google::GLOG_ERROR;
  std::string input_path, init_path, out_dir;
  FitterOptions options;
  TargetOptions target_options;
  ZeroShotOptions zero_shot_options;
  zero_shot_options.num_threads = HardwareThreads();
  bool quiet = false;
  bool blender_axes_import = true;
  auto fail = [](const std::string& message) {
    std::cerr << "fit_sequence: " << message << "\n";
    return 2;
  };
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    long long number = 0;
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage << "\n";
      return 0;
    } else if (arg == "--input" && has_value) {
      input_path = argv[++i];
    } else if (arg == "--init" && has_value) {
      init_path = argv[++i];
    } else if (arg == "--out" && has_value) {
      out_dir = argv[++i];
    } else if (arg == "--seed" && has_value) {
      if (!ParseInteger(argv[++i], 0, 1LL << 53, &number)) return fail("--seed: expected an integer >= 0");
      options.seed = target_options.seed = static_cast<uint64_t>(number);
    } else if (arg == "--optimizer" && has_value) {
      const std::string name = argv[++i];
      if (name == "ceres") {
        options.optimizer = Optimizer::kCeres;
      } else if (name == "adam") {
        options.optimizer = Optimizer::kAdam;
      } else {
        return fail("--optimizer: expected 'ceres' or 'adam'");
      }
    } else if (arg == "--loss" && has_value) {
      const std::string name = argv[++i];
      if (name == "none") {
        options.loss = RobustLoss::kNone;
      } else if (name == "huber") {
        options.loss = RobustLoss::kHuber;
      } else if (name == "cauchy") {
        options.loss = RobustLoss::kCauchy;
      } else {
        return fail("--loss: expected 'none', 'huber' or 'cauchy'");
      }
    } else if (arg == "--fit-gates") {
      options.fit_gates = true;
    } else if (arg == "--samples" && has_value) {
      if (!ParseInteger(argv[++i], 100, 1000000, &number)) return fail("--samples: expected an integer in [100, 1000000]");
      options.num_output_samples = options.num_target_samples = static_cast<int>(number);
      target_options.num_samples = static_cast<int>(std::max<long long>(number, 10000));
    } else if (arg == "--threads" && has_value) {
      if (!ParseInteger(argv[++i], 1, 256, &number)) return fail("--threads: expected an integer in [1, 256]");
      zero_shot_options.num_threads = static_cast<int>(number);
    } else if (arg == "--work-budget" && has_value) {
      if (!ParseInteger(argv[++i], 100, 1000000000, &number)) {
        return fail("--work-budget: expected work units in [100, 1000000000]");
      }
      zero_shot_options.work_budget = number;
    } else if (arg == "--time-budget" && has_value) {
      if (!ParseInteger(argv[++i], 1, 86400, &number)) return fail("--time-budget: expected seconds in [1, 86400]");
      zero_shot_options.time_budget_seconds = static_cast<double>(number);
    } else if (arg == "--max-ops" && has_value) {
      if (!ParseInteger(argv[++i], 3, 1000, &number)) return fail("--max-ops: expected an integer in [3, 1000]");
      zero_shot_options.max_ops = static_cast<int>(number);
    } else if (arg == "--blender-axes" && has_value) {
      const std::string axes = argv[++i];
      if (axes != "import" && axes != "raw") return fail("--blender-axes: expected 'import' or 'raw'");
      blender_axes_import = axes == "import";
    } else if (arg == "--no-freeform") {
      zero_shot_options.freeform = false;
    } else if (arg == "--quiet") {
      quiet = true;
    } else {
      return fail("unexpected argument '" + arg.substr(0, 80) + "'; " + kUsage);
    }
  }
  if (input_path.empty() || out_dir.empty()) return fail(kUsage);
  if (const std::string problem = CheckOutputFolder(out_dir); !problem.empty()) return fail(problem);
  // A terminal gets a progress bar under the decision lines; a pipe or file gets plain lines.
  SearchProgressPrinter printer(&std::cout, isatty(STDOUT_FILENO) == 1);
  if (!quiet) {
    options.progress = &std::cout;
    if (isatty(STDOUT_FILENO) != 1) zero_shot_options.progress = &std::cout;
    zero_shot_options.on_progress = [&printer](const SearchProgress& progress) { return printer(progress); };
  }
  zero_shot_options.seed = options.seed;
  zero_shot_options.optimizer = options.optimizer;
  const bool zero_shot = init_path.empty();

  // Everything is computed before anything is written.
  std::unique_ptr<Target> target;
  Sequence sequence;
  FitSummary summary;
  ZeroShotResult recovered;
  SequenceOutputs outputs;
  try {
    target = LoadTarget(input_path, target_options);
    if (zero_shot) {
      recovered = RecoverSequence(*target, zero_shot_options);
      printer.Close();
      sequence = ParseSequence(recovered.sequence);
      summary.final_loss = recovered.loss;
      summary.seconds = recovered.seconds;
    } else {
      sequence = LoadSequence(init_path);
      Fitter fitter(*target, &sequence, options);
      summary = fitter.Fit();
    }
  } catch (const std::exception& e) {
    printer.Close();
    return fail(e.what());
  }
  BlenderScriptOptions blender;
  try {
    // The file's name in letters, digits and a few marks (a name that is not UTF-8 could not be
    // written to sequence.json).
    sequence.name = blender.name = BlenderObjectName(std::filesystem::path(input_path).stem().string());
    if (blender_axes_import) blender.blender_from_sequence = BlenderImportFrame(input_path);
    outputs = RenderSequenceOutputs(&sequence, blender);
  } catch (const std::exception& e) {
    std::cerr << "fit_sequence: the fitted sequence does not re-evaluate: " << e.what() << "\n";
    return 1;
  }

  MetricsOptions metrics_options;
  metrics_options.seed = options.seed;
  const ShapeMetrics shape = ComputeShapeMetrics(outputs.result, target->shape(), metrics_options);
  const WiringMetrics wiring = ComputeWiringMetrics(outputs.result);
  Json metrics = {
      {"target", Printable(input_path, 4096)},  // JSON needs UTF-8: odd bytes show as ?
      {"optimizer", options.optimizer == Optimizer::kCeres ? "ceres" : "adam"},
      {"seed", options.seed},
      {"frame", {{"outputs", "the input's frame and units"},
                 {"metrics", "the target's unit box: (p - centre) * scale"},
                 {"centre", {target->centre().x(), target->centre().y(), target->centre().z()}},
                 {"scale", target->scale()}}},
      {"fit", {{"initial_loss", Number(summary.initial_loss)},
               {"final_loss", Number(summary.final_loss)},
               {"correspondence_updates", summary.outer_iterations},
               {"inner_iterations", summary.inner_iterations},
               {"jacobian_evaluations", summary.jacobian_evaluations},
               {"seconds", summary.seconds},
               {"pruned_ops", summary.pruned_ops}}},
      {"shape", {{"chamfer", {{"output_to_target", shape.chamfer.output_to_target},
                              {"target_to_output", shape.chamfer.target_to_output},
                              {"sum", shape.chamfer.Sum()}}},
                 {"chamfer_squared", {{"output_to_target", shape.chamfer_squared.output_to_target},
                                      {"target_to_output", shape.chamfer_squared.target_to_output},
                                      {"sum", shape.chamfer_squared.Sum()}}},
                 {"sample_chamfer", shape.sample_chamfer},
                 {"normal_consistency", Number(shape.normal_consistency)},
                 {"f1_0.01", shape.f1_001},
                 {"f1_0.02", shape.f1_002},
                 {"num_samples", metrics_options.num_samples}}},
      {"wiring", {{"valence4_fraction", wiring.valence4_fraction},
                  {"quad_fraction", wiring.quad_fraction},
                  {"face_area_cv", wiring.face_area_cv},
                  {"vertices", outputs.result.NumVertices()},
                  {"faces", outputs.result.NumFaces()}}}};
  if (options.fit_gates) metrics["fit"]["gates_before_finalisation"] = summary.gates_before_finalisation;
  metrics["mode"] = zero_shot ? "zero-shot" : "fit-parameters";
  metrics["ops"] = static_cast<int>(sequence.ops.size());
  if (zero_shot) {
    metrics["fit"] = {{"final_loss", Number(recovered.loss)},
                      {"fits", recovered.num_fits},
                      {"work_per_time", WorkPerTime(recovered.fit_costs)},
                      {"work", recovered.work},
                      {"work_budget", zero_shot_options.work_budget},
                      {"seconds", recovered.seconds},
                      {"time_budget_seconds", Number(zero_shot_options.time_budget_seconds > 0
                                                         ? zero_shot_options.time_budget_seconds
                                                         : std::numeric_limits<double>::quiet_NaN())},
                      {"threads", zero_shot_options.num_threads},
                      {"ended_by", SearchEndName(recovered.end)},
                      {"search_complete", recovered.search_complete},
                      {"freeform", recovered.freeform}};
  }
  std::string log;
  for (const std::string& line : recovered.decisions) log += line + "\n";
  // Two independent sample sets of the target itself: Chamfer below this is within sampling noise.
  if (!target->is_cloud()) metrics["shape"]["sampling_noise_floor"] = SamplingNoiseFloor(target->shape(), metrics_options);

  try {
    StagedOutputFolder folder(out_dir);
    WriteSequenceOutputs(outputs, folder.staging_dir(), /*write_steps=*/true,
                         "opgraph fit_sequence result (the input's frame and units)");
    WriteFileAtomic(folder.staging_dir() + "/metrics.json", metrics.dump(1) + "\n");
    WriteFileAtomic(folder.staging_dir() + "/log.txt", log);
    const ReportInput report{sequence.name, outputs.steps, StepFileStems(outputs.step_names),
                             SequenceToJson(sequence)["operations"], outputs.result, target->points(), metrics,
                             blender.blender_from_sequence};
    WriteFileAtomic(folder.staging_dir() + "/report.html", ReportHtml(report));
    folder.Commit();
  } catch (const std::exception& e) {
    std::cerr << "fit_sequence: " << e.what() << "\n";
    return 1;
  }
  std::cout << "fit_sequence: " << sequence.ops.size() << " ops, loss " << summary.final_loss << ", Chamfer "
            << shape.chamfer.Sum() << " (unit box), " << summary.seconds << " s -> " << out_dir << "\n";
  return 0;
}
