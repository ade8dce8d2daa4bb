#include "solver/build_fit_objective.h"

#include <memory>

#include <ceres/loss_function.h>

#include "residuals/correspondence_cost.h"

namespace opgraph {

namespace {

std::unique_ptr<ceres::LossFunction> MakeLoss(RobustLoss kind, double scale) {
  switch (kind) {
    case RobustLoss::kHuber:
      return std::make_unique<ceres::HuberLoss>(scale);
    case RobustLoss::kCauchy:
      return std::make_unique<ceres::CauchyLoss>(scale);
    case RobustLoss::kNone:
      break;
  }
  return nullptr;
}

// A block list of `objective` over `data` (Program blocks), with each block's first column.
const Objective::Blocks* AddBlocks(const Program& program, std::vector<double*> data, Objective* objective) {
  Objective::Blocks& blocks = objective->block_lists.emplace_back();
  for (double* pointer : data) {
    for (const ProgramBlock& block : program.blocks()) {
      if (block.data == pointer) blocks.columns.push_back(block.column);
    }
  }
  blocks.data = std::move(data);
  return &blocks;
}

const ceres::CostFunction* AddCost(std::unique_ptr<ceres::CostFunction> cost, Objective* objective) {
  objective->other_costs.push_back(std::move(cost));
  return objective->other_costs.back().get();
}

}  // namespace

void BuildFitObjective(const Program& program, const FitterOptions& options, double unit_scale,
                       const FitCorrespondences& correspondences, const double* sparsity_weight, Objective* objective) {
  const std::vector<SurfaceCorrespondence>& forward = correspondences.output_to_target;
  const std::vector<SurfaceCorrespondence>& backward = correspondences.target_to_output;
  const double forward_weight = correspondences.output_to_target_weight;
  const double backward_weight = correspondences.target_to_output_weight;
  const BooleanWeightTerms& boolean = correspondences.boolean;
  const MixedBranchTerms& mixed = correspondences.mixed;
  const Objective::Blocks* all_blocks = AddBlocks(program, program.BlockPointers(), objective);
  objective->terms.reserve(forward.size() + backward.size() + boolean.boolean_to_target.size() +
                           boolean.target_to_boolean.size() + mixed.forward.size() + mixed.backward.size() +
                           program.blocks().size() + options.domain_rules.size());
  // Which residuals the Boolean weight scales (solver/boolean_weight.h): `on_extrusion` selects
  // (when given) the ones scaled by sqrt(1 - beta); the Boolean side's by sqrt(beta).
  enum class Scale { kNone, kExtrusion, kBoolean };
  auto add_terms = [&](const std::vector<SurfaceCorrespondence>& list, double weight, const std::vector<char>* on_extrusion,
                       Scale scale) {
    // The robust loss acts on the residual weight * (p - q) = sqrt(w / N) * (distance in the
    // unit box), so its scale (unit-box units) is multiplied by sqrt(w / N) = weight / unit_scale.
    objective->losses.push_back(MakeLoss(options.loss, options.loss_scale * weight / unit_scale));
    const ceres::LossFunction* loss = objective->losses.back().get();
    for (size_t i = 0; i < list.size(); ++i) {
      const Scale s = on_extrusion && !(*on_extrusion)[i] ? Scale::kNone : scale;
      const ceres::CostFunction* cost;
      if (s == Scale::kNone) {
        cost = &objective->correspondence_costs.emplace_back(&program, list[i], options.metric, weight);
      } else {
        cost = AddCost(std::make_unique<BooleanWeightedCost>(&program, list[i], options.metric, weight,
                                                             boolean.beta_block, s == Scale::kBoolean),
                       objective);
      }
      objective->terms.push_back({cost, loss, all_blocks});
    }
  };
  const bool weighted = boolean.beta_block >= 0;
  add_terms(forward, forward_weight, weighted ? &boolean.on_extrusion : nullptr, weighted ? Scale::kExtrusion : Scale::kNone);
  add_terms(backward, backward_weight, nullptr, weighted ? Scale::kExtrusion : Scale::kNone);
  if (weighted) {
    add_terms(boolean.boolean_to_target, forward_weight, nullptr, Scale::kBoolean);
    add_terms(boolean.target_to_boolean, backward_weight, nullptr, Scale::kBoolean);
  }
  auto add_mixed_terms = [&](const std::vector<SurfaceCorrespondence>& list, const std::vector<int>& option,
                             double weight) {
    objective->losses.push_back(MakeLoss(options.loss, options.loss_scale * weight / unit_scale));
    for (size_t i = 0; i < list.size(); ++i) {
      objective->terms.push_back({AddCost(std::make_unique<BranchWeightedCost>(&program, list[i], options.metric,
                                                                               weight, mixed.block, option[i]),
                                          objective),
                                  objective->losses.back().get(), all_blocks});
    }
  };
  add_mixed_terms(mixed.forward, mixed.forward_option, mixed.forward_weight);
  add_mixed_terms(mixed.backward, mixed.backward_option, mixed.backward_weight);
  for (const ProgramBlock& block : program.blocks()) {
    if (block.is_gate) {
      objective->terms.push_back({AddCost(std::make_unique<GateSparsityCost>(sparsity_weight), objective), nullptr,
                                  AddBlocks(program, {block.data}, objective)});
    }
  }
  for (const ParameterRangeRule& rule : options.domain_rules) {
    for (const ProgramBlock& block : program.blocks()) {
      if (block.holds_op_params() && block.op == rule.op && rule.param >= 0 && rule.param < block.size) {
        objective->terms.push_back({AddCost(std::make_unique<ParameterRangeCost>(rule, block.size), objective),
                                    nullptr, AddBlocks(program, {block.data}, objective)});
      }
    }
  }
}

}  // namespace opgraph
