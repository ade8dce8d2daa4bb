#include "core/cloud_surface.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/nearest.h"

namespace opgraph {

CloudSurface::CloudSurface(const Positions<double>& points, const Positions<double>& normals)
    : points_(points), normals_(normals) {
  if (points.empty() || normals.size() != points.size()) {
    throw std::invalid_argument("cloud surface: needs one normal per point and at least one point");
  }
  tree_ = std::make_unique<PointTree>(points_);
  spacing_.assign(points_.size(), 0.0);
  const int k = std::min<int>(kSpacingNeighbours + 1, static_cast<int>(points_.size()));  // the point itself first
  std::vector<size_t> indices;
  std::vector<double> squared;
  for (size_t i = 0; i < points_.size(); ++i) {
    tree_->KNearest(points_[i], k, &indices, &squared);
    spacing_[i] = std::sqrt(squared.back());
  }
}

CloudSurface::~CloudSurface() = default;

double CloudSurface::Distance(const Vec3d& query) const {
  const int nearest = tree_->Nearest(query, nullptr);
  const Vec3d offset = query - points_[nearest];
  const double along = normals_[nearest].dot(offset);
  const double tangential = (offset - along * normals_[nearest]).norm();
  const double excess = std::max(0.0, tangential - spacing_[nearest]);
  return std::sqrt(along * along + excess * excess);
}

}  // namespace opgraph
