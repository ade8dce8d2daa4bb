// Embedding opgraph in a reconstruction pipeline: a PCL point cloud in memory in, a design
// sequence out, through the entry header api/opgraph.h. Here the cloud is a scan-like sampling of
// a box with a boss on top (in a pipeline it comes from your scanner or reconstruction); pass a
// .pcd path to use your own.
//
//   build/embed_point_cloud [cloud.pcd] [out_dir]
#include <pcl/common/point_tests.h>
#include <pcl/io/pcd_io.h>

#include <iostream>
#include <random>

#include "api/opgraph.h"

int main(int argc, char** argv) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  if (argc > 1) {
    if (pcl::io::loadPCDFile(argv[1], cloud) < 0) {
      std::cerr << "embed_point_cloud: cannot read " << argv[1] << "\n";
      return 2;
    }
  } else {
    // 20,000 points on a 4 x 2 x 1 box (in millimetres, off the origin) with a 1 x 1 x 0.6 boss.
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0, 1);
    std::normal_distribution<float> noise(0, 0.002f);
    auto box_surface_point = [&](float sx, float sy, float sz) {
      // A random point on a box's surface, area-weighted by face.
      const float areas[3] = {sy * sz, sx * sz, sx * sy};
      const float pick = u(rng) * (areas[0] + areas[1] + areas[2]);
      const int axis = pick < areas[0] ? 0 : (pick < areas[0] + areas[1] ? 1 : 2);
      float p[3] = {(u(rng) - 0.5f) * sx, (u(rng) - 0.5f) * sy, (u(rng) - 0.5f) * sz};
      const float half[3] = {sx / 2, sy / 2, sz / 2};
      p[axis] = u(rng) < 0.5f ? -half[axis] : half[axis];
      return pcl::PointXYZ(p[0], p[1], p[2]);
    };
    for (int i = 0; i < 20000; ++i) {
      pcl::PointXYZ p = i % 5 ? box_surface_point(40, 20, 10) : box_surface_point(10, 10, 6);
      if (i % 5 == 0) {
        if (p.z < -2.9f) continue;  // the boss's bottom is inside the box
        p.z += 8;
      } else if (p.z > 4.9f && std::abs(p.x) < 5 && std::abs(p.y) < 5) {
        continue;  // the box's top under the boss
      }
      cloud.push_back(pcl::PointXYZ(p.x + 100 + noise(rng), p.y + 50 + noise(rng), p.z + noise(rng)));
    }
  }

  // #P by 3, the finite points (a scan's cloud may hold NaNs); no normals: they are estimated.
  Eigen::MatrixX3d points(cloud.size(), 3);
  Eigen::Index count = 0;
  for (const pcl::PointXYZ& p : cloud) {
    if (pcl::isFinite(p)) points.row(count++) << p.x, p.y, p.z;
  }
  points.conservativeResize(count, 3);
  const opgraph::api::Target target = opgraph::api::Target::FromPoints(points);
  opgraph::api::RecoverOptions options;
  options.work_budget = 60000;  // a short search (the default is 500,000 work units)
  options.on_progress = [](const opgraph::api::Progress& progress) {
    if (!progress.decision.empty()) std::cout << progress.decision << "\n";
    return true;
  };
  const opgraph::api::RecoverResult result = opgraph::api::RecoverSequence(target, options);

  std::cout << result.sequence_json;
  if (argc > 2) {
    opgraph::api::WriteOptions write;
    write.comment = "opgraph embed_point_cloud result";
    opgraph::api::WriteOutputs(result.sequence_json, argv[2], write);
  }
  return 0;
}
