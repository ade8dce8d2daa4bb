#include "benchmarks/synth/synth_index.h"

#include <cstdio>
#include <iomanip>
#include <set>
#include <sstream>

#include "benchmarks/splits.h"
#include "benchmarks/synth/synth_checks.h"
#include "ops/op.h"
#include "ops/sequence_op_names.h"

namespace opgraph {
namespace synth {
namespace {

std::string Percent(int count, size_t total) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << 100.0 * count / std::max<size_t>(total, 1) << "%";
  return s.str();
}

void Histogram(std::ostringstream& md, const std::string& title, const std::map<std::string, int>& counts, size_t total) {
  md << "| " << title << " | models | share |\n|---|---|---|\n";
  for (const auto& [key, count] : counts) md << "| " << key << " | " << count << " | " << Percent(count, total) << " |\n";
  md << "\n";
}

}  // namespace

std::string ModelName(int index) {
  char name[32];
  std::snprintf(name, sizeof(name), "synth_%03d", index);
  return name;
}

IndexEntry MakeIndexEntry(const std::string& name, int index, const SynthModel& model) {
  IndexEntry entry;
  entry.name = name;
  entry.index = index;
  entry.recipe = model.recipe;
  entry.ops = SequenceOpNames(model.sequence);
  entry.vertices = model.mesh.NumVertices();
  entry.faces = model.mesh.NumFaces();
  entry.genus = Genus(model.mesh);
  entry.parts = NumParts(model.mesh);
  entry.attempts = model.attempts;
  entry.held_out = SynthHeldOut(index);
  entry.rejections = model.rejections;
  return entry;
}

Json IndexJson(const std::vector<IndexEntry>& entries) {
  Json models = Json::array();
  for (const IndexEntry& e : entries) {
    models.push_back({{"name", e.name}, {"index", e.index}, {"split", e.held_out ? "heldout" : "tune"},
                      {"recipe", e.recipe}, {"ops", e.ops}, {"n_ops", e.ops.size()}, {"verts", e.vertices},
                      {"faces", e.faces}, {"genus", e.genus}, {"parts", e.parts}});
    if (e.blender_distance != -1) {
      models.back()["blender_replaced"] = e.replaced;
      models.back()["blender_distance"] = e.blender_distance;
      models.back()["blender_counts_equal"] = e.blender_counts_equal;
    }
  }
  return {{"models", models}};
}

std::string IndexMarkdown(const std::vector<IndexEntry>& entries, uint64_t seed, double seconds, int threads) {
  std::map<std::string, int> per_op, lengths, recipes, genus, rejections, splits;
  for (const std::string& op : OpNames()) per_op[op] = 0;
  int attempts = 0;
  for (const IndexEntry& e : entries) {
    for (const std::string& op : std::set<std::string>(e.ops.begin(), e.ops.end())) ++per_op[op];
    char length[8];
    std::snprintf(length, sizeof(length), "%02zu", e.ops.size());
    ++lengths[length], ++recipes[e.recipe], ++genus[std::to_string(e.genus)];
    ++splits[e.held_out ? "heldout" : "tune"];
    for (const auto& [why, count] : e.rejections) rejections[why] += count;
    attempts += e.attempts;
  }
  int verified = 0, rebuilt = 0;
  for (const IndexEntry& e : entries) {
    verified += e.blender_distance != -1;
    rebuilt += e.blender_distance >= 0 && e.blender_distance < 1e-6 && e.blender_counts_equal;
  }
  std::ostringstream md;
  md << "# Synthetic corpus index (seed " << seed << ", " << entries.size() << " models)\n\n"
     << "Made by `build/make_synth --out out/synth --seed " << seed << " --count " << entries.size()
     << (verified > 0 ? " --verify_blender" : "") << "` in "
     << std::fixed << std::setprecision(0) << seconds << " s on " << threads << " threads; "
     << attempts << " samples drawn, " << attempts - static_cast<int>(entries.size()) << " rejected by the checks.\n\n";
  if (verified > 0) {
    int replaced = 0;
    std::ostringstream which;
    for (const IndexEntry& e : entries) {
      for (double d : e.replaced) which << (replaced++ ? ", " : "") << e.name << " (" << d << ")";
    }
    md << "Real Blender (`--verify_blender`) rebuilt " << rebuilt << " of " << verified
       << " models from their `rebuild_blender.py` within 1e-6 of the diagonal with equal counts, after replacing "
       << replaced << " sample(s) it did not rebuild (engine parity gaps; distance of the diagonal, -2: Blender "
       << "failed): " << (replaced ? which.str() : "none") << ".\n\n";
  }
  Histogram(md, "op (models using it)", per_op, entries.size());
  Histogram(md, "sequence length", lengths, entries.size());
  Histogram(md, "recipe", recipes, entries.size());
  Histogram(md, "genus (summed over parts)", genus, entries.size());
  Histogram(md, "split", splits, entries.size());
  md << "Rejected samples by reason:\n\n| reason | samples |\n|---|---|\n";
  for (const auto& [why, count] : rejections) md << "| " << why << " | " << count << " |\n";
  md << "\n## Models\n\n| model | split | recipe | ops | verts | faces | genus | parts | Blender | sequence |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const IndexEntry& e : entries) {
    md << "| " << e.name << " | " << (e.held_out ? "heldout" : "tune") << " | " << e.recipe << " | " << e.ops.size()
       << " | " << e.vertices << " | " << e.faces << " | " << e.genus << " | " << e.parts << " | ";
    if (e.blender_distance == -1) md << "– | ";
    else if (e.blender_distance < 0) md << "failed | ";
    else md << std::scientific << std::setprecision(1) << e.blender_distance << std::defaultfloat << (e.blender_counts_equal ? "" : " counts differ") << " | ";
    for (size_t i = 0; i < e.ops.size(); ++i) md << (i ? " " : "") << e.ops[i];
    md << " |\n";
  }
  return md.str();
}

}  // namespace synth
}  // namespace opgraph
