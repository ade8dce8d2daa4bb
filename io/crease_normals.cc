#include "io/crease_normals.h"

#include <pcl/common/centroid.h>
#include <pcl/features/normal_3d.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

namespace opgraph {
namespace {

// A plane is taken from another neighbourhood when it is flatter than this fraction of the
// point's own: a crease's neighbourhoods are many times less flat than a face's.
constexpr double kFlatterRatio = 0.25;

// A neighbourhood's least-squares plane and how flat it is.
struct NeighbourhoodPlane {
  Vec3d normal = Vec3d::Zero();
  Vec3d centroid = Vec3d::Zero();
  double variation = 1;  // smallest eigenvalue over their sum (PCL's curvature): 0 on a plane
  double tolerance = 0;  // how far off the plane a point may lie and still be on it
};

NeighbourhoodPlane FitPlane(const pcl::PointCloud<pcl::PointXYZ>& cloud, const std::vector<int>& indices,
                            const std::vector<float>& squared_distances) {
  NeighbourhoodPlane plane;
  Eigen::Vector4f parameters;
  float curvature = 1;
  if (!pcl::computePointNormal(cloud, indices, parameters, curvature) || !parameters.allFinite()) return plane;
  plane.normal = parameters.head<3>().cast<double>().normalized();
  Eigen::Vector4f centroid;
  pcl::compute3DCentroid(cloud, indices, centroid);
  plane.centroid = centroid.head<3>().cast<double>();
  plane.variation = curvature;
  // Twice the members' RMS distance to the plane (noise), and a float's rounding at the
  // neighbourhood's radius (an exact plane).
  double squared_residual = 0;
  for (int i : indices) {
    squared_residual += std::pow(plane.normal.dot(cloud[i].getVector3fMap().cast<double>() - plane.centroid), 2);
  }
  const double radius = std::sqrt(*std::max_element(squared_distances.begin(), squared_distances.end()));
  plane.tolerance = 2 * std::sqrt(squared_residual / indices.size()) + 1e-5 * radius;
  return plane;
}

}  // namespace

Positions<double> CreasePreservingNormals(const Positions<double>& points, int k) {
  // PCL works in floats: about the box's centre, so coordinates far from the origin keep
  // their precision relative to the cloud's size.
  Eigen::AlignedBox3d box;
  for (const Vec3d& p : points) box.extend(p);
  const Vec3d centre = box.center();
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  cloud->reserve(points.size());
  for (const Vec3d& p : points) {
    const Vec3d q = p - centre;
    cloud->push_back(pcl::PointXYZ(static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z())));
  }
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(cloud);
  const int neighbours = std::min<int>(k, static_cast<int>(points.size()));
  std::vector<std::vector<int>> neighbourhoods(points.size());
  std::vector<NeighbourhoodPlane> planes(points.size());
  std::vector<float> squared_distances;
  for (size_t i = 0; i < points.size(); ++i) {
    tree.nearestKSearch(static_cast<int>(i), neighbours, neighbourhoods[i], squared_distances);
    planes[i] = FitPlane(*cloud, neighbourhoods[i], squared_distances);
  }
  // Two rounds: a point beside the crease reaches, through a neighbour that took a
  // neighbourhood further in, a plane its own neighbours' neighbourhoods all cross the crease
  // from. A plane is taken only when clearly flatter than the point's own (smooth parts keep
  // theirs: their neighbourhoods differ in flatness by sampling noise only).
  std::vector<int> chosen(points.size());
  for (size_t i = 0; i < points.size(); ++i) chosen[i] = static_cast<int>(i);
  for (int round = 0; round < 2; ++round) {
    std::vector<int> next = chosen;
    for (size_t i = 0; i < points.size(); ++i) {
      for (int j : neighbourhoods[i]) {
        const NeighbourhoodPlane& plane = planes[chosen[j]];
        const bool on_plane = std::abs(plane.normal.dot(points[i] - centre - plane.centroid)) <= plane.tolerance;
        const bool clearly_flatter = plane.variation < kFlatterRatio * planes[i].variation;
        if (on_plane && clearly_flatter && plane.variation < planes[next[i]].variation) next[i] = chosen[j];
      }
    }
    chosen.swap(next);
  }
  Positions<double> normals(points.size());
  for (size_t i = 0; i < points.size(); ++i) normals[i] = planes[chosen[i]].normal;
  return normals;
}

}  // namespace opgraph
