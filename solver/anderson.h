// Anderson acceleration of a fixed-point iteration x <- G(x) (Walker & Ni 2011, type II), as
// AA-ICP applies it to the correspondence loop (Pavlov, Ovchinnikov, Shabanov, Ferguson 2018):
// the fitter's "re-estimate correspondences, solve" is such a map G of the parameters, and it
// converges linearly, slowly where the shape must move far (a ridge raised, a boss grown), with
// one LM iteration per update near the end. From the last m applications the next point is the
// combination of their images whose residuals G(x) - x cancel best in least squares.
//
// The caller safeguards: it evaluates the loss at the extrapolated point and, where that is not
// lower, falls back to the plain image G(x) and calls Clear().
#pragma once

#include <deque>

#include <Eigen/Core>

namespace opgraph {

class AndersonAcceleration {
 public:
  // `history` applications of G are kept (m); 0 turns the acceleration off.
  explicit AndersonAcceleration(int history) : history_(history) {}

  // Records one application x -> g (both #params) and, once two are recorded, writes the
  // extrapolated next point to `next` (#params) and returns true. False when off, with fewer
  // than two applications, or when the extrapolation is degenerate (not finite).
  bool Step(const Eigen::VectorXd& x, const Eigen::VectorXd& g, Eigen::VectorXd* next);

  void Clear() { images_.clear(), residuals_.clear(); }

 private:
  int history_;
  std::deque<Eigen::VectorXd> images_;     // G(x_i)
  std::deque<Eigen::VectorXd> residuals_;  // G(x_i) - x_i
};

}  // namespace opgraph
