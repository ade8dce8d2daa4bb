#include "benchmarks/results_sets.h"

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include "benchmarks/splits.h"
#include "ops/params.h"

namespace opgraph {
namespace fs = std::filesystem;
namespace {

std::vector<fs::path> Sorted(const fs::path& dir, bool directories) {
  if (!fs::is_directory(dir)) throw std::runtime_error("no folder " + dir.string());
  std::vector<fs::path> paths;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (directories ? entry.is_directory() : entry.path().extension() == ".obj") paths.push_back(entry.path());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

void AddSynth(const std::string& set, const fs::path& synth, std::vector<ResultsModel>* models) {
  std::ifstream in(synth / "index.json");
  if (!in) throw std::runtime_error("no " + (synth / "index.json").string() + " (run build/make_synth --out " + synth.string() + ")");
  const Json index = Json::parse(in);
  const std::string split = set == "synth-heldout" ? "heldout" : "tune";
  for (const Json& model : index.at("models")) {
    if (model.at("split") != split) continue;
    const std::string name = model.at("name");
    models->push_back({set, name, synth / name / "model.obj", synth / name / "sequence.json"});
  }
}

}  // namespace

const std::vector<std::string>& ResultsSetNames() {
  static const std::vector<std::string> kSets = {"gt-dev",   "synth-tune", "synth-heldout",
                                                 "real-dev", "real-tune",  "real-heldout"};
  return kSets;
}

bool IsHeldOutSet(const std::string& set) { return set.find("heldout") != std::string::npos; }

std::vector<ResultsModel> ListModels(const std::string& set, const fs::path& data, const fs::path& synth) {
  std::vector<ResultsModel> models;
  if (set == "all") {
    for (const std::string& each : ResultsSetNames()) {
      const std::vector<ResultsModel> part = ListModels(each, data, synth);
      models.insert(models.end(), part.begin(), part.end());
    }
    return models;
  }
  if (set == "gt-dev") {
    for (const fs::path& dir : Sorted(data / "gt-dev", true)) {
      models.push_back({set, dir.filename().string(), dir / "model.obj", dir / "sequence.json"});
    }
  } else if (set == "synth-tune" || set == "synth-heldout") {
    AddSynth(set, synth, &models);
  } else if (set == "real-dev") {
    for (const fs::path& obj : Sorted(data / "real-dev", false)) models.push_back({set, obj.stem().string(), obj, ""});
  } else if (set == "real-tune" || set == "real-heldout") {
    const std::vector<fs::path> objs = Sorted(data / "real-train", false);
    for (size_t i = 0; i < objs.size(); ++i) {
      if (RealHeldOut(static_cast<int>(i)) == (set == "real-heldout")) models.push_back({set, objs[i].stem().string(), objs[i], ""});
    }
  } else {
    throw std::runtime_error("unknown set '" + set.substr(0, 40) + "'");
  }
  return models;
}

}  // namespace opgraph
