#include "apps/fit_sequence_options.h"

#include <gflags/gflags.h>

#include <algorithm>
#include <cstdlib>
#include <utility>

#include "apps/cli_flags.h"
#include "core/parallel_for.h"

namespace opgraph {
namespace {

// The names the flags take, each beside its value.
constexpr std::pair<const char*, Optimizer> kOptimizers[] = {
    {"lm", Optimizer::kLm}, {"ceres", Optimizer::kCeres}, {"adam", Optimizer::kAdam}};
constexpr std::pair<const char*, RobustLoss> kLosses[] = {
    {"none", RobustLoss::kNone}, {"huber", RobustLoss::kHuber}, {"cauchy", RobustLoss::kCauchy}};

template <typename Value, size_t N>
const char* NameOf(const std::pair<const char*, Value> (&names)[N], Value value) {
  for (const auto& [name, named] : names) {
    if (named == value) return name;
  }
  return "";
}

// False when `name` is none of `names`.
template <typename Value, size_t N>
bool ValueOf(const std::pair<const char*, Value> (&names)[N], const std::string& name, Value* value) {
  for (const auto& [known, named] : names) {
    if (name != known) continue;
    *value = named;
    return true;
  }
  return false;
}

// Seeds go into JSON as numbers: beyond 2^53 a double would change them.
constexpr uint64_t kMaxSeed = uint64_t{1} << 53;

constexpr const char* kUsage = "usage: fit_sequence --input TARGET --out DIR [--init SEQ.json] [flags]";

}  // namespace

const char* OptimizerName(Optimizer optimizer) { return NameOf(kOptimizers, optimizer); }

}  // namespace opgraph

// The defaults are the options structs' own, so each is stated once.
DEFINE_string(input, "",
              "the target (required): a mesh (OBJ, PLY, STL, OFF, glTF/GLB, any format Assimp reads) or a point "
              "cloud (PLY without faces, PCD, XYZ), in any units and frame; the outputs are in its frame and units");
DEFINE_string(out, "",
              "the output folder (required), written whole or not at all; it replaces an earlier run's folder, and "
              "a folder holding anything else is refused");
DEFINE_string(init, "",
              "a sequence skeleton SEQ.json: instead of recovering a sequence, fit its continuous parameters (its ops "
              "and discrete choices fixed, its parameters the start)");
DEFINE_int64(work_budget, opgraph::ZeroShotOptions().work_budget,
             "the search's budget in work units, in [100, 1000000000]: Jacobian evaluations weighted by the "
             "program's size (search/zero_shot.h), so a seed gives the same result on any machine; the default is "
             "about a minute on 2 cores");
DEFINE_int32(time_budget, 0,
             "a cap on the search in seconds, in [1, 86400], on top of the work budget (0: none); metrics.json says "
             "which of the two ended the search");
DEFINE_int32(beam_width, opgraph::ZeroShotOptions().beam_width,
             "main forms (the first decision) the search continues from, the best result kept; 1 is greedy; in [1, 16]");
DEFINE_double(op_price, opgraph::ZeroShotOptions().min_relative_gain,
              "the fraction of the loss each op the search adds must remove, in [0, 0.9]: higher gives shorter "
              "sequences, lower closer fits");
DEFINE_int32(max_ops, opgraph::ZeroShotOptions().max_ops, "the most operations the recovered sequence has, in [3, 1000]");
DEFINE_int64(max_faces, opgraph::ZeroShotOptions().max_faces, opgraph::MaxFacesHelp());
DEFINE_uint64(seed, opgraph::FitterOptions().seed, "the seed of the samples and of the search's random choices, in [0, 2^53]");
DEFINE_int32(threads, opgraph::HardwareThreads(),
             "candidate fits run in parallel, in [1, 256] (default: every hardware thread); the result does not "
             "depend on it");
DEFINE_string(optimizer, opgraph::OptimizerName(opgraph::FitterOptions().optimizer),
              "the fits' optimizer: lm (Levenberg-Marquardt on dense normal equations), ceres (Ceres' Levenberg-Marquardt, dense QR) or adam");
DEFINE_string(loss, opgraph::NameOf(opgraph::kLosses, opgraph::FitterOptions().loss),
              "with --init: a robust loss against outliers in the target, none, huber or cauchy (scale 0.02 of the "
              "target's unit box)");
DEFINE_bool(fit_gates, false, "with --init: also fit each op's gate, and prune the ops whose gate falls below 0.5");
DEFINE_int32(samples, opgraph::FitterOptions().num_target_samples,
             "with --init: surface samples per correspondence update in each direction, in [100, 1000000]; a mesh "
             "target is sampled at least this densely");
