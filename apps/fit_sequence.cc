// fit_sequence --input TARGET --out DIR [--init SEQ.json] [flags]; `fit_sequence --help` lists
// the flags with their defaults (apps/fit_sequence_options.cc).
// Without --init (the main job): recovers a design sequence for TARGET (a mesh or point cloud,
// any format io/read_input reads) from scratch with the zero-shot controller
// (search/zero_shot.h). With --init: fits every continuous parameter of the sequence skeleton
// SEQ.json (ops and discrete choices fixed; its parameters are the start).
// Writes DIR/sequence.json, DIR/result.obj (in the input's frame and units),
// DIR/steps/NN_<op>.obj, DIR/rebuild_blender.py, DIR/metrics.json and DIR/log.txt (the
// controller's decisions), replacing an earlier run's DIR whole (apps/output_folder.h).
// Progress on stdout: a bar on a terminal, plain lines otherwise.
// Bad input: one line on stderr naming the problem, exit code 2, and nothing written.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <string>

#include <unistd.h>

#include <glog/logging.h>

#include "apps/cli_flags.h"
#include "apps/fit_sequence_options.h"
#include "apps/output_folder.h"
#include "apps/report_html.h"
#include "apps/search_progress_printer.h"
#include "apps/tool_errors.h"
#include "core/metrics.h"
#include "core/obj_io.h"
#include "core/printable.h"
#include "io/blender_import_frame.h"
#include "io/sequence_outputs.h"
#include "solver/fitter.h"
#include "search/zero_shot.h"

namespace {

opgraph::Json Number(double x) { return std::isfinite(x) ? opgraph::Json(x) : opgraph::Json(nullptr); }

// How well the work budget's unit tracked this run's fit times (docs/zero-shot.md).
opgraph::Json WorkPerTime(const std::vector<opgraph::FitCost>& costs) {
  const opgraph::FitCostSummary summary = opgraph::SummariseFitCosts(costs);
  return {{"fits", summary.fits},
          {"microseconds_per_unit", summary.microseconds_per_unit},
          {"fit_ratio_p10", summary.ratio_p10},
          {"fit_ratio_p90", summary.ratio_p90}};
}

int Run(int argc, char** argv) {
  using namespace opgraph;
  const auto started = std::chrono::steady_clock::now();  // --time-budget counts the whole run
  // Ceres warns (with a dump of the residual block) when a trial step's Jacobian is not finite,
  // as at a Boolean's degenerate placement; the solver rejects that step by itself, and the
  // dump is noise on a user's terminal. Errors still show.
  FLAGS_minloglevel = google::GLOG_ERROR;
  FitSequenceOptions run = FitSequenceOptionsFromCommandLine(argc, argv);
  FitterOptions& options = run.fitter;
  ZeroShotOptions& zero_shot_options = run.zero_shot;
  const std::string& input_path = run.input_path;
  const std::string& out_dir = run.out_dir;
  if (const std::string problem = CheckOutputFolder(out_dir); !problem.empty()) return BadInput("fit_sequence", problem);
  // A terminal gets a progress bar under the decision lines; a pipe or file gets plain lines.
  SearchProgressPrinter printer(&std::cout, isatty(STDOUT_FILENO) == 1);
  if (!run.quiet) {
    options.progress = &std::cout;
    if (isatty(STDOUT_FILENO) != 1) zero_shot_options.progress = &std::cout;
    zero_shot_options.on_progress = [&printer](const SearchProgress& progress) { return printer(progress); };
  }
  const bool zero_shot = run.init_path.empty();
  if (zero_shot_options.time_budget_seconds > 0) zero_shot_options.time_budget_start = started;

  // Everything is computed before anything is written.
  std::unique_ptr<Target> target;
  Sequence sequence;
  FitSummary summary;
  ZeroShotResult recovered;
  SequenceOutputs outputs;
  // The file an error names: the target until it is read, then the --init sequence.
  std::string current_file = input_path;
  try {
    target = LoadTarget(input_path, run.target);
    if (zero_shot) {
      recovered = RecoverSequence(*target, zero_shot_options);
      printer.Close();
      sequence = ParseSequence(recovered.sequence);
      summary.final_loss = recovered.loss;
      summary.seconds = recovered.seconds;
    } else {
      current_file = run.init_path;
      sequence = LoadSequence(run.init_path);
      sequence.max_faces = zero_shot_options.max_faces;
      Fitter fitter(*target, &sequence, options);
      summary = fitter.Fit();
    }
  } catch (const std::exception& e) {
    printer.Close();
    return ReportException("fit_sequence", current_file, e);
  }
  sequence.max_faces = zero_shot_options.max_faces;
  BlenderScriptOptions blender;
  try {
    // The file's name in letters, digits and a few marks (a name that is not UTF-8 could not be
    // written to sequence.json).
    sequence.name = blender.name = BlenderObjectName(std::filesystem::path(input_path).stem().string());
    if (run.blender_axes_import) blender.blender_from_sequence = BlenderImportFrame(input_path);
    outputs = RenderSequenceOutputs(&sequence, blender);
  } catch (const std::exception& e) {
    return ReportInternalFailure("fit_sequence", "the fitted sequence does not re-evaluate", e);
  }

  MetricsOptions metrics_options;
  metrics_options.seed = options.seed;
  const ShapeMetrics shape = ComputeTargetMetrics(outputs.result, *target, metrics_options);
  const WiringMetrics wiring = ComputeWiringMetrics(outputs.result);
  Json metrics = {
      {"target", Printable(input_path, 4096)},  // JSON needs UTF-8: odd bytes show as ?
      {"optimizer", OptimizerName(options.optimizer)},
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
                      {"fits_ahead", recovered.num_fits_ahead},
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
    if (zero_shot_options.time_budget_seconds > 0) metrics["fit"]["cut_by_time_budget"] = recovered.cut_by_time;
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
    return ReportInternalFailure("fit_sequence", out_dir, e);
  }
  std::cout << "fit_sequence: " << sequence.ops.size() << " ops, loss " << summary.final_loss << ", Chamfer "
            << shape.chamfer.Sum() << " (unit box), " << summary.seconds << " s -> " << out_dir << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return opgraph::RunAtToolEdge("fit_sequence", Run, argc, argv); }
