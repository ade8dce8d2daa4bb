// The fitter's discrete side (solver/fitter.h): whether the written sequence still rebuilds
// the program's output, and the program rebuilt when the topology passes or the committed
// branch choices change it.
#include <stdexcept>

#include "solver/fitter.h"

namespace opgraph {

void Fitter::RebuildProgram() {
  const std::vector<double> logits = program_->logits();
  const std::vector<double> boolean_logits = program_->boolean_logits();
  retired_jacobian_evaluations_ += program_->num_jacobian_evaluations();
  program_ = std::make_unique<Program>(sequence_, free_gates_, std::vector<BranchChoice>(), boolean_weight_ops_);
  ++program_generation_;
  program_->set_logits(logits);  // exact gates (the constructor clamps them)
  program_->set_boolean_logits(boolean_logits);
}

Fitter::Reproduction Fitter::CheckReproduction() const {
  try {
    Sequence copy = ParseSequence(SequenceToJson(*sequence_));
    for (size_t k = 0; k < copy.ops.size(); ++k) copy.gates[k] = program_->Gate(static_cast<int>(k));
    const std::vector<Mesh> steps = EvaluateSequence(&copy);
    const Mesh& result = steps.empty() ? copy.StartMesh() : steps.back();
    if (result.faces != program_->faces() || result.vertices.size() != program_->positions().size()) {
      return Reproduction::kDifferent;
    }
    const double tolerance = 1e-7 / target_.scale();
    for (size_t v = 0; v < result.vertices.size(); ++v) {
      if (!((result.vertices[v] - program_->positions()[v]).norm() <= tolerance)) return Reproduction::kDifferent;
    }
    return Reproduction::kSame;
  } catch (const std::exception&) {
    return Reproduction::kFails;
  }
}

bool Fitter::ResolveTopology() {
  // A blend of branches is no written sequence; its topology is fixed until CommitBranches.
  if (program_->num_branches() > 0) return true;
  const Reproduction reproduction = CheckReproduction();
  if (reproduction != Reproduction::kDifferent) return reproduction == Reproduction::kSame;
  // The copy evaluated with these parameters and gates, so the sequence itself will too.
  program_->StoreGates();
  RebuildProgram();
  program_->PrepareForEvaluation(false, true);
  return true;
}

bool Fitter::CommitBranches(FitSummary* summary) {
  if (program_->num_branches() == 0) return false;
  for (int b = 0; b < program_->num_branches(); ++b) {
    const std::vector<double> weights = program_->BranchWeights(b);
    summary->branch_weights.push_back(weights);
    summary->branch_choices.push_back(static_cast<int>(std::max_element(weights.begin(), weights.end()) - weights.begin()));
  }
  program_->CommitBranches();
  RebuildProgram();
  if (options_.progress) {
    *options_.progress << "fit: committed " << summary->branch_choices.size() << " branch choice(s); polishing\n";
  }
  return true;
}

}  // namespace opgraph
