// Writes the synthetic corpus: per model `model.obj` (polygons kept, Blender frame),
// `sequence.json` (our format) and `rebuild_blender.py`, plus `index.json` and `index.md`
// (ops, counts, genus, split, the op and length histograms). The default set is
// `make_synth --out out/synth` (seed 1, 200 models); docs/corpus.md describes it.
#include <gflags/gflags.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <thread>

#include "apps/cli_flags.h"
#include "ops/blender_script.h"
#include "benchmarks/splits.h"
#include "benchmarks/synth/synth_checks.h"
#include "benchmarks/synth/synth_grammar.h"
#include "benchmarks/synth/synth_index.h"
#include "core/obj_io.h"
#include "core/surface_distance.h"
#include "tests/blender_runner.h"
#include "ops/sequence.h"

DEFINE_string(out, "", "output folder (replaced whole when the set is complete)");
DEFINE_uint64(seed, 1, "the set's seed; the default set is seed 1");
DEFINE_int32(count, 200, "number of models (indices 0 .. count-1)");
DEFINE_string(indices, "", "comma-separated model indices to write instead of 0 .. count-1");
DEFINE_bool(verify_blender, false, "rebuild every model in real Blender from its rebuild_blender.py; replace one it does not rebuild within 1e-6 (the default set uses it)");
DEFINE_int32(threads, 0, "worker threads (0: all hardware threads); the output does not depend on it");

namespace fs = std::filesystem;
using namespace opgraph;

namespace {

std::vector<int> Indices() {
  std::vector<int> indices;
  if (FLAGS_indices.empty()) {
    for (int i = 0; i < FLAGS_count; ++i) indices.push_back(i);
    return indices;
  }
  std::stringstream list(FLAGS_indices);
  std::string item;
  while (std::getline(list, item, ',')) indices.push_back(std::stoi(item));
  return indices;
}

void WriteModel(const synth::SynthModel& model, const fs::path& dir) {
  fs::create_directories(dir);
  WriteObj(model.mesh, (dir / "model.obj").string(), "opgraph synthetic model (Blender frame, +Z up)");
  WriteFileAtomic((dir / "sequence.json").string(), model.sequence.dump(1) + "\n");
  const Sequence sequence = ParseSequence(model.sequence);
  WriteFileAtomic((dir / "rebuild_blender.py").string(), BlenderScript(sequence));
}

// Real Blender rebuilds `model` from its script; the distance of its mesh from model.obj (of the
// diagonal; -2 when Blender fails) and whether the counts agree.
std::pair<double, bool> RebuildInBlender(const fs::path& model) {
  std::pair<double, bool> result{-2, false};
  try {
    const Mesh ours = ReadObj((model / "model.obj").string());
    const Mesh blender = RunBlender((model / "rebuild_blender.py").string(), (model / "blender.obj").string());
    result = {SymmetricSurfaceDistanceRelative(ours, blender),
              ours.NumVertices() == blender.NumVertices() && ours.NumFaces() == blender.NumFaces()};
  } catch (const std::exception&) {
  }
  fs::remove(model / "blender.obj");
  fs::remove(model / "blender.obj.log");
  return result;
}

// Each model rebuilt by real Blender; one it does not rebuild within 1e-6 with equal counts
// (an engine parity gap) is replaced by its index's next sample, up to 5 times. The index
// records the replaced samples.
void VerifyInBlender(const fs::path& dir, int threads, std::vector<synth::SynthModel>* models,
                     std::vector<synth::IndexEntry>* entries) {
  std::atomic<size_t> next{0};
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t) {
    workers.emplace_back([&] {
      for (size_t k; (k = next++) < entries->size();) {
        synth::IndexEntry& entry = (*entries)[k];
        for (int redraw = 1;; ++redraw) {
          const auto [distance, counts_equal] = RebuildInBlender(dir / entry.name);
          entry.blender_distance = distance, entry.blender_counts_equal = counts_equal;
          if ((distance >= 0 && distance < 1e-6 && counts_equal) || redraw > 5) break;
          entry.replaced.push_back(distance);
          synth::SynthModel replacement = synth::SampleModel(FLAGS_seed, entry.index, {}, redraw);
          if (!replacement.ok) break;
          (*models)[k] = replacement;
          WriteModel(replacement, dir / entry.name);
          const std::vector<double> replaced = entry.replaced;
          entry = synth::MakeIndexEntry(entry.name, entry.index, replacement);
          entry.replaced = replaced;
        }
      }
    });
  }
  for (std::thread& worker : workers) worker.join();
}

}  // namespace

int main(int argc, char** argv) {
  ParseCommandLineOrExit(argc, argv,
                         {"make_synth", "usage: make_synth --out DIR [--seed N] [--count N | --indices I,J,...]",
                          __FILE__, /*max_arguments=*/0});
  if (FLAGS_out.empty() || FLAGS_count < 1) return BadInput("make_synth", "--out and --count >= 1 are required");
  std::vector<int> indices;
  try {
    indices = Indices();
  } catch (const std::exception&) {
    std::cerr << "make_synth: --indices must be a comma-separated list of integers\n";
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  std::vector<synth::SynthModel> models(indices.size());
  std::atomic<size_t> next{0}, done{0};
  const int threads = FLAGS_threads > 0 ? FLAGS_threads : std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t) {
    workers.emplace_back([&] {
      for (size_t k; (k = next++) < indices.size();) {
        models[k] = synth::SampleModel(FLAGS_seed, indices[k], {});
        const size_t finished = ++done;
        if (finished % 20 == 0 || finished == indices.size()) std::cerr << "[make_synth] " << finished << " / " << indices.size() << "\n";
      }
    });
  }
  for (std::thread& worker : workers) worker.join();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const fs::path out = FLAGS_out, partial = FLAGS_out + ".partial";
  fs::remove_all(partial);
  std::vector<synth::IndexEntry> entries;
  for (size_t k = 0; k < indices.size(); ++k) {
    if (!models[k].ok) {
      std::cerr << "make_synth: model " << indices[k] << ": no valid sample in " << models[k].attempts << " attempts\n";
      return 1;
    }
    const std::string name = synth::ModelName(indices[k]);
    WriteModel(models[k], partial / name);
    entries.push_back(synth::MakeIndexEntry(name, indices[k], models[k]));
  }
  if (FLAGS_verify_blender) VerifyInBlender(partial, threads, &models, &entries);
  WriteFileAtomic((partial / "index.json").string(), synth::IndexJson(entries).dump(1) + "\n");
  WriteFileAtomic((partial / "index.md").string(), synth::IndexMarkdown(entries, FLAGS_seed, seconds, threads));
  fs::remove_all(out);
  fs::rename(partial, out);
  std::cout << "[make_synth] " << entries.size() << " models in " << out << " (" << seconds << " s)\n";
  return 0;
}
