// The evaluation sets of the corpus protocol (docs/corpus.md) and the models in each.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace opgraph {

struct ResultsModel {
  std::string set, name;
  std::filesystem::path input;  // the mesh given to fit_sequence
  std::filesystem::path truth;  // its ground-truth sequence (empty for real meshes)
};

// gt-dev, synth-tune, synth-heldout, real-dev, real-tune, real-heldout, in that order.
const std::vector<std::string>& ResultsSetNames();
bool IsHeldOutSet(const std::string& set);

// The models of `set` ("all": every set), sorted by name within a set. `data` is
// ../shared/data, `synth` the generated corpus (build/make_synth). Throws std::runtime_error
// naming the missing folder or index.
std::vector<ResultsModel> ListModels(const std::string& set, const std::filesystem::path& data,
                                     const std::filesystem::path& synth);

}  // namespace opgraph
