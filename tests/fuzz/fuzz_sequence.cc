// libFuzzer harness of a sequence file as apply_sequence takes it: LoadSequence, the op-count
// check, then RenderSequenceOutputs (EvaluateSequence on every op, the steps as Blender shows
// them, rebuild_blender.py). Findings as in fuzz_read_input.cc.
#include <cstdint>
#include <exception>
#include <string>

#include "io/sequence_outputs.h"
#include "ops/sequence.h"
#include "tests/fuzz/fuzz_input_file.h"

namespace {

// Small enough that a run stays fast (every step below this is evaluated), large enough for
// every op of the seed sequences (tests/data/parity).
constexpr int64_t kFuzzMaxFaces = 50000;
constexpr size_t kFuzzMaxOps = 64;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = opgraph::WriteFuzzInput(data, size, ".json");
  try {
    opgraph::Sequence sequence = opgraph::LoadSequence(path);
    if (sequence.ops.size() > kFuzzMaxOps) return 0;  // apply_sequence's --max-ops refuses it
    sequence.max_faces = kFuzzMaxFaces;
    const opgraph::SequenceOutputs outputs = opgraph::RenderSequenceOutputs(&sequence);
    for (const opgraph::Mesh& step : outputs.steps) opgraph::AbortIfInvalid(step, "a step of an accepted sequence");
  } catch (const std::exception& error) {
    opgraph::AbortUnlessBadInput(error, "the sequence");
  }
  return 0;
}
