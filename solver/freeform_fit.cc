#include "solver/freeform_fit.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/deadline.h"
#include "core/nearest.h"
#include "residuals/displacement_cost.h"

namespace opgraph {
namespace {

// A point of the output's triangle `triangle` at `barycentric`, as base + sum_j A_j d_j.
struct LinearPoint {
  Vec3d base = Vec3d::Zero();
  std::vector<LinearPointCost::Term> terms;
};

LinearPoint PointOnTriangle(const AffineTail& tail, const Positions<double>& undisplaced, const MeshTriangle& triangle,
                            const Vec3d& barycentric) {
  LinearPoint point;
  std::map<int, Eigen::Matrix3d> merged;
  for (int k = 0; k < 3; ++k) {
    const int o = triangle.v[k];
    point.base += barycentric[k] * undisplaced[o];
    for (const AffineTail::Term& term : tail.terms[o]) {
      auto [it, inserted] = merged.emplace(term.vertex, Eigen::Matrix3d::Zero());
      it->second += barycentric[k] * term.matrix;
    }
  }
  for (const auto& [vertex, matrix] : merged) point.terms.push_back({vertex, matrix});
  return point;
}

struct Correspondence {
  LinearPoint point;
  Vec3d target_point, target_normal;
  bool forward;  // output sample to its nearest target sample (else target sample to output)
};

std::vector<Correspondence> FindCorrespondences(const Target& target, const AffineTail& tail,
                                                const Positions<double>& undisplaced, const Positions<double>& positions,
                                                const std::vector<MeshTriangle>& triangles, const FreeformOptions& options,
                                                uint64_t seed) {
  std::vector<Correspondence> out;
  const SurfaceSamples samples = SampleSurface(positions, triangles, options.num_output_samples, seed);
  for (size_t i = 0; i < samples.points.size(); ++i) {
    const int nearest = target.tree().Nearest(samples.points[i], nullptr);
    out.push_back({PointOnTriangle(tail, undisplaced, triangles[samples.triangles[i]], samples.barycentrics[i]),
                   target.points()[nearest], target.normals()[nearest], true});
  }
  const TriangleTree tree(positions, triangles);
  const int num_target = std::min<int>(options.num_target_samples, static_cast<int>(target.points().size()));
  for (int i = 0; i < num_target; ++i) {
    const ClosestPoint closest = tree.Closest(target.points()[i]);
    if (closest.triangle < 0) continue;
    out.push_back({PointOnTriangle(tail, undisplaced, triangles[closest.triangle], closest.barycentric),
                   target.points()[i], target.normals()[i], false});
  }
  return out;
}

// The cage's edges, each once.
std::vector<std::pair<int, int>> CageEdges(const Mesh& cage) {
  std::set<std::pair<int, int>> edges;
  for (const Polygon& face : cage.faces) {
    for (size_t k = 0; k < face.size(); ++k) {
      const int a = face[k], b = face[(k + 1) % face.size()];
      edges.emplace(std::min(a, b), std::max(a, b));
    }
  }
  return {edges.begin(), edges.end()};
}

// The data loss at the current displacements `d`: the sum of squared Chamfer residuals, as the
// fitter's objective (mean squared distances in the unit box, both directions).
double DataLoss(const std::vector<Correspondence>& correspondences, const std::vector<double>& d, const Target& target,
                const FreeformOptions& options) {
  size_t num_forward = 0;
  for (const Correspondence& c : correspondences) num_forward += c.forward ? 1 : 0;
  const size_t num_backward = correspondences.size() - num_forward;
  double loss = 0;
  for (const Correspondence& c : correspondences) {
    Vec3d p = c.point.base;
    for (const LinearPointCost::Term& term : c.point.terms) p += term.matrix * Vec3d(d[3 * term.vertex], d[3 * term.vertex + 1], d[3 * term.vertex + 2]);
    const Vec3d difference = target.scale() * (p - c.target_point);
    const double plane = c.target_normal.dot(difference), share = kPointToPointShare * kPointToPointShare;
    const double squared = options.metric == ChamferMetric::kPointToPoint ? difference.squaredNorm()
                           : options.metric == ChamferMetric::kPointToPlane ? plane * plane
                                                                            : plane * plane + share * difference.squaredNorm();
    loss += squared / static_cast<double>(std::max<size_t>(1, c.forward ? num_forward : num_backward));
  }
  return loss;
}

}  // namespace

std::string FreeformOptions::Check() const {
  if (num_output_samples < 10 || num_target_samples < 10) return "free-form: at least 10 samples each way";
  if (max_outer_iterations < 1 || max_inner_iterations < 1) return "free-form: iterations must be at least 1";
  if (!(smoothness_weight >= 0)) return "free-form: smoothness weight must be >= 0";
  if (num_threads < 1) return "free-form: threads must be at least 1";
  if (!(max_seconds >= 0)) return "free-form: max seconds must be >= 0";
  return "";
}

FreeformResult FitDisplacements(const Target& target, const Mesh& cage, const AffineTail& tail,
                                const FreeformOptions& options) {
  const std::string problem = options.Check();
  if (!problem.empty()) throw std::invalid_argument(problem);
  const int num_vertices = cage.NumVertices();
  const std::vector<MeshTriangle> triangles = FanTriangulate(tail.faces);
  const Positions<double> undisplaced = tail.Apply(cage.vertices);
  const std::vector<std::pair<int, int>> edges = CageEdges(cage);
  std::vector<double> d(3 * static_cast<size_t>(num_vertices), 0.0);
  auto displaced_output = [&]() {
    Positions<double> moved = cage.vertices;
    for (int v = 0; v < num_vertices; ++v) moved[v] += Vec3d(d[3 * v], d[3 * v + 1], d[3 * v + 2]);
    return tail.Apply(moved);
  };
  FreeformResult result;
  const Deadline deadline(options.max_seconds);
  for (int outer = 0; outer < options.max_outer_iterations && (outer == 0 || !deadline.Passed()); ++outer) {
    const Positions<double> positions = displaced_output();
    const std::vector<Correspondence> correspondences =
        FindCorrespondences(target, tail, undisplaced, positions, triangles, options, options.seed + 7919 * outer);
    if (outer == 0) result.initial_loss = DataLoss(correspondences, d, target, options);
    size_t num_forward = 0;
    for (const Correspondence& c : correspondences) num_forward += c.forward ? 1 : 0;
    const size_t num_backward = correspondences.size() - num_forward;
    ceres::Problem::Options problem_options;
    problem_options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
    ceres::Problem problem(problem_options);
    for (int v = 0; v < num_vertices; ++v) problem.AddParameterBlock(&d[3 * v], 3);
    std::vector<double*> blocks;
    for (const Correspondence& c : correspondences) {
      if (c.point.terms.empty()) continue;
      const double weight =
          target.scale() / std::sqrt(static_cast<double>(std::max<size_t>(1, c.forward ? num_forward : num_backward)));
      blocks.clear();
      for (const LinearPointCost::Term& term : c.point.terms) blocks.push_back(&d[3 * term.vertex]);
      problem.AddResidualBlock(LinearPointCost::Create(c.point.base, c.point.terms, c.target_point, c.target_normal,
                                                       options.metric, weight),
                               nullptr, blocks);
    }
    const double smoothness = target.scale() * std::sqrt(options.smoothness_weight / std::max<size_t>(1, edges.size()));
    for (const auto& [a, b] : edges) {
      problem.AddResidualBlock(DisplacementDifferenceCost::Create(smoothness), nullptr, &d[3 * a], &d[3 * b]);
    }
    ceres::Solver::Options solver_options;
    solver_options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    solver_options.max_num_iterations = options.max_inner_iterations;
    solver_options.num_threads = options.num_threads;
    solver_options.logging_type = ceres::SILENT;
    if (deadline.limited()) solver_options.max_solver_time_in_seconds = deadline.SecondsLeft();
    ceres::Solver::Summary summary;
    ceres::Solve(solver_options, &problem, &summary);
  }
  result.final_loss = DataLoss(FindCorrespondences(target, tail, undisplaced, displaced_output(), triangles, options,
                                                   options.seed),
                               d, target, options);
  result.displacements.resize(num_vertices);
  for (int v = 0; v < num_vertices; ++v) result.displacements[v] = Vec3d(d[3 * v], d[3 * v + 1], d[3 * v + 2]);
  return result;
}

}  // namespace opgraph
