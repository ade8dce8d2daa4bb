#include "solver/fitter.h"

namespace opgraph {

std::string FitterOptions::Check() const {
  if (num_output_samples < 10 || num_output_samples > 10000000) return "num_output_samples must be in [10, 1e7]";
  if (num_target_samples < 0 || num_target_samples > 10000000) return "num_target_samples must be in [0, 1e7]";
  if (!(output_to_target_weight >= 0) || !(target_to_output_weight >= 0) ||
      output_to_target_weight + target_to_output_weight <= 0) {
    return "term weights must be >= 0 and not both 0";
  }
  if (!(loss_scale > 0)) return "loss_scale must be > 0";
  if (!(gate_sparsity_weight >= 0)) return "gate_sparsity_weight must be >= 0";
  if (!(prune_gate > 0 && prune_gate < 1)) return "prune_gate must be in (0, 1)";
  if (max_outer_iterations < 1 || max_inner_iterations < 1 || adam_iterations < 1) return "iteration limits must be >= 1";
  if (!(adam_learning_rate > 0)) return "adam_learning_rate must be > 0";
  if (!(initial_trust_region_radius > 0)) return "initial_trust_region_radius must be > 0";
  if (!(min_relative_improvement >= 0)) return "min_relative_improvement must be >= 0";
  if (max_stalled_updates < 0) return "max_stalled_updates must be >= 0";
  if (num_threads < 1) return "num_threads must be >= 1";
  if (!(max_seconds >= 0)) return "max_seconds must be >= 0";
  for (const ParameterRangeRule& rule : domain_rules) {
    if (!(rule.weight >= 0) || !(rule.lower <= rule.upper)) return "domain rule: need weight >= 0 and lower <= upper";
  }
  for (int op : boolean_weight_ops) {
    if (op < 0) return "boolean_weight_ops: op indices must be >= 0";
  }
  for (const BranchChoice& branch : branches) {
    if (branch.op < 0 || branch.field.empty() || branch.options.size() < 2) {
      return "branch choice: need op >= 0, a field and >= 2 options";
    }
  }
  return "";
}

}  // namespace opgraph
