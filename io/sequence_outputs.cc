#include "io/sequence_outputs.h"

#include <cstdio>
#include <filesystem>

#include "core/obj_io.h"
#include "io/write_glb.h"

namespace opgraph {

std::string StepFileStem(size_t index, const std::string& op_name) {
  char number[32];
  std::snprintf(number, sizeof(number), "%02zu_", index);
  return number + op_name;
}

std::vector<std::string> StepFileStems(const std::vector<std::string>& op_names) {
  std::vector<std::string> stems;
  for (size_t i = 0; i < op_names.size(); ++i) stems.push_back(StepFileStem(i, op_names[i]));
  return stems;
}

SequenceOutputs RenderSequenceOutputs(Sequence* sequence, const BlenderScriptOptions& blender) {
  SequenceOutputs outputs;
  outputs.steps = EvaluateSequence(sequence);
  for (const auto& op : sequence->ops) outputs.step_names.push_back(op->Name());
  outputs.result = outputs.steps.empty() ? sequence->StartMesh() : outputs.steps.back();
  // A transform that becomes the object's moves every step before it too.
  const std::vector<BlenderStepPlan> plan = PlanBlenderSteps(*sequence);
  for (size_t j = 0; j < plan.size(); ++j) {
    if (!plan[j].object_transform) continue;
    const Op& transform = *sequence->ops[j];
    for (size_t k = 0; k < j; ++k) {
      Positions<double> moved;
      transform.Evaluate(transform.params().data(), 1.0, outputs.steps[k].vertices, &moved);
      outputs.steps[k].vertices = std::move(moved);
    }
  }
  outputs.blender_script = BlenderScript(*sequence, blender);
  outputs.steps_glb = outputs.steps.empty() ? GlbBytes({outputs.result}, {"start"})
                                             : GlbBytes(outputs.steps, StepFileStems(outputs.step_names));
  outputs.sequence_json = SequenceToJson(*sequence).dump(1) + "\n";
  return outputs;
}

void WriteSequenceOutputs(const SequenceOutputs& outputs, const std::string& out_dir, bool write_steps,
                          const std::string& result_comment) {
  std::filesystem::create_directories(out_dir);
  if (write_steps) {
    std::filesystem::create_directories(std::filesystem::path(out_dir) / "steps");
    for (size_t i = 0; i < outputs.steps.size(); ++i) {
      WriteObj(outputs.steps[i], out_dir + "/steps/" + StepFileStem(i, outputs.step_names[i]) + ".obj",
               "opgraph step " + std::to_string(i) + ": " + outputs.step_names[i]);
    }
  }
  WriteObj(outputs.result, out_dir + "/result.obj", result_comment);
  WriteFileAtomic(out_dir + "/result.glb", outputs.steps_glb);
  WriteFileAtomic(out_dir + "/rebuild_blender.py", outputs.blender_script);
  WriteFileAtomic(out_dir + "/sequence.json", outputs.sequence_json);
}

}  // namespace opgraph
