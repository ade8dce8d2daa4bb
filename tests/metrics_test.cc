// Metrics against hand-computed values on small shapes; sampling and closest-point queries.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/cloud_surface.h"
#include "core/metrics.h"
#include "core/nearest.h"
#include "io/read_input.h"
#include "ops/sequence.h"

namespace opgraph {
namespace {

Mesh Square(double z, double side = 1.0) {
  Mesh m;
  m.vertices = {{0, 0, z}, {side, 0, z}, {side, side, z}, {0, side, z}};
  m.faces = {{0, 1, 2, 3}};
  return m;
}

TEST(Metrics, ParallelSquaresAtKnownOffset) {
  // Target: unit square (its box's longest side is 1, so no rescaling); output 0.015 above.
  const ShapeMetrics m = ComputeShapeMetrics(Square(0.015), Square(0.0));
  EXPECT_NEAR(m.chamfer.output_to_target, 0.015, 1e-12);
  EXPECT_NEAR(m.chamfer.target_to_output, 0.015, 1e-12);
  EXPECT_NEAR(m.chamfer.Sum(), 0.03, 1e-12);
  EXPECT_NEAR(m.chamfer_squared.Sum(), 2 * 0.015 * 0.015, 1e-12);
  EXPECT_NEAR(m.normal_consistency, 1.0, 1e-12);
  EXPECT_EQ(m.f1_001, 0.0);
  EXPECT_EQ(m.f1_002, 1.0);
  // Nearest samples are at least the offset apart, plus in-plane sampling noise.
  EXPECT_GE(m.sample_chamfer, 2 * 0.015 * 0.015);
  EXPECT_LT(m.sample_chamfer, 2 * 0.015 * 0.015 + 2e-4);
}

TEST(Metrics, ScaleInvariantOnTargetBox) {
  // The same configuration ten times larger gives the same numbers.
  Mesh out = Square(0.15, 10), target = Square(0, 10);
  const ShapeMetrics m = ComputeShapeMetrics(out, target);
  EXPECT_NEAR(m.chamfer.Sum(), 0.03, 1e-12);
}

TEST(Metrics, CubeInsideLargerCube) {
  // Target cube of side 2.2 (unit box: side 1), output cube of side 2 (side 1 / 1.1) at the same
  // centre: every output point is exactly (1 - 1/1.1) / 2 = 1/22 from the target surface.
  const ShapeMetrics m = ComputeShapeMetrics(MakeCube(2.0), MakeCube(2.2));
  EXPECT_NEAR(m.chamfer.output_to_target, 1.0 / 22, 1e-12);
  EXPECT_NEAR(m.chamfer_squared.output_to_target, 1.0 / (22 * 22), 1e-12);
  // Target points are at least 1/22 from the smaller cube and at most sqrt(3)/22.
  EXPECT_GT(m.chamfer.target_to_output, 1.0 / 22);
  EXPECT_LT(m.chamfer.target_to_output, std::sqrt(3.0) / 22);
  // Output->target: the parallel face is always nearest (normals agree). Target points over the
  // inner cube's edges and corners are nearest to an edge, and may pick the other face there.
  EXPECT_LT(m.normal_consistency, 1.0);
  EXPECT_GT(m.normal_consistency, 0.9);
  EXPECT_EQ(m.f1_002, 0.0);
}

TEST(Metrics, IdenticalShapesHaveZeroPointToSurfaceDistance) {
  const ShapeMetrics m = ComputeShapeMetrics(MakeCube(2.0), MakeCube(2.0));
  EXPECT_LT(m.chamfer.Sum(), 1e-12);
  EXPECT_EQ(m.f1_001, 1.0);
  // The sample-to-sample floor is not zero: two independent sample sets.
  const double floor = SamplingNoiseFloor(MakeCube(2.0));
  EXPECT_GT(floor, 1e-3);
  EXPECT_LT(floor, 0.05);
}

TEST(Metrics, PointCloudTarget) {
  // Target = the 8 corners of the unit cube (as a cloud); output = the same cube's surface.
  Mesh cloud = MakeCube(1.0);
  cloud.faces.clear();
  const ShapeMetrics m = ComputeShapeMetrics(MakeCube(1.0), cloud);
  EXPECT_TRUE(std::isnan(m.normal_consistency));
  EXPECT_NEAR(m.chamfer.target_to_output, 0.0, 1e-12);  // the corners lie on the surface
  // Each face's nearest corner is one of its own: the mean distance from a uniform point of a
  // square of side 1/2 to a corner, (1/2) (sqrt(2) + asinh(1)) / 3.
  const double expected = 0.5 * (std::sqrt(2.0) + std::asinh(1.0)) / 3.0;
  EXPECT_NEAR(m.chamfer.output_to_target, expected, 0.005);
}

// `count` area-weighted samples of `shape` as a cloud (no faces), with the faces' normals.
Mesh SampledCloud(const Mesh& shape, int count, Positions<double>* normals) {
  const SurfaceSamples samples = SampleSurface(shape.vertices, FanTriangulate(shape.faces), count, 7);
  Mesh cloud;
  cloud.vertices = samples.points;
  *normals = samples.normals;
  return cloud;
}

TEST(Metrics, CloudWithNormalsIsJudgedAgainstItsSurface) {
  // A 20k-point cloud of a cube: distances to the nearest point carry a floor of about half the
  // spacing; distances to the surface the cloud samples match the exact point-to-surface
  // distances to the cube itself.
  Positions<double> normals;
  const Mesh cloud = SampledCloud(MakeCube(2.0), 20000, &normals);
  for (const double side : {2.0, 2.04, 1.9}) {
    const ShapeMetrics exact = ComputeShapeMetrics(MakeCube(side), MakeCube(2.0));
    const ShapeMetrics nearest_point = ComputeShapeMetrics(MakeCube(side), cloud);
    const ShapeMetrics surface = ComputeShapeMetrics(MakeCube(side), cloud, normals);
    EXPECT_NEAR(surface.chamfer.output_to_target, exact.chamfer.output_to_target, 3e-4) << side;
    // The floor shows where the fit is close (far off, the offset dominates the nearest point's).
    if (side == 2.0) EXPECT_GT(nearest_point.chamfer.output_to_target, 2e-3);
    EXPECT_EQ(surface.chamfer.target_to_output, nearest_point.chamfer.target_to_output) << side;
  }
  // Estimated normals (PCL, 16 neighbours) as for a cloud read without them.
  const ShapeMetrics exact = ComputeShapeMetrics(MakeCube(2.04), MakeCube(2.0));
  const ShapeMetrics estimated = ComputeShapeMetrics(MakeCube(2.04), cloud, EstimatePointNormals(cloud.vertices, 16));
  EXPECT_NEAR(estimated.chamfer.output_to_target, exact.chamfer.output_to_target, 1e-3);
}

TEST(Metrics, CloudSurfaceEndsAtTheCloudsEdge) {
  // Output: a square of side 2 over a cloud of the unit square. Its part past the cloud is as far
  // from the cloud's surface as from the square itself (the exact reference), up to the spacing.
  Positions<double> normals;
  const Mesh cloud = SampledCloud(Square(0.0), 20000, &normals);
  const ShapeMetrics exact = ComputeShapeMetrics(Square(0.0, 2.0), Square(0.0));
  const ShapeMetrics surface = ComputeShapeMetrics(Square(0.0, 2.0), cloud, normals);
  EXPECT_GT(exact.chamfer.output_to_target, 0.3);
  EXPECT_NEAR(surface.chamfer.output_to_target, exact.chamfer.output_to_target, 0.02);
  const CloudSurface surface_of_cloud(cloud.vertices, normals);
  EXPECT_NEAR(surface_of_cloud.Distance(Vec3d(0.5, 0.5, 0.01)), 0.01, 1e-9);  // over the square
  EXPECT_NEAR(surface_of_cloud.Distance(Vec3d(1.5, 0.5, 0.0)), 0.5, 0.03);   // beside it
}

TEST(Metrics, Wiring) {
  const WiringMetrics cube = ComputeWiringMetrics(MakeCube(2.0));
  EXPECT_EQ(cube.valence4_fraction, 0.0);
  EXPECT_EQ(cube.quad_fraction, 1.0);
  EXPECT_NEAR(cube.face_area_cv, 0.0, 1e-12);

  // Catmull-Clark level 1 of the cube: 26 vertices, the 8 corners keep valence 3.
  Sequence sequence = ParseSequence(Json::parse(R"({"operations": [{"op": "Subdivision", "params": {"levels": 1}}]})"));
  const Mesh subdivided = EvaluateSequence(&sequence).back();
  const WiringMetrics sub = ComputeWiringMetrics(subdivided);
  EXPECT_NEAR(sub.valence4_fraction, 18.0 / 26.0, 1e-12);
  EXPECT_EQ(sub.quad_fraction, 1.0);

  // Two separate faces of areas 1 and 3 (a quad and a triangle): mean 2, deviation 1.
  Mesh two;
  two.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {3, 0, 1}, {0, 2, 1}};
  two.faces = {{0, 1, 2, 3}, {4, 5, 6}};
  const WiringMetrics w = ComputeWiringMetrics(two);
  EXPECT_NEAR(w.face_area_cv, 0.5, 1e-12);
  EXPECT_EQ(w.quad_fraction, 0.5);
  EXPECT_EQ(w.valence4_fraction, 0.0);
}

TEST(Sampling, SeededAreaWeightedOnSurface) {
  Mesh two;
  two.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {3, 0, 1}, {3, 1, 1}, {0, 1, 1}};
  two.faces = {{0, 1, 2, 3}, {4, 5, 6, 7}};
  const std::vector<MeshTriangle> triangles = FanTriangulate(two.faces);
  const SurfaceSamples a = SampleSurface(two.vertices, triangles, 20000, 5);
  const SurfaceSamples b = SampleSurface(two.vertices, triangles, 20000, 5);
  ASSERT_EQ(a.points.size(), 20000u);
  int upper = 0;
  for (size_t i = 0; i < a.points.size(); ++i) {
    EXPECT_EQ(a.points[i], b.points[i]);
    const MeshTriangle& t = triangles[a.triangles[i]];
    const Vec3d rebuilt = a.barycentrics[i][0] * two.vertices[t.v[0]] + a.barycentrics[i][1] * two.vertices[t.v[1]] +
                          a.barycentrics[i][2] * two.vertices[t.v[2]];
    EXPECT_LT((rebuilt - a.points[i]).norm(), 1e-12);
    EXPECT_NEAR(std::abs(a.normals[i].z()), 1.0, 1e-12);
    upper += a.points[i].z() > 0.5;
  }
  // Areas 1 and 3: three quarters of the samples on the upper face (binomial sd ~0.003).
  EXPECT_NEAR(upper / 20000.0, 0.75, 0.015);
}

