#include "solver/anderson.h"

#include <Eigen/QR>

namespace opgraph {

bool AndersonAcceleration::Step(const Eigen::VectorXd& x, const Eigen::VectorXd& g, Eigen::VectorXd* next) {
  if (history_ <= 0) return false;
  if (!images_.empty() && images_.back().size() != g.size()) Clear();
  images_.push_back(g);
  residuals_.push_back(g - x);
  while (static_cast<int>(images_.size()) > history_ + 1) images_.pop_front(), residuals_.pop_front();
  const int columns = static_cast<int>(images_.size()) - 1;
  if (columns < 1) return false;
  const Eigen::Index n = g.size();
  Eigen::MatrixXd residual_changes(n, columns), image_changes(n, columns);
  for (int i = 0; i < columns; ++i) {
    residual_changes.col(i) = residuals_[i + 1] - residuals_[i];
    image_changes.col(i) = images_[i + 1] - images_[i];
  }
  // gamma minimises |f_k - dF gamma|; rank-revealing, as successive residuals are often nearly
  // parallel.
  const Eigen::VectorXd gamma = residual_changes.colPivHouseholderQr().solve(residuals_.back());
  *next = g - image_changes * gamma;
  return next->allFinite();
}

}  // namespace opgraph
