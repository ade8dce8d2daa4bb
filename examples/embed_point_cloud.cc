// Embedding opgraph in a reconstruction pipeline: a PCL point cloud in memory in, a design
// sequence out. Here the cloud is a scan-like sampling of a box with a boss on top (in a
// pipeline it comes from your scanner or reconstruction); pass a .pcd path to use your own.
//
//   build/embed_point_cloud [cloud.pcd] [out_dir]
#include <pcl/io/pcd_io.h>

#include <iostream>
#include <random>

#include "io/pcl_cloud.h"
#include "io/sequence_outputs.h"
#include "solver/target.h"
#include "search/zero_shot.h"

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

  opgraph::InputGeometry input = opgraph::InputFromPclCloud(cloud);
  opgraph::TargetOptions target_options;
  const opgraph::Target target(input.mesh, input.normals, target_options);  // normals estimated if absent
  opgraph::ZeroShotOptions options;
  options.work_budget = 60000;  // a short search (the default is 500,000 work units)
  options.progress = &std::cout;
  const opgraph::ZeroShotResult result = opgraph::RecoverSequence(target, options);

  std::cout << result.sequence.dump(1) << "\n";
  if (argc > 2) {
    opgraph::Sequence sequence = opgraph::ParseSequence(result.sequence);
    opgraph::WriteSequenceOutputs(opgraph::RenderSequenceOutputs(&sequence), argv[2], /*write_steps=*/true,
                                  "opgraph embed_point_cloud result");
  }
  return 0;
}
