// The fitter's last stage when it fits gates (solver/fitter.h): ops whose gate fell below
// prune_gate are removed, the other gates folded into their op's parameters, and the
// parameters polished with the gates fixed.
#include "solver/fitter.h"

namespace opgraph {

void Fitter::Finalise(FitSummary* summary) {
  program_->StoreGates();
  summary->gates_before_finalisation = sequence_->gates;
  std::vector<bool> prune(sequence_->ops.size(), false);
  for (size_t k = 0; k < sequence_->ops.size(); ++k) {
    Op& op = *sequence_->ops[k];
    if (!program_->GateIsFree(static_cast<int>(k))) continue;  // pinned, or without parameters
    const double gate = sequence_->gates[k];
    prune[k] = gate < options_.prune_gate;
    // Fold the gate into the parameters: each op's gate blends p toward its identity value.
    for (size_t i = 0; i < op.params().size(); ++i) {
      const ParamSpec& spec = op.specs()[i];
      double& p = op.mutable_params()[i];
      p = std::min(spec.upper, std::max(spec.lower, spec.identity + gate * (p - spec.identity)));
    }
    sequence_->gates[k] = 1.0;
  }
  const Json folded = SequenceToJson(*sequence_);
  Json pruned = folded;
  pruned["operations"] = Json::array();
  for (size_t k = 0; k < prune.size(); ++k) {
    if (!prune[k]) pruned["operations"].push_back(folded["operations"][k]);
  }
  Sequence next;
  try {
    next = ParseSequence(pruned);
    EvaluateSequence(&next);
    for (size_t k = 0; k < prune.size(); ++k) {
      if (prune[k]) summary->pruned_ops.push_back(static_cast<int>(k));
    }
  } catch (const SequenceError&) {
    // A later op's target depends on a pruned one: keep them all (folded, near identity).
    next = ParseSequence(folded);
  }
  retired_jacobian_evaluations_ += program_->num_jacobian_evaluations();
  program_.reset();
  *sequence_ = std::move(next);
  free_gates_ = false;
  program_ = std::make_unique<Program>(sequence_, free_gates_);
  ++program_generation_;
  if (options_.progress) {
    *options_.progress << "fit: finalised gates (" << summary->pruned_ops.size() << " ops pruned); polishing\n";
  }
  RunStage(0.0, summary);
}

}  // namespace opgraph
