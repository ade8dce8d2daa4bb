// Runs fit_sequence (the main job, zero-shot) on every model of the reference data and writes
// the results table: geometry, Blender replay, sequence similarity to ground truth, wiring,
// time. Usage (from the repository root, after a build):
//   build/run_results --data ../shared/data --out out/results --doc docs/results.md [--time-budget S]
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "core/obj_io.h"
#include "core/sequence_similarity.h"
#include "core/surface_distance.h"
#include "ops/params.h"

namespace fs = std::filesystem;
using opgraph::Json;

namespace {

struct Row {
  std::string set, name;
  bool ok = false;
  std::string error;
  double chamfer = 0, f1_001 = 0, f1_002 = 0, normal_consistency = 0;
  double valence4 = 0, quad = 0, area_cv = 0;
  bool subdivided = false;
  int ops = 0;
  double seconds = 0;
  double replay_distance = -1;
  bool replay_counts_equal = false;
  double lcs = -1, levenshtein = -1;
  std::string sequence;
};

std::string Quote(const std::string& s) { return "'" + s + "'"; }

std::vector<std::string> OpNames(const Json& document) {
  std::vector<std::string> names;
  for (const Json& op : document.at("operations")) names.push_back(op.at("op"));
  return names;
}

double Median(std::vector<double> values) {
  if (values.empty()) return NAN;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double Mean(const std::vector<double>& values) {
  double sum = 0;
  for (double v : values) sum += v;
  return values.empty() ? NAN : sum / values.size();
}

Row Run(const std::string& set, const std::string& name, const fs::path& input, const fs::path& truth,
        const fs::path& fit_sequence, const fs::path& out, int budget) {
  Row row{set, name};
  const fs::path dir = out / name;
  fs::remove_all(dir);
  const std::string command = Quote(fit_sequence.string()) + " --input " + Quote(input.string()) + " --out " +
                              Quote(dir.string()) + " --time-budget " + std::to_string(budget) + " --quiet > " +
                              Quote((out / (name + ".log")).string()) + " 2>&1";
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(command.c_str());
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (status != 0) {
    std::ifstream log(out / (name + ".log"));
    std::getline(log, row.error);
    return row;
  }
  const Json metrics = Json::parse(std::ifstream(dir / "metrics.json"));
  const Json sequence = Json::parse(std::ifstream(dir / "sequence.json"));
  row.chamfer = metrics["shape"]["chamfer"]["sum"];
  row.f1_001 = metrics["shape"]["f1_0.01"];
  row.f1_002 = metrics["shape"]["f1_0.02"];
  row.normal_consistency = metrics["shape"]["normal_consistency"].is_number() ? metrics["shape"]["normal_consistency"].get<double>() : NAN;
  row.valence4 = metrics["wiring"]["valence4_fraction"];
  row.quad = metrics["wiring"]["quad_fraction"];
  row.area_cv = metrics["wiring"]["face_area_cv"];
  const std::vector<std::string> ours = OpNames(sequence);
  row.ops = static_cast<int>(ours.size());
  row.subdivided = std::find(ours.begin(), ours.end(), "Subdivision") != ours.end();
  for (const std::string& op : ours) row.sequence += (row.sequence.empty() ? "" : " ") + op;
  if (!truth.empty()) {
    const std::vector<std::string> gt = OpNames(Json::parse(std::ifstream(truth)));
    row.lcs = opgraph::NormalizedLcsSimilarity(ours, gt);
    row.levenshtein = opgraph::LevenshteinSimilarity(ours, gt);
  }
  // Real Blender replays the script; its mesh must be ours.
  const fs::path blender_obj = dir / "blender.obj";
  const std::string replay = "blender -b --factory-startup --python-exit-code 1 -P " +
                             Quote((dir / "rebuild_blender.py").string()) + " -- " + Quote(blender_obj.string()) +
                             " > " + Quote((dir / "blender.log").string()) + " 2>&1";
  if (std::system(replay.c_str()) == 0) {
    const opgraph::Mesh ours_mesh = opgraph::ReadObj((dir / "result.obj").string());
    const opgraph::Mesh blender_mesh = opgraph::ReadObj(blender_obj.string());
    row.replay_distance = opgraph::SymmetricSurfaceDistanceRelative(ours_mesh, blender_mesh);
    row.replay_counts_equal =
        ours_mesh.NumVertices() == blender_mesh.NumVertices() && ours_mesh.NumFaces() == blender_mesh.NumFaces();
  }
  row.ok = true;
  return row;
}

std::string Fixed(double value, int digits) {
  if (!std::isfinite(value)) return "–";
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << value;
  return s.str();
}

std::string Sci(double value) {
  if (!std::isfinite(value) || value < 0) return "–";
  std::ostringstream s;
  s << std::scientific << std::setprecision(1) << value;
  return s.str();
}

}  // namespace

int main(int argc, char** argv) {
  fs::path data = "../shared/data", out = "out/results", doc = "docs/results.md";
  fs::path fit_sequence = fs::path(argv[0]).parent_path() / "fit_sequence";
  int budget = 90;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string arg = argv[i];
    if (arg == "--data") data = argv[i + 1];
    else if (arg == "--out") out = argv[i + 1];
    else if (arg == "--doc") doc = argv[i + 1];
    else if (arg == "--time-budget") budget = std::atoi(argv[i + 1]);
    else {
      std::cerr << "run_results: unknown argument " << arg << "\n";
      return 2;
    }
  }
  if (!fs::is_directory(data / "gt-dev")) {
    std::cerr << "run_results: no gt-dev folder under " << data << "\n";
    return 2;
  }
  fs::create_directories(out);
  std::vector<Row> rows;
  std::vector<fs::path> models;
  for (const auto& entry : fs::directory_iterator(data / "gt-dev")) models.push_back(entry.path());
  std::sort(models.begin(), models.end());
  for (const fs::path& model : models) {
    std::cout << "[results] gt-dev/" << model.filename().string() << " ..." << std::flush;
    rows.push_back(Run("gt-dev", model.filename().string(), model / "model.obj", model / "sequence.json",
                       fit_sequence, out, budget));
    std::cout << " " << (rows.back().ok ? "Chamfer " + Sci(rows.back().chamfer) : rows.back().error) << ", "
              << Fixed(rows.back().seconds, 1) << " s" << std::endl;
  }
  std::vector<fs::path> reals;
  for (const auto& entry : fs::directory_iterator(data / "real-dev")) {
    if (entry.path().extension() == ".obj") reals.push_back(entry.path());
  }
  std::sort(reals.begin(), reals.end());
  for (const fs::path& model : reals) {
    std::cout << "[results] real-dev/" << model.stem().string() << " ..." << std::flush;
    rows.push_back(Run("real-dev", model.stem().string(), model, "", fit_sequence, out, budget));
    std::cout << " " << (rows.back().ok ? "Chamfer " + Sci(rows.back().chamfer) : rows.back().error) << ", "
              << Fixed(rows.back().seconds, 1) << " s" << std::endl;
  }

