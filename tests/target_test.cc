// Target loading (through io/read_input): unit-box transform, samples on the surface with outward normals,
// estimated cloud normals, and one-line errors on bad files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/metrics.h"
#include "core/nearest.h"
#include "core/obj_io.h"
#include "solver/target.h"

namespace opgraph {
namespace {

namespace fs = std::filesystem;

std::string TempFile(const std::string& name, const std::string& contents) {
  const fs::path path = fs::temp_directory_path() / ("opgraph_target_test_" + name);
  std::ofstream(path) << contents;
  return path.string();
}

TEST(Target, ObjMeshSamplesLieOnTheSurfaceWithOutwardNormals) {
  Mesh box = MakeCube(2.0);
  for (Vec3d& v : box.vertices) v = Vec3d(v.x() * 3 + 10, v.y(), v.z() * 0.5);  // 6 x 2 x 1 at (10, 0, 0)
  const std::string path = (fs::temp_directory_path() / "opgraph_target_test_box.obj").string();
  WriteObj(box, path);
  TargetOptions options;
  options.num_samples = 2000;
  const std::unique_ptr<Target> target = LoadTarget(path, options);
  EXPECT_FALSE(target->is_cloud());
  EXPECT_NEAR((target->centre() - Vec3d(10, 0, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR(target->scale(), 1.0 / 6, 1e-12);
  ASSERT_EQ(target->points().size(), 2000u);
  for (size_t i = 0; i < target->points().size(); ++i) {
    const Vec3d local = (target->points()[i] - Vec3d(10, 0, 0)).cwiseQuotient(Vec3d(3, 1, 0.5));
    EXPECT_NEAR(local.cwiseAbs().maxCoeff(), 1.0, 1e-9);  // on the box
    EXPECT_GT(target->normals()[i].dot(local), 0.0);     // outward
  }
  double squared;
  EXPECT_EQ(target->tree().Nearest(target->points()[17], &squared), 17);
  EXPECT_EQ(squared, 0.0);
}

TEST(Target, XyzCloudGetsPlaneNormals) {
  std::string text;
  for (int i = 0; i < 30; ++i) {
    for (int j = 0; j < 30; ++j) text += std::to_string(i * 0.1) + " " + std::to_string(j * 0.1) + " 2.5\n";
  }
  const std::unique_ptr<Target> target = LoadTarget(TempFile("plane.xyz", text), TargetOptions());
  EXPECT_TRUE(target->is_cloud());
  ASSERT_EQ(target->points().size(), 900u);
  for (const Vec3d& n : target->normals()) EXPECT_NEAR(std::abs(n.z()), 1.0, 1e-9);
}

TEST(Target, BadFilesFailWithOneLine) {
  const struct {
    std::string name, contents, expected;
  } cases[] = {
      {"bad.xyz", "1 2 3\n4 5\n", "bad.xyz"},
      {"few.xyz", "1 2 3\n4 5 6\n7 8 1\n", "fewer than 4 points"},
      {"same.xyz", "1 2 3\n1 2 3\n1 2 3\n1 2 3\n", "same.xyz"},
  };
  for (const auto& c : cases) {
    try {
      LoadTarget(TempFile(c.name, c.contents), TargetOptions());
      ADD_FAILURE() << c.name << ": no error";
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(c.expected), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
  EXPECT_THROW(LoadTarget("/nonexistent/target.obj", TargetOptions()), std::runtime_error);
}

TEST(Target, CloudMetricsUseTheSurfaceBuiltOnce) {
  // A cloud far from the unit box (side 20, centred at (100, -50, 3)): the target's surface,
  // built once in the input frame, gives the metrics of a surface built in the unit box for the
  // call, and the exact point-to-surface distance to the cube it samples.
  Mesh cube = MakeCube(20.0);
  for (Vec3d& v : cube.vertices) v += Vec3d(100, -50, 3);
  const SurfaceSamples samples = SampleSurface(cube.vertices, FanTriangulate(cube.faces), 20000, 3);
  Mesh cloud;
  cloud.vertices = samples.points;
  TargetOptions options;
  const Target target(cloud, samples.normals, options);
  ASSERT_NE(target.cloud_surface(), nullptr);
  Mesh larger = MakeCube(20.4);
  for (Vec3d& v : larger.vertices) v += Vec3d(100, -50, 3);
  MetricsOptions metrics_options;
  metrics_options.num_samples = 3000;
  const ShapeMetrics cached = ComputeTargetMetrics(larger, target, metrics_options);
  Mesh target_points;
  target_points.vertices = target.points();
  const ShapeMetrics fresh = ComputeShapeMetrics(larger, target_points, target.normals(), metrics_options);
  EXPECT_NEAR(cached.chamfer.output_to_target, fresh.chamfer.output_to_target, 1e-12);
  EXPECT_EQ(cached.chamfer.target_to_output, fresh.chamfer.target_to_output);
  const ShapeMetrics exact = ComputeShapeMetrics(larger, cube, metrics_options);
  EXPECT_NEAR(cached.chamfer.output_to_target, exact.chamfer.output_to_target, 3e-4);
  EXPECT_GT(cached.chamfer.output_to_target, 5e-3);  // the offset (0.01 of the unit box) shows
}

}  // namespace
}  // namespace opgraph
