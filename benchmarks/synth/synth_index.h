// The synthetic corpus' index: one entry per model (ops, counts, genus, split) and the set's
// histograms (models per op, sequence lengths, recipes, genus, rejections), as JSON and as the
// Markdown page docs/corpus.md links to.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "benchmarks/synth/synth_grammar.h"

namespace opgraph {
namespace synth {

struct IndexEntry {
  std::string name, recipe;
  int index = 0;
  std::vector<std::string> ops;
  int vertices = 0, faces = 0, genus = 0, parts = 0, attempts = 0;
  bool held_out = false;
  std::map<std::string, int> rejections;
  double blender_distance = -1;  // of the diagonal; -1: not verified, -2: Blender failed
  bool blender_counts_equal = false;
  std::vector<double> replaced;  // Blender distances of earlier samples of this index it did not rebuild
};

std::string ModelName(int index);  // "synth_007"
IndexEntry MakeIndexEntry(const std::string& name, int index, const SynthModel& model);
Json IndexJson(const std::vector<IndexEntry>& entries);
std::string IndexMarkdown(const std::vector<IndexEntry>& entries, uint64_t seed, double seconds, int threads);

}  // namespace synth
}  // namespace opgraph
