// Proposal families on small cages and targets built by known sequences: each family proposes
// the change that built the target (found from the target or the residuals, not from the
// sequence), and every change it proposes gives a sequence the engine evaluates.
#include "search/proposals.h"

#include <gtest/gtest.h>

#include "ops/builders.h"
#include "ops/sequence.h"
#include "search/face_residuals.h"
#include "search/loop_ops.h"
#include "search/pose.h"

namespace opgraph {
namespace {

using build::Axis;

Mesh Build(const std::vector<Json>& ops) {
  Sequence sequence = ParseSequence(build::Document(ops));
  return EvaluateSequence(&sequence).back();
}

std::unique_ptr<Target> MakeTarget(const std::vector<Json>& ops) {
  return std::make_unique<Target>(Build(ops), Positions<double>{}, TargetOptions{});
}

// Applies every alternative of every round to `layout` and checks the result evaluates.
int ExpectAllEvaluate(const Layout& layout, const std::vector<Round>& rounds) {
  int applied = 0;
  for (const Round& round : rounds) {
    for (const Edit& edit : round.alternatives) {
      Layout changed = layout;
      if (edit(&changed).empty()) continue;
      ++applied;
      Sequence sequence = ParseSequence(changed.Document());
      EXPECT_NO_THROW(EvaluateSequence(&sequence)) << changed.Document().dump();
    }
  }
  return applied;
}

TEST(Proposals, ExtrusionOnTheFaceWithTheResidual) {
  // A block with a boss on top, 0.6 high on a 1-high block.
  build::ExtrudeArgs boss;
  boss.faces.normals = {Vec3d::UnitZ()};
  boss.height = 0.6;
  const auto target = MakeTarget({build::GlobalScale(Vec3d(1, 1, 0.5)), build::Extrude(boss)});
  const Layout pose = PoseLayoutOnBox(Eigen::Matrix3d::Identity(), Vec3d(-1, -1, -0.5), Vec3d(1, 1, 0.5));
  const std::vector<Round> rounds = ProposeExtrusions(pose, ComputeFaceResiduals(*target, pose));
  ASSERT_FALSE(rounds.empty());
  Layout first = pose;
  ASSERT_FALSE(rounds[0].alternatives.empty());
  ASSERT_FALSE(rounds[0].alternatives[0](&first).empty());
  ASSERT_EQ(first.details.size(), 1u);
  const Json& extrude = first.details[0];
  EXPECT_EQ(extrude["op"], "Extrude");
  EXPECT_NEAR(extrude["params"]["height"].get<double>(), 0.6, 0.15);
  EXPECT_NEAR(extrude["params"]["faces"]["normal"][2].get<double>(), 1.0, 1e-9);
  EXPECT_GT(ExpectAllEvaluate(pose, rounds), 0);
}

TEST(Proposals, InsetAndExtrudeInAtAThinWalledVesselsMouth) {
  // A deep vessel, walls 0.05 thick: its cavity's samples lie nearer the side faces than the
  // mouth, so only the mouth (no surface in its middle, a floor under it) shows the cavity.
  build::FaceTarget top;
  top.normals = {Vec3d::UnitZ()};
  build::FaceTarget mouth;  // the inset's inner face only
  mouth.centers = {Vec3d(0, 0, 1)};
  mouth.expect = 1;
  build::ExtrudeArgs cavity{mouth, false, -1.6};
  const auto target =
      MakeTarget({build::GlobalScale(Vec3d(0.5, 0.5, 1)), build::Inset(top, 0.05), build::Extrude(cavity)});
  const Layout pose = PoseLayoutOnBox(Eigen::Matrix3d::Identity(), Vec3d(-0.5, -0.5, -1), Vec3d(0.5, 0.5, 1));
  const FaceResiduals residuals = ComputeFaceResiduals(*target, pose);
  int openings = 0;
  for (size_t f = 0; f < residuals.centroids.size(); ++f) {
    if (residuals.opening_depth[f] == 0) continue;
    ++openings;
    EXPECT_NEAR(residuals.normals[f].z(), 1.0, 1e-9);
    EXPECT_NEAR(residuals.opening_depth[f], 1.6, 0.1);
    EXPECT_NEAR(residuals.opening_rim[f], 0.05, 0.03);
  }
  EXPECT_EQ(openings, 1);
  const std::vector<Round> rounds = ProposeExtrusions(pose, residuals);
  ASSERT_FALSE(rounds.empty());
  ASSERT_EQ(rounds[0].alternatives.size(), 2u);  // without and with Subdivision
  Layout first = pose;
  ASSERT_FALSE(rounds[0].alternatives[0](&first).empty());
  ASSERT_EQ(first.details.size(), 2u);
  EXPECT_EQ(first.details[0]["op"], "Inset");
  EXPECT_NEAR(first.details[0]["params"]["thickness"].get<double>(), 0.05, 0.03);
  EXPECT_EQ(first.details[1]["op"], "Extrude");
  EXPECT_NEAR(first.details[1]["params"]["height"].get<double>(), -1.6, 0.1);
  EXPECT_FALSE(first.subdivide);
  Layout smoothed = pose;
  ASSERT_FALSE(rounds[0].alternatives[1](&smoothed).empty());
  EXPECT_TRUE(smoothed.subdivide);
  EXPECT_GT(ExpectAllEvaluate(pose, rounds), 0);
}

TEST(Proposals, NoExtrusionWhereTheCageFits) {
  const auto target = MakeTarget({build::GlobalScale(Vec3d(1, 1, 0.5))});
  const Layout pose = PoseLayoutOnBox(Eigen::Matrix3d::Identity(), Vec3d(-1, -1, -0.5), Vec3d(1, 1, 0.5));
  const FaceResiduals residuals = ComputeFaceResiduals(*target, pose);
  EXPECT_TRUE(ProposeExtrusions(pose, residuals).empty());
  for (double depth : residuals.opening_depth) EXPECT_EQ(depth, 0.0);
}

TEST(Proposals, MirroredPairAcrossItsGap) {
  // Two blocks 1.5 apart along X (a pair), mirrored by the sequence that built them.
  const auto target = MakeTarget({build::GlobalScale(Vec3d(0.5, 1, 0.7)), build::GlobalTranslate(Vec3d(1.25, 0, 0)),
                                  build::Mirror({Axis::kX}), build::GlobalTranslate(Vec3d(3, 1, 0))});
  const Layout pose = PoseLayout(*target, Eigen::Matrix3d::Identity());
  const std::vector<Expansion> pairs = ProposeMirrors(*target, pose);
  ASSERT_EQ(pairs.size(), 1u);
  const Layout& pair = pairs[0].layout;
  EXPECT_EQ(pair.mirror_axes, std::vector<int>{0});
  EXPECT_NEAR(pair.half_extent.x(), 0.5, 0.05);
  EXPECT_NEAR(pair.mirror_offset["params"]["offset"][0].get<double>(), 1.25, 0.05);
  // As placed, before any fit, the pair already covers the target.
  Sequence sequence = ParseSequence(pair.Document());
  const Mesh placed = EvaluateSequence(&sequence).back();
  ASSERT_EQ(placed.NumVertices(), 16);
  for (const Vec3d& p : placed.vertices) {
    double squared = 0;
    target->tree().Nearest(p, &squared);
    EXPECT_LT(std::sqrt(squared), 0.1);
  }
  // A single block has no mirrored pair.
  const auto single = MakeTarget({build::GlobalScale(Vec3d(0.5, 1, 0.7))});
  EXPECT_TRUE(ProposeMirrors(*single, PoseLayout(*single, Eigen::Matrix3d::Identity())).empty());
}

// A slab with thin legs at its corners: a loop-cut grid whose loops are scaled 2.5 (cuts at
// 0.83 of the half extents), the corner faces extruded down.
std::unique_ptr<Target> ThinLeggedTable() {
  build::VertexTarget x_loops, y_loops;
  x_loops.box.lo[0] = -0.5, x_loops.box.hi[0] = 0.5;
  y_loops.box.lo[1] = -0.5, y_loops.box.hi[1] = 0.5;
  build::ExtrudeArgs legs;
  legs.faces.normals = {-Vec3d::UnitZ()};
  legs.faces.centers = {Vec3d(-1.375, -0.915, -0.1), Vec3d(1.375, -0.915, -0.1), Vec3d(-1.375, 0.915, -0.1),
                        Vec3d(1.375, 0.915, -0.1)};
  legs.faces.expect = 4;
  legs.individual = true;
  legs.height = 1.5;
  return MakeTarget({build::LoopCut(Axis::kX, 2, Vec3d::Zero()), build::LoopCut(Axis::kY, 2, Vec3d::Zero()),
                     build::EdgeLoopScale(x_loops, Vec3d(2.5, 1, 1)), build::EdgeLoopScale(y_loops, Vec3d(1, 2.5, 1)),
                     build::GlobalScale(Vec3d(1.5, 1, 0.1)), build::Extrude(legs)});
}

TEST(Proposals, SlabUnderATable) {
  // A top slab with four legs grown from a loop-cut grid.
  build::ExtrudeArgs legs;
  legs.faces.normals = {-Vec3d::UnitZ()};
  legs.faces.centers = {Vec3d(-1, -0.67, -0.1), Vec3d(1, -0.67, -0.1), Vec3d(-1, 0.67, -0.1), Vec3d(1, 0.67, -0.1)};
  legs.faces.expect = 4;
  legs.individual = true;
  legs.height = 1.5;
  const auto target = MakeTarget({build::LoopCut(Axis::kX, 2, Vec3d::Zero()), build::LoopCut(Axis::kY, 2, Vec3d::Zero()),
                                  build::GlobalScale(Vec3d(1.5, 1, 0.1)), build::Extrude(legs)});
  const Layout pose = PoseLayout(*target, Eigen::Matrix3d::Identity());
  const std::vector<Expansion> slabs = ProposeSlabs(*target, pose);
  ASSERT_GE(slabs.size(), 2u);
  EXPECT_NEAR(slabs[0].layout.half_extent.z(), 0.1, 0.03);
  EXPECT_FALSE(slabs[1].layout.grid.empty());
}

// The thin-legged table's slab starts whose grid is placed where the legs start.
std::vector<Expansion> GridsWhereTheLegsStart(const Target& target) {
  std::vector<Expansion> placed;
  for (const Expansion& slab : ProposeSlabs(target, PoseLayout(target, Eigen::Matrix3d::Identity()))) {
    if (slab.what.find("where the parts below start") != std::string::npos) placed.push_back(slab);
  }
  return placed;
}

TEST(Proposals, SlabGridWhereTheLegsStart) {
  // One of the slab's grids places its loops where the legs start.
  const auto target = ThinLeggedTable();
  const std::vector<Expansion> placed = GridsWhereTheLegsStart(*target);
  EXPECT_EQ(placed.size(), 1u);
  for (const Expansion& slab : placed) {
    ASSERT_EQ(slab.layout.grid.size(), 4u);
    // The grid's loop scales (its second and fourth ops), along X and along Y.
    EXPECT_NEAR(slab.layout.grid[1]["params"]["scale"][0].get<double>(), 2.5, 0.15);
    EXPECT_NEAR(slab.layout.grid[3]["params"]["scale"][1].get<double>(), 2.5, 0.15);
    Sequence sequence = ParseSequence(slab.layout.Document());
    EXPECT_NO_THROW(EvaluateSequence(&sequence));
  }
}

TEST(Proposals, LegsExtrudedFromTheFacesTheyStandOn) {
  // On the slab with the grid where the legs start, the legs' inner walls lie over the edges
  // between the corner faces and their neighbours, and their samples go to either face; the
  // legs are the four corner faces, extruded down together.
  const auto target = ThinLeggedTable();
  int legs_alone = 0;
  for (const Expansion& slab : GridsWhereTheLegsStart(*target)) {
    for (const Round& round : ProposeExtrusions(slab.layout, ComputeFaceResiduals(*target, slab.layout))) {
      for (const Edit& edit : round.alternatives) {
        Layout changed = slab.layout;
        if (edit(&changed).empty() || changed.details.size() != slab.layout.details.size() + 1) continue;
        const Json& extrude = changed.details.back();
        if (extrude["op"] != "Extrude" || extrude["params"]["faces"]["expect"] != 4) continue;
        bool corners = true;
        for (const Json& center : extrude["params"]["faces"]["centers"]) {
          corners = corners && std::abs(center[0].get<double>()) > 0.5 && std::abs(center[1].get<double>()) > 0.5;
        }
        if (corners && extrude["params"]["height"].get<double>() > 0) ++legs_alone;
      }
    }
  }
  EXPECT_GE(legs_alone, 1);
}

TEST(Proposals, NoOpeningUnderATablesThinLegs) {
  // The box's bottom face under a table: nothing in its middle and the top above it as a
  // floor, but legs at the corners only, no rim all round: not a vessel's mouth.
  const auto target = ThinLeggedTable();
  const Layout pose = PoseLayoutOnBox(Eigen::Matrix3d::Identity(), Vec3d(-1.5, -1, -1.6), Vec3d(1.5, 1, 0.1));
  for (double depth : ComputeFaceResiduals(*target, pose).opening_depth) EXPECT_EQ(depth, 0.0);
}

TEST(Proposals, BooleanOnTheClusterOfMissingMaterial) {
  // A block with a cylindrical boss on its +X side, off centre (added by a Boolean union).
  build::BooleanArgs boss;
  boss.primitive = build::Primitive::kCylinder;
  boss.size = Vec3d(0.6, 0.6, 1.0);
  boss.rotation_deg = Vec3d(0, 90, 0);  // its axis along X
  boss.location = Vec3d(1.4, 0.3, 0.2);
  const auto target = MakeTarget({build::GlobalScale(Vec3d(1, 0.8, 0.6)), build::Boolean(boss)});
  const Layout pose = PoseLayoutOnBox(Eigen::Matrix3d::Identity(), Vec3d(-1, -0.8, -0.6), Vec3d(1, 0.8, 0.6));
  const std::vector<ResidualCluster> clusters = FindResidualClusters(*target, pose);
  ASSERT_FALSE(clusters.empty());
  EXPECT_FALSE(clusters[0].excess);
  EXPECT_GT(clusters[0].centre.x(), 1.0);
  EXPECT_NEAR(clusters[0].centre.y(), 0.3, 0.15);
  EXPECT_NEAR(clusters[0].centre.z(), 0.2, 0.15);
  const std::vector<Round> rounds = ProposeBooleans(pose, clusters);
  ASSERT_FALSE(rounds.empty());
  EXPECT_EQ(rounds[0].alternatives.size(), 4u);  // a box, a cylinder along each axis
  Layout first = pose;
  ASSERT_FALSE(rounds[0].alternatives[0](&first).empty());
  EXPECT_EQ(first.details.back()["params"]["operation"], "UNION");
  EXPECT_GT(ExpectAllEvaluate(pose, rounds), 0);
}

TEST(Proposals, BooleanDifferenceWhereTheCageHasExcess) {
  // A stepped block (the -X half raised by an extrusion) under the cage of its bounding box: the
  // cage has material the target lacks over the +X half.
  build::ExtrudeArgs step;
  step.faces.normals = {Vec3d::UnitZ()};
  step.faces.box.hi[0] = 0;
  step.height = 0.6;
  const auto target = MakeTarget({build::LoopCut(Axis::kX, 1, Vec3d::Zero()), build::GlobalScale(Vec3d(1, 0.8, 0.3)),
                                  build::Extrude(step)});
  const Layout pose = PoseLayoutOnBox(Eigen::Matrix3d::Identity(), Vec3d(-1, -0.8, -0.3), Vec3d(1, 0.8, 0.9));
  const std::vector<ResidualCluster> clusters = FindResidualClusters(*target, pose);
  ASSERT_FALSE(clusters.empty());
  EXPECT_TRUE(clusters[0].excess);
  EXPECT_NEAR(clusters[0].centre.x(), 0.5, 0.2);
  // In the cage's frame (centred on the pose's box): the excess lies in its upper part.
  EXPECT_GT(clusters[0].centre.z(), 0.0);
  Layout first = pose;
  ASSERT_FALSE(ProposeBooleans(pose, clusters)[0].alternatives[0](&first).empty());
  EXPECT_EQ(first.details.back()["params"]["operation"], "DIFFERENCE");
  // Nothing is cut into a bevelled cage (a modeller bevels last).
  Layout bevelled = pose;
  bevelled.details.push_back(build::Bevel(0.05, 3));
  EXPECT_TRUE(ProposeBooleans(bevelled, clusters).empty());
  EXPECT_TRUE(ProposeFacets(bevelled, ComputeFaceResiduals(*target, bevelled)).empty());
}

TEST(Proposals, LoopMovesOnTheProfileNearTheResidual) {
  // A bar whose upper loop is shifted sideways (a stepped profile).
  build::VertexTarget upper;
  upper.box.lo[2] = 0.2;
  const auto target = MakeTarget({build::LoopCut(Axis::kZ, 2, Vec3d::Zero()), build::EdgeLoopTranslate(upper, Vec3d(0.5, 0, 0)),
                                  build::GlobalScale(Vec3d(0.5, 0.5, 2))});
  Layout profiled = PoseLayoutOnBox(Eigen::Matrix3d::Identity(), Vec3d(-0.5, -0.5, -2), Vec3d(1.0, 0.5, 2));
  ASSERT_FALSE(ProposeProfiles(profiled, Vec3d::Zero())[2].alternatives[0](&profiled).empty());  // x2, each loop scaled
  const std::vector<Round> rounds = ProposeLoopMoves(profiled, ComputeFaceResiduals(*target, profiled));
  ASSERT_FALSE(rounds.empty());
  EXPECT_EQ(ExpectAllEvaluate(profiled, rounds), 5 * static_cast<int>(rounds.size()));  // a shift, four tilts
  // The first rounds replace a loop group's scale: the same ops but one.
  Layout tilted = profiled;
  ASSERT_FALSE(rounds[0].alternatives[1](&tilted).empty());
  EXPECT_EQ(tilted.NumOps(), profiled.NumOps());
  // The rotation acts on the scaled cage (a tilt does not commute with an unequal scale).
  ASSERT_FALSE(tilted.details.empty());
  EXPECT_EQ(tilted.details[0]["op"], "EdgeLoopAffineRotate");
  EXPECT_EQ(tilted.profile.size() + 1, profiled.profile.size());
}

TEST(Proposals, FacetRidgeOnTheFaceBelowIt) {
  // A block whose top face carries a ridge: knifed between two edge midpoints, the cut raised.
  build::FaceTarget top;
  top.normals = {Vec3d::UnitZ()};
  top.expect = 1;
  build::DisplaceGroup ridge{{}, Vec3d(0, 0, 0.5)};
  ridge.verts.box.lo[2] = 0.9, ridge.verts.box.lo[0] = -0.1, ridge.verts.box.hi[0] = 0.1;
  ridge.verts.expect = 2;
  const auto target = MakeTarget({build::KnifeEdges(top, Vec3d(0, -1, 1), Vec3d(0, 1, 1)), build::VertexDisplace({ridge})});
  const Layout pose = PoseLayoutOnBox(Eigen::Matrix3d::Identity(), Vec3d(-1, -1, -1), Vec3d(1, 1, 1));
  const std::vector<Round> rounds = ProposeFacets(pose, ComputeFaceResiduals(*target, pose));
  ASSERT_EQ(rounds.size(), 2u);  // the waists, and the ridge on the top face
  EXPECT_EQ(rounds[0].alternatives.size(), 3u);
  Layout raised = pose;
  ASSERT_FALSE(rounds[1].alternatives[0](&raised).empty());
  EXPECT_EQ(raised.details[0]["op"], "KnifeCut");
  EXPECT_GT(raised.details[1]["params"]["groups"][0]["offset"][2].get<double>(), 0.1);
  EXPECT_EQ(ExpectAllEvaluate(pose, rounds), 5);
}

TEST(Proposals, EveryStructuredFamilyEvaluates) {
  const Layout pose = PoseLayoutOnBox(Eigen::Matrix3d::Identity(), Vec3d(-1, -0.5, -2), Vec3d(1, 0.5, 2));
  EXPECT_EQ(ExpectAllEvaluate(pose, ProposeSmoothing(pose)), 1);
  EXPECT_EQ(ExpectAllEvaluate(pose, ProposeProfiles(pose, Vec3d::Zero())), 14);  // 7 profiles, each also subdivided
  EXPECT_EQ(ExpectAllEvaluate(pose, ProposeDeforms(pose)), 12);   // along the long axis Z
  EXPECT_EQ(ExpectAllEvaluate(pose, ProposeRidges(pose)), 12);    // axis pairs and sides
  EXPECT_EQ(ExpectAllEvaluate(pose, ProposeHoles(pose)), 9);
  EXPECT_EQ(ExpectAllEvaluate(pose, ProposeBevels(pose)), 1);  // the segment rounds need a bevel first
  for (const Expansion& grid : ProposeGrids(pose)) {
    Sequence sequence = ParseSequence(grid.layout.Document());
    EXPECT_NO_THROW(EvaluateSequence(&sequence));
  }
  EXPECT_EQ(ProposeGrids(pose).size(), 3u);
  // Without the Rotate, the Translate, or both: one op fewer each, and the documents say so.
  EXPECT_EQ(ExpectAllEvaluate(pose, ProposePoseDrops(pose)), 3);
  const Round drops = ProposePoseDrops(pose).at(0);
  Layout both = pose;
  ASSERT_FALSE(drops.alternatives.at(2)(&both).empty());
  EXPECT_EQ(both.NumOps(), pose.NumOps() - 2);
  const Json document = both.Document();  // held: a range-for over a member of a temporary reads freed memory
  for (const Json& op : document["operations"]) EXPECT_EQ(op["op"], "GlobalAffineScale");
  EXPECT_TRUE(drops.finishing);
  EXPECT_TRUE(ProposePoseDrops(both).empty());
  // The profile follows the long axis.
  Layout profiled = pose;
  ProposeProfiles(pose, Vec3d::Zero())[0].alternatives[0](&profiled);
  EXPECT_EQ(profiled.profile[0]["params"]["axis"], "Z");
}

TEST(Proposals, LoopCountsOfADeformationsRings) {
  Layout twisted = PoseLayoutOnBox(Eigen::Matrix3d::Identity(), Vec3d(-0.4, -0.3, -1), Vec3d(0.4, 0.3, 1));
  EXPECT_TRUE(ProposeLoopCounts(twisted).empty());  // no profile
  twisted.profile = {build::LoopCut(Axis::kZ, 7, Vec3d::Zero())};
  EXPECT_TRUE(ProposeLoopCounts(twisted).empty());  // rings that nothing uses
  twisted.deforms = {build::SimpleDeform(build::Deform::kTwist, Axis::kZ, 60)};
  const std::vector<Round> rounds = ProposeLoopCounts(twisted);
  ASSERT_EQ(rounds.size(), 1u);
  std::vector<int> counts;
  for (const Edit& edit : rounds[0].alternatives) {
    Layout changed = twisted;
    ASSERT_FALSE(edit(&changed).empty());
    ASSERT_EQ(changed.profile.size(), 1u);
    counts.push_back(changed.profile[0]["params"]["cuts"].get<int>());
    EXPECT_EQ(changed.profile[0]["params"]["axis"], "Z");
  }
  EXPECT_EQ(counts, (std::vector<int>{1, 2, 3, 4, 5, 6, 8, 9, 10, 11, 12}));
  EXPECT_EQ(ExpectAllEvaluate(twisted, rounds), 11);
}

TEST(Proposals, LoopCountsResampleAProfilesScales) {
  Layout turned = PoseLayoutOnBox(Eigen::Matrix3d::Identity(), Vec3d(-0.5, -0.5, -1), Vec3d(0.5, 0.5, 1));
  turned.profile = LoopCutWithScales(2, 2, 4);  // loops at z = -1/3 and 1/3
  turned.profile[1]["params"]["scale"] = ToJson(Vec3d(0.5, 0.5, 1));
  turned.profile[2]["params"]["scale"] = ToJson(Vec3d(0.8, 0.8, 1));
  const std::vector<Round> rounds = ProposeLoopCounts(turned);
  ASSERT_EQ(rounds.size(), 1u);
  ASSERT_EQ(rounds[0].alternatives.size(), 7u);  // 1, 3, ..., 8
  Layout three = turned;
  ASSERT_FALSE(rounds[0].alternatives[1](&three).empty());
  ASSERT_EQ(three.profile.size(), 4u);
  EXPECT_EQ(three.profile[0]["params"]["cuts"], 3);
  // Loops at z = -1/2, 0, 1/2: between the end face (1) and the first loop, between the loops,
  // between the last loop and the other end face.
  const double expected[] = {1 + (0.5 - 1) * 0.75, 0.65, 0.8 + (1 - 0.8) * 0.25};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(three.profile[k + 1]["params"]["scale"][0].get<double>(), expected[k], 1e-12) << k;
    EXPECT_NEAR(three.profile[k + 1]["params"]["scale"][2].get<double>(), 1.0, 1e-12) << k;
  }
  EXPECT_EQ(ExpectAllEvaluate(turned, rounds), 7);
  // Grouped scales are another profile family: no count to change.
  turned.profile = LoopCutWithScales(2, 2, 4, {{0, 1}});
  EXPECT_TRUE(ProposeLoopCounts(turned).empty());
}

}  // namespace
}  // namespace opgraph
