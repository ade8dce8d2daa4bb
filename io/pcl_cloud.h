// Adapters from PCL point clouds in memory to opgraph's input geometry, for pipelines that
// embed the fitter (see examples/embed_point_cloud.cc).
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cmath>
#include <type_traits>

#include "io/read_input.h"

namespace opgraph {

// A point cloud as InputGeometry: positions of every finite point (#P), and its normals when
// PointT carries them (pcl::PointNormal, pcl::PointXYZRGBNormal, ...) and all are finite.
template <typename PointT>
InputGeometry InputFromPclCloud(const pcl::PointCloud<PointT>& cloud) {
  InputGeometry input;
  bool normals_usable = pcl::traits::has_normal_v<PointT>;
  for (const PointT& point : cloud.points) {
    const Vec3d p(point.x, point.y, point.z);
    if (!p.allFinite()) continue;
    input.mesh.vertices.push_back(p);
    if constexpr (pcl::traits::has_normal_v<PointT>) {
      const Vec3d n(point.normal_x, point.normal_y, point.normal_z);
      normals_usable = normals_usable && n.allFinite() && n.norm() > 1e-12;
      input.normals.push_back(normals_usable ? n.normalized() : Vec3d::Zero());
    }
  }
  if (!normals_usable) input.normals.clear();
  return input;
}

}  // namespace opgraph
