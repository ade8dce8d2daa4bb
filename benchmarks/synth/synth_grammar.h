// The synthetic corpus: designer-like sequences sampled from the cube by a grammar of how
// modellers build (block out, structure, finish), built with the engine and kept only when they
// pass the degeneracy checks (synth_checks.h). Each model is fully determined by the set's seed
// and its index.
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "core/mesh.h"
#include "ops/params.h"

namespace opgraph {
namespace synth {

struct SynthOptions {
  int min_ops = 2;
  int max_ops = 18;
  int max_faces = 20000;
  int max_attempts = 400;  // samples tried per model before giving up
  std::string Check() const;  // empty when valid
};

struct SynthModel {
  bool ok = false;
  std::string recipe;      // the kind of object the grammar aimed at ("turned", "furniture", ...)
  Json sequence;           // the sequence document (our format)
  Mesh mesh;               // what it builds (Blender frame)
  int attempts = 0;        // samples drawn, the accepted one included
  std::map<std::string, int> rejections;  // why the others were rejected
};

// Samples model `index` of the set whose seed is `set_seed`. `redraw` > 0 draws the index's
// next sample instead (make_synth --verify_blender replaces a model Blender does not rebuild).
SynthModel SampleModel(uint64_t set_seed, int index, const SynthOptions& options, int redraw = 0);

// Recipe names, in the grammar's order.
const std::vector<std::string>& RecipeNames();

}  // namespace synth
}  // namespace opgraph
