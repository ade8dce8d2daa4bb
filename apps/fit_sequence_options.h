// fit_sequence's command line: its flags (fit_sequence_options.cc; `fit_sequence --help` lists
// them with their defaults and meanings) read into the options of one run.
#pragma once

#include <string>

#include "search/zero_shot.h"
#include "solver/fitter.h"
#include "solver/target.h"

namespace opgraph {

struct FitSequenceOptions {
  std::string input_path;  // --input: the target, a mesh or point cloud (io/read_input.h)
  std::string init_path;   // --init: fit this skeleton's parameters; empty: recover a sequence
  std::string out_dir;     // --out
  FitterOptions fitter;
  TargetOptions target;
  ZeroShotOptions zero_shot;  // its seed and optimizer are the fitter's
  bool quiet = false;
  bool blender_axes_import = true;  // --blender-axes import; false: raw
  // Empty when valid, else the problem in the command line's words ("--threads: ...").
  std::string Check() const;
};

// The options fit_sequence's command line gives. Prints the help or the version and exits 0,
// or prints one line naming the problem and exits 2 (apps/cli_flags.h).
FitSequenceOptions FitSequenceOptionsFromCommandLine(int argc, char** argv);

// "ceres" or "adam", as --optimizer takes it and metrics.json records it.
const char* OptimizerName(Optimizer optimizer);

}  // namespace opgraph
