// apply_sequence SEQ.json --out DIR [--max-ops N]
// Evaluates a design sequence and writes DIR/result.obj, DIR/steps/NN_<op>.obj and
// DIR/rebuild_blender.py, replacing an earlier run's DIR whole (apps/output_folder.h). Bad input
// (an --out that is a file or a folder of other files among it): one line on stderr naming the
// problem, exit code 2, and nothing written.
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>

#include "apps/output_folder.h"
#include "io/sequence_outputs.h"

namespace {

constexpr const char* kUsage = "usage: apply_sequence SEQ.json --out DIR [--max-ops N]";

// One step file is written per op: a sequence longer than this is refused (--max-ops).
constexpr long long kDefaultMaxOps = 1000;

}  // namespace

int main(int argc, char** argv) {
  using namespace opgraph;
  std::string sequence_path, out_dir;
  long long max_ops = kDefaultMaxOps;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out" && i + 1 < argc) {
      out_dir = argv[++i];
    } else if (arg == "--max-ops" && i + 1 < argc) {
      const std::string value = argv[++i];
      if (value.empty() || value.size() > 7 || value.find_first_not_of("0123456789") != std::string::npos ||
          std::stoll(value) < 1) {
        std::cerr << "apply_sequence: --max-ops: expected an integer in [1, 9999999]\n";
        return 2;
      }
      max_ops = std::stoll(value);
    } else if (arg == "-h" || arg == "--help") {
      std::cout << kUsage << "\n";
      return 0;
    } else if (sequence_path.empty() && arg.rfind("--", 0) != 0) {
      sequence_path = arg;
    } else {
      std::cerr << "apply_sequence: unexpected argument '" << arg << "'; " << kUsage << "\n";
      return 2;
    }
  }
  if (sequence_path.empty() || out_dir.empty()) {
    std::cerr << "apply_sequence: " << kUsage << "\n";
    return 2;
  }
  if (const std::string problem = CheckOutputFolder(out_dir); !problem.empty()) {
    std::cerr << "apply_sequence: " << problem << "\n";
    return 2;
  }

  // Everything is computed before anything is written, so a bad sequence leaves no files.
  SequenceOutputs outputs;
  try {
    Sequence sequence = LoadSequence(sequence_path);
    if (static_cast<long long>(sequence.ops.size()) > max_ops) {
      throw std::runtime_error(sequence_path + ": " + std::to_string(sequence.ops.size()) + " operations, above --max-ops " +
                               std::to_string(max_ops));
    }
    BlenderScriptOptions blender;
    blender.name = BlenderObjectName(sequence.name.empty() ? std::filesystem::path(sequence_path).stem().string()
                                                           : sequence.name);
    outputs = RenderSequenceOutputs(&sequence, blender);
  } catch (const std::exception& e) {
    std::cerr << "apply_sequence: " << e.what() << "\n";
    return 2;
  }

  try {
    StagedOutputFolder folder(out_dir);
    WriteSequenceOutputs(outputs, folder.staging_dir(), /*write_steps=*/true,
                         "opgraph apply_sequence result (Blender frame, +Z up)");
    folder.Commit();
  } catch (const std::exception& e) {
    std::cerr << "apply_sequence: " << e.what() << "\n";
    return 1;
  }
  std::cout << "apply_sequence: " << outputs.steps.size() << " operations -> " << out_dir << "/result.obj ("
            << outputs.result.NumVertices() << " vertices, " << outputs.result.NumFaces() << " faces)\n";
  return 0;
}
