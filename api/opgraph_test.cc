#include "api/opgraph.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "ops/builders.h"

namespace opgraph {
namespace api {
namespace {

namespace fs = std::filesystem;

// A 4 x 4 x 1 block with a boss on top, as a modeller would build it.
std::string BlockWithBossJson() {
  build::ExtrudeArgs boss;
  boss.faces.normals = {Vec3d::UnitZ()};
  boss.faces.expect = 1;
  boss.height = 0.8;
  boss.width = 0.5;
  return build::Document({build::GlobalScale(Vec3d(2, 2, 0.5)), build::Extrude(boss)}).dump();
}

// A short search: it ends on its work budget, at a point the work done fixes.
RecoverOptions ShortSearch() {
  RecoverOptions options;
  options.work_budget = 3000;
  options.freeform = false;
  return options;
}

TEST(Api, ApplySequenceBuildsTheDocumentsMesh) {
  const Mesh cube = ApplySequence(R"({"operations": []})");
  EXPECT_EQ(cube.vertices.rows(), 8);
  EXPECT_EQ(cube.faces.size(), 6u);
  const Mesh subdivided = ApplySequence(build::Document({build::Subdivision(1)}).dump());
  EXPECT_EQ(subdivided.vertices.rows(), 26);
  EXPECT_EQ(subdivided.faces.size(), 24u);
  const Mesh block = ApplySequence(BlockWithBossJson());
  EXPECT_EQ(block.vertices.rows(), 12);  // the cube's 8 and the extruded top's 4
  EXPECT_DOUBLE_EQ(block.vertices.col(0).maxCoeff(), 2);
  EXPECT_DOUBLE_EQ(block.vertices.col(2).maxCoeff(), 0.5 + 0.8);
}

TEST(Api, BadInputIsAnInvalidArgument) {
  EXPECT_THROW(ApplySequence("{"), std::invalid_argument);
  EXPECT_THROW(ApplySequence(R"({"operations": [{"op": "Smooth"}]})"), std::invalid_argument);
  RecoverOptions options;
  options.work_budget = 0;
  EXPECT_EQ(options.Check(), "work budget must be positive");
  const Target target = Target::FromMesh(ApplySequence(BlockWithBossJson()));
  EXPECT_THROW(RecoverSequence(target, options), std::invalid_argument);
  Eigen::MatrixX3d two_points(2, 3);
  two_points.setZero();
  EXPECT_THROW(Target::FromPoints(two_points), std::invalid_argument);
  const Eigen::MatrixX3d points = target.sample_points();
  EXPECT_THROW(Target::FromPoints(points, points.topRows(5)), std::invalid_argument);
  EXPECT_THROW(Target::FromFile("/nonexistent/shape.obj"), std::runtime_error);
}

TEST(Api, TargetsFromMeshesPointsAndFiles) {
  const Target mesh_target = Target::FromMesh(ApplySequence(BlockWithBossJson()));
  EXPECT_FALSE(mesh_target.is_point_cloud());
  EXPECT_EQ(mesh_target.sample_points().rows(), TargetOptions().num_samples);

  TargetOptions options;
  options.max_cloud_points = 2000;
  const Target cloud = Target::FromPoints(mesh_target.sample_points(), mesh_target.sample_normals(), options);
  EXPECT_TRUE(cloud.is_point_cloud());
  EXPECT_EQ(cloud.shape().vertices.rows(), mesh_target.sample_points().rows());
  EXPECT_EQ(cloud.sample_points().rows(), 2000);
  EXPECT_TRUE(cloud.shape().faces.empty());
  // Normals given are kept (normalised); without them they are estimated.
  const Target estimated = Target::FromPoints(mesh_target.sample_points(), Eigen::MatrixX3d(), options);
  EXPECT_NEAR(estimated.sample_normals().rowwise().norm().minCoeff(), 1, 1e-9);

  const Target barrel = Target::FromFile(OPGRAPH_SOURCE_DIR "/examples/barrel.obj");
  EXPECT_FALSE(barrel.is_point_cloud());
  EXPECT_GT(barrel.shape().faces.size(), 100u);
}

TEST(Api, ConcurrentRecoveriesMatchSequentialOnes) {
  const Target block = Target::FromMesh(ApplySequence(BlockWithBossJson()));
  const Target barrel = Target::FromFile(OPGRAPH_SOURCE_DIR "/examples/barrel.obj");
  const RecoverResult block_alone = RecoverSequence(block, ShortSearch());
  const RecoverResult barrel_alone = RecoverSequence(barrel, ShortSearch());

  RecoverResult block_together, barrel_together;
  std::thread block_thread([&] { block_together = RecoverSequence(block, ShortSearch()); });
  std::thread barrel_thread([&] { barrel_together = RecoverSequence(barrel, ShortSearch()); });
  block_thread.join();
  barrel_thread.join();

  EXPECT_EQ(block_alone.ended_by, "work budget");
  EXPECT_GE(block_alone.num_ops, 1);
  EXPECT_EQ(block_together.sequence_json, block_alone.sequence_json);
  EXPECT_EQ(block_together.decisions, block_alone.decisions);
  EXPECT_EQ(block_together.work, block_alone.work);
  EXPECT_EQ(barrel_together.sequence_json, barrel_alone.sequence_json);
  EXPECT_EQ(barrel_together.decisions, barrel_alone.decisions);
  // The result mesh is the one the sequence builds.
  EXPECT_EQ(block_alone.mesh.vertices, ApplySequence(block_alone.sequence_json).vertices);
}

TEST(Api, ProgressReportsAndCancels) {
  const Target target = Target::FromMesh(ApplySequence(BlockWithBossJson()));
  RecoverOptions options = ShortSearch();
  std::vector<Progress> seen;
  options.on_progress = [&seen](const Progress& progress) {
    seen.push_back(progress);
    return seen.size() < 2;
  };
  const RecoverResult cancelled = RecoverSequence(target, options);
  EXPECT_EQ(cancelled.ended_by, "cancelled");
  ASSERT_GE(seen.size(), 2u);
  EXPECT_EQ(seen[0].stage, "search");
  EXPECT_GT(seen[1].loss, 0);
  EXPECT_GE(seen[1].ops, 1);
  EXPECT_NO_THROW(ApplySequence(cancelled.sequence_json));  // the best so far, whole

  // An exception in the callback ends the search and comes back to the caller.
  options.on_progress = [](const Progress&) -> bool { throw std::logic_error("stop here"); };
  EXPECT_THROW(RecoverSequence(target, options), std::logic_error);
}

TEST(Api, FitSequenceFitsTheParameters) {
  const Target target = Target::FromMesh(ApplySequence(build::Document({build::GlobalScale(Vec3d(2, 1, 0.5))}).dump()));
  FitOptions options;
  options.num_samples = 1000;
  const FitResult fit = FitSequence(build::Document({build::GlobalScale(Vec3d(1.5, 1.5, 1))}).dump(), target, options);
  EXPECT_EQ(fit.num_ops, 1);
  EXPECT_LT(fit.final_loss, 1e-3 * fit.initial_loss);
  EXPECT_NEAR(fit.mesh.vertices.col(0).maxCoeff(), 2, 1e-2);
  EXPECT_NEAR(fit.mesh.vertices.col(2).maxCoeff(), 0.5, 1e-2);
}

TEST(Api, WriteOutputsWritesTheRunsFiles) {
  const fs::path dir = fs::temp_directory_path() / "opgraph_api_write_outputs";
  fs::remove_all(dir);
  WriteOptions options;
  options.name = "block";
  WriteOutputs(BlockWithBossJson(), dir.string(), options);
  for (const char* file : {"result.obj", "result.glb", "rebuild_blender.py", "sequence.json", "steps/01_Extrude.obj"}) {
    EXPECT_GT(fs::file_size(dir / file), 0u) << file;
  }
  std::ifstream script(dir / "rebuild_blender.py");
  std::stringstream text;
  text << script.rdbuf();
  EXPECT_NE(text.str().find("new_object('block'"), std::string::npos);

  // A sequence that does not evaluate writes nothing.
  const fs::path nothing = fs::temp_directory_path() / "opgraph_api_write_nothing";
  fs::remove_all(nothing);
  build::FaceTarget missing;
  missing.normals = {Vec3d::UnitZ()};
  missing.expect = 2;  // the cube has one top face
  EXPECT_THROW(WriteOutputs(build::Document({build::Inset(missing, 0.1)}).dump(), nothing.string()),
               std::runtime_error);
  EXPECT_FALSE(fs::exists(nothing));
  EXPECT_FALSE(Version().empty());
}

}  // namespace
}  // namespace api
}  // namespace opgraph