DEFINE_bool(freeform, opgraph::ZeroShotOptions().freeform,
            "free-form displacements of the cage as the search's last stage (search/freeform.h); --no-freeform "
            "turns them off");
DEFINE_string(blender_axes, "import",
              "where rebuild_blender.py places the object: import (on the input as Blender's default importer for "
              "its format imports it; io/blender_import_frame.h) or raw (the file's axes as Blender's)");
DEFINE_bool(quiet, false, "no progress on stdout");

namespace opgraph {

std::string FitSequenceOptions::Check() const {
  if (input_path.empty() || out_dir.empty()) return std::string(kUsage) + " (--input and --out are required)";
  if (fitter.seed > kMaxSeed) return "--seed: expected an integer in [0, 2^53]";
  if (fitter.num_target_samples < 100 || fitter.num_target_samples > 1000000) {
    return "--samples: expected an integer in [100, 1000000]";
  }
  if (zero_shot.num_threads < 1 || zero_shot.num_threads > 256) return "--threads: expected an integer in [1, 256]";
  if (zero_shot.work_budget < 100 || zero_shot.work_budget > 1000000000) {
    return "--work-budget: expected work units in [100, 1000000000]";
  }
  const double seconds = zero_shot.time_budget_seconds;
  if (seconds != 0 && (seconds < 1 || seconds > 86400)) return "--time-budget: expected seconds in [1, 86400] (or 0: none)";
  if (zero_shot.max_ops < 3 || zero_shot.max_ops > 1000) return "--max-ops: expected an integer in [3, 1000]";
  if (zero_shot.beam_width < 1 || zero_shot.beam_width > 16) return "--beam-width: expected an integer in [1, 16]";
  if (!(zero_shot.min_relative_gain >= 0 && zero_shot.min_relative_gain <= 0.9)) {
    return "--op-price: expected a fraction in [0, 0.9]";
  }
  if (const std::string problem = CheckMaxFaces(zero_shot.max_faces); !problem.empty()) return problem;
  return "";
}

FitSequenceOptions FitSequenceOptionsFromCommandLine(int argc, char** argv) {
  ParseCommandLineOrExit(argc, argv, {"fit_sequence", kUsage, __FILE__, /*max_arguments=*/0});
  FitSequenceOptions options;
  options.input_path = FLAGS_input;
  options.init_path = FLAGS_init;
  options.out_dir = FLAGS_out;
  options.fitter.seed = options.target.seed = options.zero_shot.seed = FLAGS_seed;
  if (!ValueOf(kOptimizers, FLAGS_optimizer, &options.fitter.optimizer)) {
    std::exit(BadInput("fit_sequence", "--optimizer: expected 'lm', 'ceres' or 'adam'"));
  }
  options.zero_shot.optimizer = options.fitter.optimizer;
  if (!ValueOf(kLosses, FLAGS_loss, &options.fitter.loss)) {
    std::exit(BadInput("fit_sequence", "--loss: expected 'none', 'huber' or 'cauchy'"));
  }
  if (FLAGS_blender_axes != "import" && FLAGS_blender_axes != "raw") {
    std::exit(BadInput("fit_sequence", "--blender-axes: expected 'import' or 'raw'"));
  }
  options.blender_axes_import = FLAGS_blender_axes == "import";
  options.fitter.fit_gates = FLAGS_fit_gates;
  // Given, --samples sets both directions and raises the target's samples to it; otherwise each
  // keeps its own default.
  if (!gflags::GetCommandLineFlagInfoOrDie("samples").is_default) {
    options.fitter.num_output_samples = options.fitter.num_target_samples = FLAGS_samples;
    options.target.num_samples = std::max(FLAGS_samples, options.target.num_samples);
  }
  options.zero_shot.num_threads = FLAGS_threads;
  options.zero_shot.work_budget = FLAGS_work_budget;
  options.zero_shot.time_budget_seconds = FLAGS_time_budget;
  options.zero_shot.max_ops = FLAGS_max_ops;
  options.zero_shot.beam_width = FLAGS_beam_width;
  options.zero_shot.min_relative_gain = FLAGS_op_price;
  options.zero_shot.max_faces = FLAGS_max_faces;
  options.zero_shot.freeform = FLAGS_freeform;
  options.quiet = FLAGS_quiet;
  if (const std::string problem = options.Check(); !problem.empty()) std::exit(BadInput("fit_sequence", problem));
  return options;
}

}  // namespace opgraph
