// The softmax of a branch choice's logits (program/program.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace opgraph {

// `weights` := softmax(`logits`), shifted by the largest logit so no exp overflows.
inline void Softmax(const std::vector<double>& logits, std::vector<double>* weights) {
  const double top = *std::max_element(logits.begin(), logits.end());
  double sum = 0;
  weights->resize(logits.size());
  for (size_t i = 0; i < logits.size(); ++i) sum += (*weights)[i] = std::exp(logits[i] - top);
  for (double& w : *weights) w /= sum;
}

}  // namespace opgraph
