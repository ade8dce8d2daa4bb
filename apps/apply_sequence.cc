// apply_sequence SEQ.json --out DIR [--max-ops N] [--max-faces N]; `apply_sequence --help` lists
// the flags. Evaluates a design sequence and writes DIR/result.obj, DIR/steps/NN_<op>.obj and
// DIR/rebuild_blender.py, replacing an earlier run's DIR whole (apps/output_folder.h). Bad input
// (a bad command line or sequence, a sequence that grows beyond --max-faces, an --out that is a
// file or a folder of other files among it): one line on stderr naming the problem, exit code
// 2, and nothing written. A failure of the tool itself (out of memory, a write error): exit 1.
#include <gflags/gflags.h>

#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>

#include "apps/cli_flags.h"
#include "apps/output_folder.h"
#include "apps/tool_errors.h"
#include "io/sequence_outputs.h"

DEFINE_string(out, "", "the output folder (required), written whole or not at all; it replaces an earlier run's folder");
DEFINE_int64(max_ops, 1000,
             "the longest sequence taken, in [1, 9999999]: one step file is written per operation, and a longer "
             "sequence is refused");
DEFINE_int64(max_faces, opgraph::kDefaultMaxFaces, opgraph::MaxFacesHelp());

namespace {

int Run(int argc, char** argv) {
  using namespace opgraph;
  constexpr const char* kUsage = "usage: apply_sequence SEQ.json --out DIR [--max-ops N] [--max-faces N]";
  const std::vector<std::string> arguments =
      ParseCommandLineOrExit(argc, argv, {"apply_sequence", kUsage, __FILE__, /*max_arguments=*/1});
  if (arguments.empty() || FLAGS_out.empty()) return BadInput("apply_sequence", std::string(kUsage) + " (see --help)");
  if (FLAGS_max_ops < 1 || FLAGS_max_ops > 9999999) {
    return BadInput("apply_sequence", "--max-ops: expected an integer in [1, 9999999]");
  }
  if (const std::string problem = CheckMaxFaces(FLAGS_max_faces); !problem.empty()) {
    return BadInput("apply_sequence", problem);
  }
  const std::string& sequence_path = arguments[0];
  const std::string& out_dir = FLAGS_out;
  const long long max_ops = FLAGS_max_ops;
  if (const std::string problem = CheckOutputFolder(out_dir); !problem.empty()) return BadInput("apply_sequence", problem);

  // Everything is computed before anything is written, so a bad sequence leaves no files.
  SequenceOutputs outputs;
  try {
    Sequence sequence = LoadSequence(sequence_path);
    if (static_cast<long long>(sequence.ops.size()) > max_ops) {
      throw std::runtime_error(std::to_string(sequence.ops.size()) + " operations, above --max-ops " +
                               std::to_string(max_ops));
    }
    sequence.max_faces = FLAGS_max_faces;
    BlenderScriptOptions blender;
    blender.name = BlenderObjectName(sequence.name.empty() ? std::filesystem::path(sequence_path).stem().string()
                                                           : sequence.name);
    outputs = RenderSequenceOutputs(&sequence, blender);
  } catch (const std::exception& e) {
    return ReportException("apply_sequence", sequence_path, e);
  }

  try {
    StagedOutputFolder folder(out_dir);
    WriteSequenceOutputs(outputs, folder.staging_dir(), /*write_steps=*/true,
                         "opgraph apply_sequence result (Blender frame, +Z up)");
    folder.Commit();
  } catch (const std::exception& e) {
    return ReportInternalFailure("apply_sequence", out_dir, e);
  }
  std::cout << "apply_sequence: " << outputs.steps.size() << " operations -> " << out_dir << "/result.obj ("
            << outputs.result.NumVertices() << " vertices, " << outputs.result.NumFaces() << " faces)\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return opgraph::RunAtToolEdge("apply_sequence", Run, argc, argv); }