TEST(Nearest, ClosestPointsMatchBruteForce) {
  Sequence sequence = ParseSequence(Json::parse(
      R"({"operations": [{"op": "SimpleDeformTwist", "params": {"axis": "Z", "angle_deg": 60}},
                         {"op": "Subdivision", "params": {"levels": 2}}]})"));
  const Mesh mesh = EvaluateSequence(&sequence).back();
  const std::vector<MeshTriangle> triangles = FanTriangulate(mesh.faces);
  const TriangleTree tree(mesh.vertices, triangles);
  std::mt19937_64 rng(3);
  for (int q = 0; q < 200; ++q) {
    const Vec3d p(4 * UnitRandom(rng()) - 2, 4 * UnitRandom(rng()) - 2, 4 * UnitRandom(rng()) - 2);
    double best = 1e300;
    for (const MeshTriangle& t : triangles) {
      best = std::min(best, ClosestPointOnTriangle(p, mesh.vertices[t.v[0]], mesh.vertices[t.v[1]], mesh.vertices[t.v[2]])
                                .squared_distance);
    }
    const ClosestPoint c = tree.Closest(p);
    EXPECT_NEAR(c.squared_distance, best, 1e-12);
    EXPECT_NEAR((c.point - p).squaredNorm(), best, 1e-12);
  }
}

}  // namespace
}  // namespace opgraph
