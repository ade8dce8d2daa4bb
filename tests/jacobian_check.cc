#include "tests/jacobian_check.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace opgraph {

std::vector<double> CostResiduals(Program* program, const ceres::CostFunction& cost) {
  program->PrepareForEvaluation(false, true);
  std::vector<double> r(cost.num_residuals());
  const std::vector<double*> blocks = program->BlockPointers();
  EXPECT_TRUE(cost.Evaluate(blocks.data(), r.data(), nullptr));
  return r;
}

int JacobianComparison::nonzero() const {
  int sum = 0;
  for (int n : nonzero_per_block) sum += n;
  return sum;
}

JacobianComparison ExpectJacobianMatchesCentralDifferences(Program* program, const ceres::CostFunction& cost,
                                                           const std::string& what, double tolerance) {
  const std::vector<double*> blocks = program->BlockPointers();
  program->PrepareForEvaluation(true, true);
  std::vector<std::vector<double>> jacobians(blocks.size());
  std::vector<double*> jacobian_pointers;
  for (size_t b = 0; b < blocks.size(); ++b) {
    jacobians[b].resize(cost.num_residuals() * program->blocks()[b].size);
    jacobian_pointers.push_back(jacobians[b].data());
  }
  std::vector<double> r(cost.num_residuals());
  EXPECT_TRUE(cost.Evaluate(blocks.data(), r.data(), jacobian_pointers.data()));
  JacobianComparison result;
  result.nonzero_per_block.assign(blocks.size(), 0);
  for (size_t b = 0; b < blocks.size(); ++b) {
    const ProgramBlock& block = program->blocks()[b];
    for (int j = 0; j < block.size; ++j) {
      const bool constant = std::count(block.constant.begin(), block.constant.end(), j) > 0;
      const double saved = block.data[j];
      const double h = 1e-6 * std::max(1.0, std::abs(saved));
      block.data[j] = saved + h;
      const std::vector<double> plus = CostResiduals(program, cost);
      block.data[j] = saved - h;
      const std::vector<double> minus = CostResiduals(program, cost);
      block.data[j] = saved;
      for (int i = 0; i < cost.num_residuals(); ++i) {
        const double analytic = jacobians[b][i * block.size + j];
        if (constant) {
          EXPECT_EQ(analytic, 0.0) << what << " block " << b << " (held) column " << j;
          continue;
        }
        const double numeric = (plus[i] - minus[i]) / (2 * h);
        EXPECT_NEAR(analytic, numeric, tolerance * std::max(1.0, std::abs(numeric)))
            << what << " block " << b << " (op " << block.op << (block.is_gate ? " gate" : "")
            << (block.is_boolean_weight ? " Boolean weight" : "") << ") column " << j << " residual " << i;
        ++result.compared;
        result.nonzero_per_block[b] += std::abs(numeric) > 1e-6;
      }
    }
  }
  program->PrepareForEvaluation(false, true);
  return result;
}

}  // namespace opgraph
