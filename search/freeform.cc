#include "search/freeform.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "core/metrics.h"
#include "core/parallel_for.h"
#include "core/nearest.h"
#include "ops/builders.h"
#include "ops/replay_guards.h"
#include "ops/sequence.h"
#include "search/policy.h"
#include "solver/affine_tail.h"
#include "solver/freeform_fit.h"

namespace opgraph {
namespace {

// A free-form stage must lower the Chamfer distance by this fraction (with a refined cage, also
// by the price of the Subdivision it adds): it moves every cage vertex, so it is kept only for
// detail the structured ops could not reach.
constexpr double kFreeformGain = 0.25;
// Below this Chamfer distance (unit box, both ways) the structure already explains the shape.
constexpr double kMinChamfer = 2e-3;
// Cages above this size are not displaced (3 parameters and a group per vertex).
constexpr int kMaxCageVertices = 1500;

bool IsAffineTailOp(const std::string& name) {
  return name == "Subdivision" || name == "GlobalAffineScale" || name == "GlobalAffineRotate" ||
         name == "GlobalAffineTranslate";
}

// Where the displacements go: before the first Subdivision of the document's trailing run of
// affine ops, else before the run.
int TailStart(const Json& operations) {
  int first = static_cast<int>(operations.size());
  while (first > 0 && IsAffineTailOp(operations[first - 1].at("op"))) --first;
  for (int k = first; k < static_cast<int>(operations.size()); ++k) {
    if (operations[k].at("op") == "Subdivision") return k;
  }
  return first;
}

// Per vertex, the distance to the nearest other vertex of the cage.
std::vector<double> NearestSpacing(const Positions<double>& vertices) {
  const PointTree tree(vertices);
  std::vector<double> spacing(vertices.size(), 0.0);
  std::vector<size_t> indices;
  std::vector<double> squared;
  for (size_t v = 0; v < vertices.size(); ++v) {
    tree.KNearest(vertices[v], 2, &indices, &squared);
    spacing[v] = std::sqrt(squared.back());
  }
  return spacing;
}

double Chamfer(const Evaluator& evaluator, const Json& document) {
  MetricsOptions options;
  options.num_samples = 3000;
  options.seed = evaluator.options().seed;
  Sequence sequence = evaluator.Parse(document);
  return ComputeTargetMetrics(EvaluateSequence(&sequence).back(), evaluator.target(), options).chamfer.Sum();
}

struct Candidate {
  Json document;
  double chamfer = std::numeric_limits<double>::infinity();
  double loss = 0;
  int displaced = 0;
};

// The displacements fitted on the cage of `document` (its ops before `first_op`), written as a
// VertexDisplace at `first_op`: one group per moved vertex, a box around it, expecting one vertex.
std::optional<Candidate> FitCandidate(const Evaluator& evaluator, const Json& document, int first_op) {
  Sequence sequence = evaluator.Parse(document);
  const std::vector<Mesh> steps = EvaluateSequence(&sequence);
  const Mesh cage = first_op == 0 ? sequence.StartMesh() : steps[first_op - 1];
  if (cage.NumVertices() > kMaxCageVertices) return std::nullopt;
  if (cage.NumVertices() < 2) return std::nullopt;
  Eigen::AlignedBox3d box;
  for (const Vec3d& p : cage.vertices) box.extend(p);
  const double diagonal = box.diagonal().norm();
  const std::vector<double> spacing = NearestSpacing(cage.vertices);
  const AffineTail tail = ProbeAffineTail(sequence, first_op, cage, steps.back());
  FreeformOptions options;
  options.seed = evaluator.options().seed;
  options.num_threads = 1;  // the candidates run in parallel; one thread each keeps them deterministic
  options.max_seconds = evaluator.FitMaxSeconds(Evaluator::kFreeformShare);
  const FreeformResult fit = FitDisplacements(evaluator.target(), cage, tail, options);
  std::vector<build::DisplaceGroup> groups;
  for (int v = 0; v < cage.NumVertices(); ++v) {
    // A box that holds no other vertex (half its side under the nearest one's distance over
    // sqrt(3)) and is wide against Blender's float32 coordinates and its own subdivision's
    // rounding; vertices too close to another to box safely stay in place.
    const double reach = 0.25 * spacing[v];
    if (!(fit.displacements[v].norm() > 1e-5 * diagonal) || !(reach > 1e-4 * diagonal)) continue;
    build::DisplaceGroup group;
    for (int axis = 0; axis < 3; ++axis) {
      group.verts.box.lo[axis] = cage.vertices[v][axis] - reach;
      group.verts.box.hi[axis] = cage.vertices[v][axis] + reach;
    }
    group.verts.expect = 1;
    group.offset = fit.displacements[v];
    groups.push_back(group);
  }
  if (groups.empty()) return std::nullopt;
  Candidate candidate;
  candidate.document = document;
  Json& operations = candidate.document["operations"];
  operations.insert(operations.begin() + first_op, build::VertexDisplace(groups));
  Sequence replay = evaluator.Parse(candidate.document);
  const std::vector<Mesh> replay_steps = EvaluateSequence(&replay);
  if (BreaksReplay(replay, replay_steps)) return std::nullopt;
  candidate.chamfer = Chamfer(evaluator, candidate.document);
  candidate.loss = fit.final_loss;
  candidate.displaced = static_cast<int>(groups.size());
  return candidate;
}

}  // namespace

FreeformOutcome AddFreeformDetail(Evaluator* evaluator, const Json& document) {
  FreeformOutcome outcome{document};
  const Json& operations = document.at("operations");
  const int first_op = TailStart(operations);
  // Each displaced vertex is found again in Blender by a small box around it. A Bevel's profile
  // vertices match Blender's surface but can sit elsewhere along it (1.7e-3 of the diagonal seen
  // on a 9-segment bevel), so a bevelled cage is not displaced.
  for (int k = 0; k < first_op; ++k) {
    if (operations[k].at("op") == "Bevel") {
      evaluator->Note("freeform: not tried on a bevelled cage");
      return outcome;
    }
  }
  const double before = Chamfer(*evaluator, document);
  if (before < kMinChamfer) return outcome;
  std::optional<Candidate> best;
  double best_score = before * (1 - kFreeformGain);
  std::string best_what;
  // The cage as is and refined by Subdivision 1 and 2, fitted in parallel, judged in order.
  constexpr int kRefinements = 3;
  std::optional<Candidate> candidates[kRefinements];
  std::string errors[kRefinements];
  ParallelFor(kRefinements, evaluator->options().num_threads, [&](int refine) {
    Json base = document;
    if (refine > 0) base["operations"].insert(base["operations"].begin() + first_op, build::Subdivision(refine));
    try {
      candidates[refine] = FitCandidate(*evaluator, base, first_op + (refine ? 1 : 0));
    } catch (const std::runtime_error& error) {
      errors[refine] = error.what();
    }
  });
  for (int refine = 0; refine < kRefinements; ++refine) {
    if (!errors[refine].empty()) evaluator->Note("freeform: not fitted: " + errors[refine]);
    const std::optional<Candidate>& candidate = candidates[refine];
    if (!candidate) continue;
    const double score = candidate->chamfer / Price(evaluator->options(), refine > 0 ? 1 : 0);
    const std::string what = std::to_string(candidate->displaced) + " vertices displaced" +
                             (refine > 0 ? " on a cage refined by Subdivision(" + std::to_string(refine) + ")" : "");
    std::ostringstream line;
    line << "freeform: " << what << ": Chamfer " << before << " -> " << candidate->chamfer;
    evaluator->Note(line.str());
    if (score < best_score) best = candidate, best_score = score, best_what = what;
  }
  evaluator->Note(best ? "freeform: kept " + best_what : "freeform: not kept");
  if (best) outcome.document = best->document, outcome.used = true, outcome.loss = best->loss;
  return outcome;
}

}  // namespace opgraph
