#include "solver/fit_correspondences.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "core/nearest.h"
#include "ops/extrude.h"

namespace opgraph {

namespace {

SurfaceCorrespondence CorrespondenceOnTriangle(const MeshTriangle& triangle, const Vec3d& barycentric,
                                               const Vec3d& target_point, const Vec3d& target_normal) {
  SurfaceCorrespondence c;
  for (int k = 0; k < 3; ++k) c.vertices[k] = triangle.v[k], c.weights[k] = barycentric[k];
  c.target_point = target_point;
  c.target_normal = target_normal;
  return c;
}

void BuildMixedCorrespondences(const Program& program, const Target& target, const FitterOptions& options,
                               uint64_t seed, MixedBranchTerms* out) {
  const Positions<double>& positions = program.positions();
  const int num_options = program.blocks()[program.MixedBranchBlock()].size;
  std::vector<std::vector<MeshTriangle>> triangles(num_options);
  for (const MeshTriangle& t : FanTriangulate(program.faces())) triangles[program.face_options()[t.face]].push_back(t);
  const int num_target = std::min<int>(options.num_target_samples, static_cast<int>(target.points().size()));
  out->block = program.MixedBranchBlock();
  for (int k = 0; k < num_options; ++k) {
    if (options.output_to_target_weight > 0) {
      const SurfaceSamples samples = SampleSurface(positions, triangles[k], options.num_output_samples, seed);
      for (size_t i = 0; i < samples.points.size(); ++i) {
        const int nearest = target.tree().Nearest(samples.points[i], nullptr);
        out->forward.push_back(CorrespondenceOnTriangle(triangles[k][samples.triangles[i]], samples.barycentrics[i],
                                                        target.points()[nearest], target.normals()[nearest]));
        out->forward_option.push_back(k);
      }
    }
    if (options.target_to_output_weight > 0 && num_target > 0) {
      const TriangleTree tree(positions, triangles[k]);
      for (int i = 0; i < num_target; ++i) {
        const ClosestPoint closest = tree.Closest(target.points()[i]);
        if (closest.triangle < 0) continue;
        out->backward.push_back(CorrespondenceOnTriangle(triangles[k][closest.triangle], closest.barycentric,
                                                         target.points()[i], target.normals()[i]));
        out->backward_option.push_back(k);
      }
    }
  }
  out->forward_weight = target.scale() * std::sqrt(options.output_to_target_weight / std::max(1, options.num_output_samples));
  out->backward_weight = target.scale() * std::sqrt(options.target_to_output_weight / std::max(1, num_target));
}

}  // namespace

void BuildFitCorrespondences(Program* program, const Sequence& sequence, const Target& target,
                             const FitterOptions& options, uint64_t seed, FitCorrespondences* out) {
  program->EvaluateValues();
  const Positions<double>& positions = program->positions();
  const std::vector<MeshTriangle> triangles = FanTriangulate(program->faces());
  out->output_to_target.clear();
  out->target_to_output.clear();
  out->boolean = BooleanWeightTerms();
  out->mixed = MixedBranchTerms();
  if (program->MixedBranchBlock() >= 0) {
    BuildMixedCorrespondences(*program, target, options, seed, &out->mixed);
    return;
  }
  const int last_op = static_cast<int>(sequence.ops.size()) - 1;
  out->boolean.beta_block = last_op >= 0 ? program->BooleanWeightBlock(last_op) : -1;
  const int first_extruded = out->boolean.beta_block >= 0
                                 ? static_cast<const ExtrudeOp&>(*sequence.ops[last_op]).first_created_face()
                                 : std::numeric_limits<int>::max();
  const double scale = target.scale();
  const VirtualSurface boolean_surface =
      out->boolean.beta_block >= 0 ? BooleanSurface(*program, last_op) : VirtualSurface();
  if (options.output_to_target_weight > 0 && out->boolean.beta_block >= 0) {
    // B's own faces, sampled at the output's density (solver/boolean_weight.h).
    std::vector<MeshTriangle> own;
    for (const MeshTriangle& t : boolean_surface.triangles) {
      if (t.face >= boolean_surface.first_own_face) own.push_back(t);
    }
    auto area = [](const Positions<double>& p, const std::vector<MeshTriangle>& list) {
      double sum = 0;
      for (const MeshTriangle& t : list) sum += 0.5 * (p[t.v[1]] - p[t.v[0]]).cross(p[t.v[2]] - p[t.v[0]]).norm();
      return sum;
    };
    const double output_area = area(positions, triangles);
    const int count = output_area > 0 ? static_cast<int>(std::lround(options.num_output_samples *
                                                                      area(boolean_surface.positions, own) / output_area))
                                      : 0;
    const SurfaceSamples samples = SampleSurface(boolean_surface.positions, own, count, seed + 1);
    std::vector<int> own_index;  // own triangle -> index in boolean_surface.triangles
    for (size_t t = 0; t < boolean_surface.triangles.size(); ++t) {
      if (boolean_surface.triangles[t].face >= boolean_surface.first_own_face) own_index.push_back(static_cast<int>(t));
    }
    for (size_t i = 0; i < samples.points.size(); ++i) {
      const int nearest = target.tree().Nearest(samples.points[i], nullptr);
      out->boolean.boolean_to_target.push_back(CorrespondenceOnSurface(boolean_surface, own_index[samples.triangles[i]],
                                                                       samples.barycentrics[i], target.points()[nearest],
                                                                       target.normals()[nearest]));
    }
  }
  if (options.output_to_target_weight > 0) {
    const SurfaceSamples samples = SampleSurface(positions, triangles, options.num_output_samples, seed);
    for (size_t i = 0; i < samples.points.size(); ++i) {
      SurfaceCorrespondence c;
      const MeshTriangle& t = triangles[samples.triangles[i]];
      for (int k = 0; k < 3; ++k) c.vertices[k] = t.v[k], c.weights[k] = samples.barycentrics[i][k];
      const int nearest = target.tree().Nearest(samples.points[i], nullptr);
      c.target_point = target.points()[nearest];
      c.target_normal = target.normals()[nearest];
      out->output_to_target.push_back(c);
      out->boolean.on_extrusion.push_back(t.face >= first_extruded);
    }
    out->output_to_target_weight =
        scale * std::sqrt(options.output_to_target_weight / std::max<size_t>(1, out->output_to_target.size()));
  }
  const int num_target = std::min<int>(options.num_target_samples, static_cast<int>(target.points().size()));
  if (options.target_to_output_weight > 0 && num_target > 0) {
    const TriangleTree tree(positions, triangles);
    std::unique_ptr<TriangleTree> boolean_tree;
    if (out->boolean.beta_block >= 0) {
      boolean_tree = std::make_unique<TriangleTree>(boolean_surface.positions, boolean_surface.triangles);
    }
    for (int i = 0; i < num_target; ++i) {
      if (out->boolean.beta_block >= 0) {
        const ClosestPoint on_boolean = boolean_tree->Closest(target.points()[i]);
        if (on_boolean.triangle >= 0) {
          out->boolean.target_to_boolean.push_back(
              CorrespondenceOnSurface(boolean_surface, on_boolean.triangle, on_boolean.barycentric, target.points()[i],
                                      target.normals()[i]));
        }
      }
      const ClosestPoint closest = tree.Closest(target.points()[i]);
      if (closest.triangle < 0) continue;
      SurfaceCorrespondence c;
      const MeshTriangle& t = triangles[closest.triangle];
      for (int k = 0; k < 3; ++k) c.vertices[k] = t.v[k], c.weights[k] = closest.barycentric[k];
      c.target_point = target.points()[i];
      c.target_normal = target.normals()[i];
      out->target_to_output.push_back(c);
    }
    out->target_to_output_weight =
        scale * std::sqrt(options.target_to_output_weight / std::max<size_t>(1, out->target_to_output.size()));
  }
}

}  // namespace opgraph
