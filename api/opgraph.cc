#include "api/opgraph.h"

#include <exception>
#include <stdexcept>
#include <utility>

#include "io/sequence_outputs.h"
#include "search/zero_shot.h"
#include "solver/fitter.h"
#include "solver/target.h"

namespace opgraph {
namespace api {

std::string Version() { return OPGRAPH_VERSION; }

const opgraph::Target& Internal(const Target& target) { return *target.target_; }

namespace {

opgraph::Mesh InternalMesh(const Eigen::MatrixX3d& vertices, std::vector<Polygon> faces) {
  opgraph::Mesh mesh;
  mesh.vertices.reserve(static_cast<size_t>(vertices.rows()));
  for (Eigen::Index v = 0; v < vertices.rows(); ++v) mesh.vertices.push_back(vertices.row(v).transpose());
  mesh.faces = std::move(faces);
  return mesh;
}

Eigen::MatrixX3d ToMatrix(const Positions<double>& positions) {
  Eigen::MatrixX3d matrix(static_cast<Eigen::Index>(positions.size()), 3);
  for (size_t i = 0; i < positions.size(); ++i) matrix.row(static_cast<Eigen::Index>(i)) = positions[i].transpose();
  return matrix;
}

Mesh ApiMesh(const opgraph::Mesh& mesh) { return {ToMatrix(mesh.vertices), mesh.faces}; }

// What the internal constructor and fits would reject less clearly (or not at all).
void CheckShape(const opgraph::Mesh& shape) {
  if (shape.vertices.size() < 4) throw std::invalid_argument("target: fewer than 4 points");
  if (const std::string problem = shape.Validate(); !problem.empty()) throw std::invalid_argument("target: " + problem);
  Vec3d lo = shape.vertices[0], hi = shape.vertices[0];
  for (const Vec3d& p : shape.vertices) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  if (!((hi - lo).maxCoeff() > 0)) throw std::invalid_argument("target: all points are at one place (zero extent)");
}

void ThrowIfInvalid(const std::string& what, const std::string& problem) {
  if (!problem.empty()) throw std::invalid_argument(what + ": " + problem);
}

// `sequence_json` parsed; std::invalid_argument when it is not JSON or not a sequence document.
Sequence Parse(const std::string& sequence_json) {
  Json document;
  try {
    document = Json::parse(sequence_json);
  } catch (const std::exception& e) {
    throw std::invalid_argument(std::string("sequence: not JSON: ") + e.what());
  }
  try {
    return ParseSequence(document);
  } catch (const std::exception& e) {
    throw std::invalid_argument(std::string("sequence: ") + e.what());
  }
}

// The mesh `sequence` builds (the start cube when it has no ops).
Mesh ResultMesh(Sequence* sequence) {
  const std::vector<opgraph::Mesh> steps = EvaluateSequence(sequence);
  return ApiMesh(steps.empty() ? sequence->StartMesh() : steps.back());
}

// As sequence.json has it.
std::string SequenceText(const Sequence& sequence) { return SequenceToJson(sequence).dump(1) + "\n"; }

// Each API option with the internal option it stands for, in one list for both directions:
// visit(api_field, internal_field). `Api` and `Internal` may be const.
template <typename Api, typename Internal, typename Visit>
void VisitTargetOptions(Api& api, Internal& internal, const Visit& visit) {
  visit(api.num_samples, internal.num_samples);
  visit(api.max_cloud_points, internal.max_cloud_points);
  visit(api.normal_neighbours, internal.normal_neighbours);
  visit(api.seed, internal.seed);
}

template <typename Api, typename Internal, typename Visit>
void VisitRecoverOptions(Api& api, Internal& internal, const Visit& visit) {
  visit(api.work_budget, internal.work_budget);
  visit(api.time_budget_seconds, internal.time_budget_seconds);
  visit(api.max_ops, internal.max_ops);
  visit(api.min_relative_gain, internal.min_relative_gain);
  visit(api.beam_width, internal.beam_width);
  visit(api.seed, internal.seed);
  visit(api.num_threads, internal.num_threads);
  visit(api.freeform, internal.freeform);
}

template <typename Api, typename Internal, typename Visit>
void VisitFitOptions(Api& api, Internal& internal, const Visit& visit) {
  visit(api.fit_gates, internal.fit_gates);
  visit(api.max_outer_iterations, internal.max_outer_iterations);
  visit(api.num_samples, internal.num_target_samples);
  visit(api.num_samples, internal.num_output_samples);
  visit(api.seed, internal.seed);
}

const auto kFromInternal = [](auto& api, const auto& internal) { api = internal; };
const auto kToInternal = [](const auto& api, auto& internal) { internal = api; };

opgraph::TargetOptions ToInternal(const TargetOptions& options) {
  opgraph::TargetOptions internal;
  VisitTargetOptions(options, internal, kToInternal);
  return internal;
}

ZeroShotOptions ToInternal(const RecoverOptions& options) {
  ZeroShotOptions internal;
  VisitRecoverOptions(options, internal, kToInternal);
  return internal;
}

FitterOptions ToInternal(const FitOptions& options) {
  FitterOptions internal;
  VisitFitOptions(options, internal, kToInternal);
  return internal;
}

}  // namespace

// The defaults are the internal options' (one place for each).
TargetOptions::TargetOptions() {
  const opgraph::TargetOptions defaults;
  VisitTargetOptions(*this, defaults, kFromInternal);
}
std::string TargetOptions::Check() const { return ToInternal(*this).Check(); }

RecoverOptions::RecoverOptions() {
  const ZeroShotOptions defaults;
  VisitRecoverOptions(*this, defaults, kFromInternal);
}
std::string RecoverOptions::Check() const { return ToInternal(*this).Check(); }

FitOptions::FitOptions() {
  const FitterOptions defaults;
  VisitFitOptions(*this, defaults, kFromInternal);
}
std::string FitOptions::Check() const { return ToInternal(*this).Check(); }

Target::Target(std::shared_ptr<const opgraph::Target> target) : target_(std::move(target)) {}

Target Target::FromFile(const std::string& path, const TargetOptions& options) {
  ThrowIfInvalid("target options", options.Check());
  return Target(LoadTarget(path, ToInternal(options)));
}

Target Target::FromPoints(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                          const TargetOptions& options) {
  ThrowIfInvalid("target options", options.Check());
  opgraph::Mesh cloud = InternalMesh(points, {});
  CheckShape(cloud);
  if (normals.rows() != 0 && normals.rows() != points.rows()) {
    throw std::invalid_argument("target: " + std::to_string(normals.rows()) + " normals for " +
                                std::to_string(points.rows()) + " points");
  }
  Positions<double> unit_normals;
  for (Eigen::Index i = 0; i < normals.rows(); ++i) {
    const Vec3d n = normals.row(i).transpose();
    if (!(n.allFinite() && n.norm() > 1e-12)) {
      throw std::invalid_argument("target: normal " + std::to_string(i) + " is zero or not finite");
    }
    unit_normals.push_back(n.normalized());
  }
  return Target(std::make_shared<const opgraph::Target>(std::move(cloud), std::move(unit_normals), ToInternal(options)));
}

Target Target::FromMesh(const Mesh& mesh, const TargetOptions& options) {
  ThrowIfInvalid("target options", options.Check());
  opgraph::Mesh shape = InternalMesh(mesh.vertices, mesh.faces);
  CheckShape(shape);
  if (shape.faces.empty()) throw std::invalid_argument("target: a mesh without faces (use FromPoints)");
  return Target(std::make_shared<const opgraph::Target>(std::move(shape), Positions<double>(), ToInternal(options)));
}

bool Target::is_point_cloud() const { return target_->is_cloud(); }
Mesh Target::shape() const { return ApiMesh(target_->shape()); }
Eigen::MatrixX3d Target::sample_points() const { return ToMatrix(target_->points()); }
Eigen::MatrixX3d Target::sample_normals() const { return ToMatrix(target_->normals()); }

RecoverResult RecoverSequence(const Target& target, const RecoverOptions& options) {
  ThrowIfInvalid("recover options", options.Check());
  ZeroShotOptions internal = ToInternal(options);
  std::exception_ptr callback_error;
  if (options.on_progress) {
    internal.on_progress = [&](const SearchProgress& progress) {
      try {
        return options.on_progress(Progress{progress.stage, progress.fraction, progress.seconds, progress.ops,
                                            progress.loss, progress.line});
      } catch (...) {
        callback_error = std::current_exception();
        return false;
      }
    };
  }
  const ZeroShotResult recovered = opgraph::RecoverSequence(Internal(target), internal);
  if (callback_error) std::rethrow_exception(callback_error);

  RecoverResult result;
  Sequence sequence = ParseSequence(recovered.sequence);
  result.sequence_json = SequenceText(sequence);
  result.mesh = ResultMesh(&sequence);
  result.num_ops = static_cast<int>(sequence.ops.size());
  result.loss = recovered.loss;
  result.work = recovered.work;
  result.num_fits = recovered.num_fits;
  result.seconds = recovered.seconds;
  result.ended_by = SearchEndName(recovered.end);
  result.decisions = recovered.decisions;
  return result;
}

FitResult FitSequence(const std::string& sequence_json, const Target& target, const FitOptions& options) {
  ThrowIfInvalid("fit options", options.Check());
  Sequence sequence = Parse(sequence_json);
  const FitSummary summary = opgraph::FitSequence(Internal(target), &sequence, ToInternal(options));
  FitResult result;
  result.sequence_json = SequenceText(sequence);
  result.mesh = ResultMesh(&sequence);
  result.num_ops = static_cast<int>(sequence.ops.size());
  result.initial_loss = summary.initial_loss;
  result.final_loss = summary.final_loss;
  result.seconds = summary.seconds;
  return result;
}

Mesh ApplySequence(const std::string& sequence_json) {
  Sequence sequence = Parse(sequence_json);
  return ResultMesh(&sequence);
}

void WriteOutputs(const std::string& sequence_json, const std::string& out_dir, const WriteOptions& options) {
  Sequence sequence = Parse(sequence_json);
  if (!options.name.empty()) sequence.name = options.name;
  BlenderScriptOptions blender;
  if (!sequence.name.empty()) blender.name = BlenderObjectName(sequence.name);
  WriteSequenceOutputs(RenderSequenceOutputs(&sequence, blender), out_dir, options.write_steps, options.comment);
}

}  // namespace api
}  // namespace opgraph
