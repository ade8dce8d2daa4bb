// apply_sequence SEQ.json --out DIR
// Evaluates a design sequence and writes DIR/result.obj, DIR/steps/NN_<op>.obj and
// DIR/rebuild_blender.py. Bad input: one line on stderr naming the problem, exit code 2, and
// nothing written.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include "core/obj_io.h"
#include "ops/sequence.h"

namespace {

constexpr const char* kUsage = "usage: apply_sequence SEQ.json --out DIR";

}  // namespace

int main(int argc, char** argv) {
  using namespace opgraph;
  std::string sequence_path, out_dir;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out" && i + 1 < argc) {
      out_dir = argv[++i];
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

  // Everything is computed before anything is written, so a bad sequence leaves no files.
  std::vector<Mesh> steps;
  std::string script;
  Sequence sequence;
  try {
    sequence = LoadSequence(sequence_path);
    steps = EvaluateSequence(&sequence);
    script = BlenderScript(sequence);
  } catch (const std::exception& e) {
    std::cerr << "apply_sequence: " << e.what() << "\n";
    return 2;
  }

  try {
    std::filesystem::create_directories(std::filesystem::path(out_dir) / "steps");
    const Mesh result = steps.empty() ? sequence.StartMesh() : steps.back();
    for (size_t i = 0; i < steps.size(); ++i) {
      char name[64];
      std::snprintf(name, sizeof(name), "%02zu_", i);
      WriteObj(steps[i], out_dir + "/steps/" + name + sequence.ops[i]->Name() + ".obj",
               "opgraph step " + std::to_string(i) + ": " + sequence.ops[i]->Name());
    }
    WriteObj(result, out_dir + "/result.obj", "opgraph apply_sequence result (Blender frame, +Z up)");
    WriteFileAtomic(out_dir + "/rebuild_blender.py", script);
    WriteFileAtomic(out_dir + "/sequence.json", SequenceToJson(sequence).dump(1) + "\n");
  } catch (const std::exception& e) {
    std::cerr << "apply_sequence: " << e.what() << "\n";
    return 1;
  }
  std::cout << "apply_sequence: " << steps.size() << " operations -> " << out_dir << "/result.obj ("
            << (steps.empty() ? 8 : steps.back().NumVertices()) << " vertices, "
            << (steps.empty() ? 6 : steps.back().NumFaces()) << " faces)\n";
  return 0;
}
