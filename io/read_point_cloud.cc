#include "io/read_point_cloud.h"

#include <pcl/common/io.h>
#include <pcl/features/normal_3d.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "io/orient_normals.h"
#include "io/pcd_header.h"
#include "io/read_in_child_process.h"

namespace opgraph {
namespace {

[[noreturn]] void Fail(const std::string& path, const std::string& message) {
  throw std::runtime_error(path + ": " + message);
}

// pcl::fromPCLPointCloud2 trusts the blob's counts and field offsets, which come from the file.
void CheckPclBlob(const std::string& path, const pcl::PCLPointCloud2& blob) {
  const uint64_t points = static_cast<uint64_t>(blob.width) * blob.height;
  if (points == 0) Fail(path, "no points");
  for (const auto& field : blob.fields) {
    const uint64_t end = field.offset + static_cast<uint64_t>(pcl::getFieldSize(field.datatype)) * field.count;
    if (end > blob.point_step) Fail(path, "corrupt point cloud: field '" + field.name + "' lies outside its point");
  }
  if (blob.data.size() / std::max<uint64_t>(blob.point_step, 1) < points) {
    Fail(path, "corrupt point cloud: " + std::to_string(points) + " points declared, fewer stored");
  }
}

InputGeometry FromPclBlob(const std::string& path, const pcl::PCLPointCloud2& blob) {
  CheckPclBlob(path, blob);
  pcl::PointCloud<pcl::PointNormal> cloud;
  pcl::fromPCLPointCloud2(blob, cloud);
  bool has_normals = false;
  for (const auto& field : blob.fields) has_normals = has_normals || field.name == "normal_x";
  InputGeometry input;
  for (const auto& p : cloud.points) {
    input.mesh.vertices.emplace_back(p.x, p.y, p.z);
    if (has_normals) input.normals.emplace_back(p.normal_x, p.normal_y, p.normal_z);
  }
  return input;
}

}  // namespace

InputGeometry ReadPcdPoints(const std::string& path) {
  CheckPcdFile(path);  // PCL crashes on some malformed headers and trusts declared counts
  return ReadInChildProcess(path, [&path] {
    pcl::PCLPointCloud2 blob;
    pcl::PCDReader reader;
    if (reader.read(path, blob) < 0) Fail(path, "cannot read PCD point cloud");
    return FromPclBlob(path, blob);
  });
}

InputGeometry ReadPlyPoints(const std::string& path) {
  return ReadInChildProcess(path, [&path] {  // as Assimp, PCL trusts what a file says
    pcl::PCLPointCloud2 blob;
    pcl::PLYReader reader;
    if (reader.read(path, blob) < 0) Fail(path, "cannot read PLY");
    return FromPclBlob(path, blob);
  });
}

InputGeometry ReadXyzPoints(const std::string& path) {
  std::ifstream in(path);
  InputGeometry input;
  std::string line;
  int line_number = 0;
  int columns = -1;
  while (std::getline(in, line)) {
    ++line_number;
    const size_t start = line.find_first_not_of(" \t\r");
    if (start == std::string::npos || line[start] == '#') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    std::vector<double> values;
    std::string token;
    while (fields >> token) {
      char* end = nullptr;
      const double value = std::strtod(token.c_str(), &end);
      if (end == token.c_str() || *end != '\0') Fail(path, "line " + std::to_string(line_number) + ": '" + token.substr(0, 20) + "' is not a number");
      values.push_back(value);
    }
    if (values.size() < 3) Fail(path, "line " + std::to_string(line_number) + ": expected x y z [nx ny nz]");
    const int row_columns = values.size() >= 6 ? 6 : 3;
    if (columns < 0) columns = row_columns;
    if (row_columns != columns) Fail(path, "line " + std::to_string(line_number) + ": column count changes");
    input.mesh.vertices.emplace_back(values[0], values[1], values[2]);
    if (columns == 6) input.normals.emplace_back(values[3], values[4], values[5]);
  }
  return input;
}

Positions<double> EstimatePointNormals(const Positions<double>& points, int k) {
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  cloud->reserve(points.size());
  Vec3d centroid = Vec3d::Zero();
  for (const Vec3d& p : points) {
    cloud->push_back(pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())));
    centroid += p;
  }
  centroid /= std::max<size_t>(points.size(), 1);
  pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> estimation;
  estimation.setInputCloud(cloud);
  estimation.setSearchMethod(std::make_shared<pcl::search::KdTree<pcl::PointXYZ>>());
  estimation.setKSearch(std::min<int>(k, static_cast<int>(points.size())));
  pcl::PointCloud<pcl::Normal> normals;
  estimation.compute(normals);
  Positions<double> result(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    Vec3d n(normals[i].normal_x, normals[i].normal_y, normals[i].normal_z);
    if (!n.allFinite() || n.norm() < 1e-12) n = (points[i] - centroid).normalized();
    if (n.dot(points[i] - centroid) < 0) n = -n;
    result[i] = n.normalized();
  }
  OrientNormalsConsistently(points, k, &result);
  return result;
}

}  // namespace opgraph
