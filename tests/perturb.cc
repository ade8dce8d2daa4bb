#include "tests/perturb.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace opgraph {

namespace {

bool IsAngle(const std::string& name) {
  return name.find("rotation") != std::string::npos || name.find("angle") != std::string::npos ||
         name.find("tilt") != std::string::npos;
}

}  // namespace

int PerturbParameters(const Program& program, const Sequence& sequence, uint64_t seed) {
  std::mt19937_64 rng(seed);
  int count = 0;
  for (const ProgramBlock& block : program.blocks()) {
    if (!block.holds_op_params()) continue;
    const Op& op = *sequence.ops[block.op];
    for (int i = 0; i < block.size; ++i) {
      if (std::count(block.constant.begin(), block.constant.end(), i)) continue;
      const ParamSpec& spec = op.specs()[i];
      const double sign = (rng() & 1) ? 1.0 : -1.0;
      double& value = block.data[i];
      const double delta = IsAngle(spec.name) ? 0.3 : 0.3 * std::max(std::abs(value), 0.1);
      value = std::min(spec.upper, std::max(spec.lower, value + sign * delta));
      ++count;
    }
  }
  return count;
}

}  // namespace opgraph
