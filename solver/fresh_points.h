// The points at which a fit took the loss with fresh correspondences, so that the same point
// is not measured twice: the loss before a stage's first correspondence update is the one the
// update takes, and the loss after a stage is the one at its best update. A fresh loss is a
// function of the parameter values, the gates the program does not fit (the sequence's), the
// program's topology (its generation: the fitter counts rebuilds), the seed and the stage's
// sparsity weight, so equal keys give the same loss to the last bit.
#pragma once

#include <memory>
#include <vector>

#include "solver/fit_correspondences.h"

namespace opgraph {

struct FreshPoint {
  int program_generation = 0;
  double sparsity_weight = 0;
  std::vector<double> values;  // every program block's, in block order
  std::vector<double> gates;   // the sequence's
  double loss = 0;
  // The correspondences built there, while a stage may still start at this point.
  std::unique_ptr<FitCorrespondences> correspondences;
};

class FreshPoints {
 public:
  void Clear() { points_.clear(); }
  void Add(FreshPoint point) { points_.push_back(std::move(point)); }
  // The point with these keys, or null.
  FreshPoint* Find(int program_generation, double sparsity_weight, const std::vector<double>& values,
                   const std::vector<double>& gates) {
    for (FreshPoint& point : points_) {
      if (point.program_generation == program_generation && point.sparsity_weight == sparsity_weight &&
          point.values == values && point.gates == gates) {
        return &point;
      }
    }
    return nullptr;
  }

 private:
  std::vector<FreshPoint> points_;
};

}  // namespace opgraph
