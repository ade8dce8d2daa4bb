#include "benchmarks/synth/synth_grammar.h"

#include "benchmarks/synth/synth_checks.h"
#include "benchmarks/synth/synth_moves.h"
#include "ops/sequence.h"

namespace opgraph {
namespace synth {
namespace {

// Turned and cast forms: columns, vases, vessels, bottles.
void Turned(Draft* d, Random* r) {
  ScaleBlock(d, r, Proportion::kColumn);
  Profile(d, r, 2);
  if (r->Chance(0.5)) Deform(d, r, 2);
  if (r->Chance(0.55)) InsetExtrude(d, r, /*deep_cavity=*/true);
  if (r->Chance(0.25)) BevelFinish(d, r);
  if (r->Chance(0.7)) SubdivisionFinish(d, r);
}

// Hard-surface objects: boxes with bosses, panels, recesses, holes.
void HardSurface(Draft* d, Random* r) {
  ScaleBlock(d, r, Proportion::kAny);
  if (r->Chance(0.35)) Profile(d, r, r->Int(0, 2));
  const int features = r->Int(1, 3);
  for (int k = 0; k < features; ++k) {
    switch (r->Weighted({1, 1, 0.6, 0.6, 0.4, 0.4})) {
      case 0: ExtrudeFace(d, r); break;
      case 1: InsetExtrude(d, r, false); break;
      case 2: Panels(d, r); break;
      case 3: BooleanFeature(d, r, true); break;
      case 4: BooleanFeature(d, r, false); break;
      default: Chain(d, r); break;
    }
  }
  if (r->Chance(0.25)) Deform(d, r, r->Int(0, 2));
  if (r->Chance(0.45)) BevelFinish(d, r);
  if (r->Chance(0.3)) SubdivisionFinish(d, r);
}

// Detailed assemblies: a shaped block with several features, finished and posed (the long
// sequences of the corpus).
void Detailed(Draft* d, Random* r) {
  ScaleBlock(d, r, Proportion::kAny);
  Profile(d, r, r->Int(0, 2));
  const int features = r->Int(3, 6);
  for (int k = 0; k < features; ++k) {
    switch (r->Weighted({1, 1, 0.5, 0.7, 0.5, 0.6, 0.4})) {
      case 0: ExtrudeFace(d, r); break;
      case 1: InsetExtrude(d, r, false); break;
      case 2: Panels(d, r); break;
      case 3: BooleanFeature(d, r, true); break;
      case 4: BooleanFeature(d, r, false); break;
      case 5: Chain(d, r); break;
      default: Facets(d, r); break;
    }
  }
  if (r->Chance(0.3)) MirrorPair(d, r);
  if (r->Chance(0.5)) BevelFinish(d, r);
  if (r->Chance(0.4)) SubdivisionFinish(d, r);
  if (r->Chance(0.5)) Pose(d, r);
}

// Tables, benches, chairs, cabinets on legs.
void Furniture(Draft* d, Random* r) {
  ScaleBlock(d, r, Proportion::kSlab);
  if (!SlabGrid(d, r)) return;
  Legs(d, r);
  if (r->Chance(0.45)) Backrest(d, r);
  if (r->Chance(0.3)) BooleanFeature(d, r, true);
  if (r->Chance(0.35)) BevelFinish(d, r);
}

// Creatures, vehicles and tools: a body with limbs, often in symmetric pairs.
void Limbs(Draft* d, Random* r) {
  ScaleBlock(d, r, r->Chance(0.5) ? Proportion::kLong : Proportion::kAny);
  if (r->Chance(0.4)) Profile(d, r, 0);
  const int chains = r->Int(1, 2);
  for (int k = 0; k < chains; ++k) Chain(d, r);
  if (r->Chance(0.2)) Deform(d, r, 0);
  if (r->Chance(0.5)) MirrorPair(d, r);
  if (r->Chance(0.55)) SubdivisionFinish(d, r);
}

// CSG parts: a block with holes, pockets and bosses of boxes, cylinders and prisms.
void Csg(Draft* d, Random* r) {
  ScaleBlock(d, r, Proportion::kAny);
  const int booleans = r->Int(1, 3);
  for (int k = 0; k < booleans; ++k) BooleanFeature(d, r, r->Chance(0.6));
  if (r->Chance(0.2)) MirrorPair(d, r);
  if (r->Chance(0.3)) BevelFinish(d, r);
}

// Faceted solids: gems, rocks, chipped blocks.
void Faceted(Draft* d, Random* r) {
  ScaleBlock(d, r, Proportion::kAny);
  const int facets = r->Int(1, 3);
  for (int k = 0; k < facets; ++k) Facets(d, r);
  if (r->Chance(0.35)) Deform(d, r, 2);
  if (r->Chance(0.2)) BevelFinish(d, r);
}

// Twisted, bent and tapered forms: horns, bananas, twisted columns.
void Deformed(Draft* d, Random* r) {
  ScaleBlock(d, r, r->Chance(0.5) ? Proportion::kColumn : Proportion::kLong);
  const int axis = d->Extent().z() > d->Extent().x() ? 2 : 0;
  if (r->Chance(0.6)) Profile(d, r, axis);
  const int deforms = r->Int(1, 2);
  for (int k = 0; k < deforms; ++k) Deform(d, r, axis);
  if (r->Chance(0.5)) SubdivisionFinish(d, r);
}

// Buildings: a box with a gable, windows and a chimney.
void House(Draft* d, Random* r) {
  ScaleBlock(d, r, Proportion::kAny);
  Ridge(d, r);
  if (r->Chance(0.8)) InsetExtrude(d, r, false);
  if (r->Chance(0.5)) BooleanFeature(d, r, false);
}

using Recipe = void (*)(Draft*, Random*);
const Recipe kRecipes[] = {Turned, HardSurface, Furniture, Limbs, Csg, Faceted, Deformed, House, Detailed};
const std::vector<double> kRecipeWeights = {1.2, 1.3, 0.9, 0.8, 1.1, 0.8, 1.4, 0.6, 0.9};

}  // namespace

const std::vector<std::string>& RecipeNames() {
  static const std::vector<std::string> kNames = {"turned", "hard_surface", "furniture", "limbs",
                                                  "csg",    "faceted",      "deformed",  "house",
                                                  "detailed"};
  return kNames;
}

std::string SynthOptions::Check() const {
  if (min_ops < 1 || max_ops < min_ops) return "need 1 <= min_ops <= max_ops";
  if (max_faces < 6 || max_attempts < 1) return "max_faces and max_attempts must be positive";
  return "";
}

SynthModel SampleModel(uint64_t set_seed, int index, const SynthOptions& options, int redraw) {
  SynthModel model;
  Random random(ModelSeed(set_seed, index) + static_cast<uint64_t>(redraw) * 0x9e3779b97f4a7c15ULL);
  int recipe = random.Weighted(kRecipeWeights);
  while (model.attempts < options.max_attempts) {
    // The recipe is kept across rejections (so the set's mix of kinds follows the weights, not
    // how often each kind passes the checks), and redrawn only after many.
    if (model.attempts > 0 && model.attempts % 50 == 0) recipe = random.Weighted(kRecipeWeights);
    ++model.attempts;
    Draft draft;
    kRecipes[recipe](&draft, &random);
    if (random.Chance(0.25)) Pose(&draft, &random);
    std::string problem;
    if (draft.NumOps() < options.min_ops) problem = "too short";
    else if (draft.NumOps() > options.max_ops) problem = "too long";
    else if (draft.mesh().NumFaces() > options.max_faces) problem = "too many faces";
    if (problem.empty()) {
      // The written document, re-read, must build the draft's mesh: what model.obj holds.
      try {
        Sequence sequence = ParseSequence(Json::parse(draft.Document().dump()));
        const std::vector<Mesh> steps = EvaluateSequence(&sequence);
        problem = DegenerateProblem(draft.Document(), steps);
        if (problem.empty()) {
          model.ok = true;
          model.recipe = RecipeNames()[recipe];
          model.sequence = draft.Document();
          model.mesh = steps.back();
          return model;
        }
      } catch (const std::exception&) {
        problem = "does not rebuild";
      }
    }
    ++model.rejections[problem];
  }
  return model;
}

}  // namespace synth
}  // namespace opgraph
