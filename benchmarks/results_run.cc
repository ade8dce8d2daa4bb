#include "benchmarks/results_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/metrics.h"
#include "core/obj_io.h"
#include "core/sequence_similarity.h"
#include "core/surface_distance.h"
#include "ops/sequence_op_names.h"
#include "solver/target.h"
#include "tests/blender_runner.h"

namespace opgraph {
namespace fs = std::filesystem;
namespace {

double NumberOr(const Json& value, double fallback) { return value.is_number() ? value.get<double>() : fallback; }

// `count` seeded area-weighted samples of the model's surface, without normals, written to
// `path` as XYZ text. Returns the model's mesh, the reference for the numbers.
Mesh WriteCloud(const ResultsModel& model, int count, const fs::path& path) {
  TargetOptions options;
  options.num_samples = count;
  const std::unique_ptr<Target> target = LoadTarget(model.input.string(), options);
  std::ostringstream xyz;
  xyz.precision(17);
  for (const Vec3d& p : target->points()) xyz << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  WriteFileAtomic(path.string(), xyz.str());
  return target->shape();
}

}  // namespace

Json RowToJson(const ResultsRow& r) {
  return {{"set", r.set}, {"name", r.name}, {"ok", r.ok}, {"error", r.error}, {"chamfer", r.chamfer},
          {"f1_0.01", r.f1_001}, {"f1_0.02", r.f1_002},
          {"normal_consistency", std::isfinite(r.normal_consistency) ? Json(r.normal_consistency) : Json(nullptr)},
          {"valence4", r.valence4}, {"quad", r.quad}, {"area_cv", r.area_cv}, {"subdivided", r.subdivided},
          {"search_complete", r.search_complete}, {"freeform", r.freeform}, {"ops", r.ops}, {"seconds", r.seconds},
          {"replay_distance", r.replay_distance}, {"replay_counts_equal", r.replay_counts_equal}, {"lcs", r.lcs},
          {"levenshtein", r.levenshtein}, {"sequence", r.sequence}};
}

ResultsRow RowFromJson(const Json& j) {
  ResultsRow r;
  r.set = j.at("set"), r.name = j.at("name"), r.ok = j.at("ok"), r.error = j.at("error");
  r.chamfer = j.at("chamfer"), r.f1_001 = j.at("f1_0.01"), r.f1_002 = j.at("f1_0.02");
  r.normal_consistency = NumberOr(j.at("normal_consistency"), NAN);
  r.valence4 = j.at("valence4"), r.quad = j.at("quad"), r.area_cv = j.at("area_cv");
  r.subdivided = j.at("subdivided"), r.search_complete = j.at("search_complete"), r.ops = j.at("ops");
  r.freeform = j.value("freeform", false);  // records before the free-form stage have none
  r.seconds = j.at("seconds"), r.replay_distance = j.at("replay_distance");
  r.replay_counts_equal = j.at("replay_counts_equal"), r.lcs = j.at("lcs"), r.levenshtein = j.at("levenshtein");
  r.sequence = j.at("sequence");
  return r;
}

ResultsRow FitModel(const ResultsModel& model, const RunOptions& options) {
  ResultsRow row;
  row.set = model.set, row.name = model.name;
  const fs::path dir = options.out / model.set / model.name, log = options.out / model.set / (model.name + ".log");
  fs::remove_all(dir);
  fs::path input = model.input;
  Mesh reference;
  if (options.cloud_points > 0) {
    input = options.out / model.set / (model.name + ".xyz");
    try {
      reference = WriteCloud(model, options.cloud_points, input);
    } catch (const std::exception& e) {
      row.error = std::string("cannot sample the model: ") + e.what();
      return row;
    }
  }
  std::string budget;
  if (options.work_budget > 0) budget += " --work-budget " + std::to_string(options.work_budget);
  if (options.time_budget > 0) budget += " --time-budget " + std::to_string(options.time_budget);
  if (options.threads > 0) budget += " --threads " + std::to_string(options.threads);
  if (!options.fit_flags.empty()) budget += " " + options.fit_flags;
  const std::string command = ShellQuote(options.fit_sequence.string()) + " --input " + ShellQuote(input.string()) +
                              " --out " + ShellQuote(dir.string()) + budget + " --quiet > " + ShellQuote(log.string()) +
                              " 2>&1";
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(command.c_str());
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (status != 0) {
    std::ifstream in(log);
    std::getline(in, row.error);
    if (row.error.empty()) row.error = "fit_sequence exited with status " + std::to_string(status);
    return row;
  }
  try {
    const Json metrics = Json::parse(std::ifstream(dir / "metrics.json"));
    const Json sequence = Json::parse(std::ifstream(dir / "sequence.json"));
    const Json& shape = metrics.at("shape");
    row.chamfer = shape.at("chamfer").at("sum");
    row.f1_001 = shape.at("f1_0.01"), row.f1_002 = shape.at("f1_0.02");
    row.normal_consistency = NumberOr(shape.at("normal_consistency"), NAN);
    row.valence4 = metrics.at("wiring").at("valence4_fraction");
    row.quad = metrics.at("wiring").at("quad_fraction");
    row.area_cv = metrics.at("wiring").at("face_area_cv");
    if (metrics.contains("fit") && metrics["fit"].contains("search_complete")) row.search_complete = metrics["fit"]["search_complete"];
    if (metrics.contains("fit")) row.freeform = metrics["fit"].value("freeform", false);
    if (options.cloud_points > 0) {  // against the model mesh, not the cloud the fit saw
      MetricsOptions metrics_options;
      metrics_options.num_samples = 10000;
      const ShapeMetrics against_mesh = ComputeShapeMetrics(ReadObj((dir / "result.obj").string()), reference, metrics_options);
      row.chamfer = against_mesh.chamfer.Sum();
      row.f1_001 = against_mesh.f1_001, row.f1_002 = against_mesh.f1_002;
      row.normal_consistency = against_mesh.normal_consistency;
    }
    const std::vector<std::string> ours = SequenceOpNames(sequence);
    row.ops = static_cast<int>(ours.size());
    row.subdivided = std::find(ours.begin(), ours.end(), "Subdivision") != ours.end();
    for (const std::string& op : ours) row.sequence += (row.sequence.empty() ? "" : " ") + op;
    if (!model.truth.empty()) {
      const std::vector<std::string> truth = SequenceOpNames(Json::parse(std::ifstream(model.truth)));
      row.lcs = NormalizedLcsSimilarity(ours, truth);
      row.levenshtein = LevenshteinSimilarity(ours, truth);
    }
  } catch (const std::exception& e) {
    row.error = std::string("unreadable outputs: ") + e.what();
    return row;
  }
  row.ok = true;
  return row;
}

void ReplayModel(const RunOptions& options, ResultsRow* row) {
  if (!row->ok) return;
  const fs::path dir = options.out / row->set / row->name;
  try {  // real Blender replays the script; its mesh must be ours
    const Mesh ours = ReadObj((dir / "result.obj").string());
    const Mesh blender = RunBlender((dir / "rebuild_blender.py").string(), (dir / "blender.obj").string());
    row->replay_distance = SymmetricSurfaceDistanceRelative(ours, blender);
    row->replay_counts_equal = ours.NumVertices() == blender.NumVertices() && ours.NumFaces() == blender.NumFaces();
  } catch (const std::exception&) {
    row->replay_distance = -1;
  }
}

}  // namespace opgraph