  std::ostringstream md;
  md << "# fit_sequence results on the reference data\n\n"
     << "Made by `bash benchmarks/run_results.sh` (= `build/run_results --data ../shared/data --out out/results "
        "--doc docs/results.md --time-budget "
     << budget << "`), which runs `fit_sequence --input MODEL --out DIR --time-budget " << budget
     << "` (zero-shot, default seed 1) on every model, replays each `rebuild_blender.py` in real Blender, and "
        "compares.\n\n"
     << "Geometry on the target's unit bounding box (longest side 1): Chamfer = point-to-surface mean distance, both "
        "directions summed; F1 at 0.01 and 0.02; NC = normal consistency. Replay = symmetric point-to-surface "
        "distance between `result.obj` and the mesh Blender builds from `rebuild_blender.py`, relative to the "
        "bounding-box diagonal. LCS / Lev = normalised LCS and Levenshtein similarity of our op names to the "
        "ground-truth sequence. V4 = fraction of valence-4 vertices; area CV = face-area coefficient of variation. "
        "Time = wall time of the whole command on this 2-core machine.\n\n";
  for (const std::string set : {"gt-dev", "real-dev"}) {
    md << "## " << set << "\n\n| model | Chamfer | F1@0.01 | F1@0.02 | NC | ops | LCS | Lev | V4 | quads | area CV | "
          "replay | time s | sequence |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    std::vector<double> chamfer, f1, nc, lcs, lev, seconds, v4_smooth, area_cv;
    int replay_ok = 0, count = 0;
    for (const Row& r : rows) {
      if (r.set != set) continue;
      ++count;
      if (!r.ok) {
        md << "| " << r.name << " | failed: " << r.error << " |||||||||||||\n";
        continue;
      }
      chamfer.push_back(r.chamfer), f1.push_back(r.f1_001), seconds.push_back(r.seconds), area_cv.push_back(r.area_cv);
      if (std::isfinite(r.normal_consistency)) nc.push_back(r.normal_consistency);
      if (r.lcs >= 0) lcs.push_back(r.lcs), lev.push_back(r.levenshtein);
      if (r.subdivided) v4_smooth.push_back(r.valence4);
      const bool replay = r.replay_distance >= 0 && r.replay_distance < 1e-6 && r.replay_counts_equal;
      replay_ok += replay;
      md << "| " << r.name << " | " << Fixed(r.chamfer, 4) << " | " << Fixed(r.f1_001, 3) << " | "
         << Fixed(r.f1_002, 3) << " | " << Fixed(r.normal_consistency, 3) << " | " << r.ops << " | "
         << (r.lcs >= 0 ? Fixed(r.lcs, 2) : "–") << " | " << (r.levenshtein >= 0 ? Fixed(r.levenshtein, 2) : "–")
         << " | " << Fixed(r.valence4, 2) << " | " << Fixed(r.quad, 2) << " | " << Fixed(r.area_cv, 2) << " | "
         << Sci(r.replay_distance) << (replay ? "" : " ✗") << " | " << Fixed(r.seconds, 1) << " | " << r.sequence
         << " |\n";
    }
    md << "\n**" << set << " summary:** median Chamfer " << Fixed(Median(chamfer), 4) << ", median F1@0.01 "
       << Fixed(Median(f1), 3) << ", median NC " << Fixed(Median(nc), 3);
    if (!lcs.empty()) md << ", mean LCS " << Fixed(Mean(lcs), 2) << ", mean Levenshtein " << Fixed(Mean(lev), 2);
    md << ", valence-4 fraction on subdivided results (median) " << Fixed(Median(v4_smooth), 3)
       << ", face-area CV median " << Fixed(Median(area_cv), 2) << ", median time " << Fixed(Median(seconds), 1)
       << " s, Blender replay within 1e-6 with equal counts: " << replay_ok << " of " << count << ".\n\n";
  }
  opgraph::WriteFileAtomic(doc.string(), md.str());
  std::cout << "[results] wrote " << doc << "\n";
  return 0;
}
