#include "benchmarks/results_doc.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "core/obj_io.h"

namespace opgraph {
namespace fs = std::filesystem;
namespace {

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

std::string ModelRow(const ResultsRow& r) {
  if (!r.ok) return "| " + r.name + " | failed: " + r.error.substr(0, 160) + " |||||||||||||\n";
  std::ostringstream md;
  md << "| " << r.name << " | " << Fixed(r.chamfer, 4) << " | " << Fixed(r.f1_001, 3) << " | " << Fixed(r.f1_002, 3)
     << " | " << Fixed(r.normal_consistency, 3) << " | " << r.ops << " | " << (r.lcs >= 0 ? Fixed(r.lcs, 2) : "–")
     << " | " << (r.levenshtein >= 0 ? Fixed(r.levenshtein, 2) : "–") << " | " << Fixed(r.valence4, 2) << " | "
     << Fixed(r.quad, 2) << " | " << Sci(r.replay_distance) << (r.ReplayOk() ? "" : " ✗") << " | "
     << Fixed(r.seconds, 1) << (r.search_complete ? "" : " (cut)") << " | " << r.sequence << " |\n";
  return md.str();
}

}  // namespace

void SaveSetRecord(const SetRecord& record, const fs::path& dir) {
  Json rows = Json::array();
  for (const ResultsRow& row : record.rows) rows.push_back(RowToJson(row));
  const Json json = {{"set", record.set},   {"commit", record.commit}, {"date", record.date},
                     {"time_budget", record.time_budget}, {"work_budget", record.work_budget},
                     {"threads", record.threads},         {"jobs", record.jobs},     {"rows", rows}};
  fs::create_directories(dir);
  WriteFileAtomic((dir / (record.set + ".json")).string(), json.dump(1) + "\n");
}

std::vector<SetRecord> LoadSetRecords(const fs::path& dir) {
  std::vector<SetRecord> records;
  for (const std::string& set : ResultsSetNames()) {
    std::ifstream in(dir / (set + ".json"));
    if (!in) continue;
    const Json json = Json::parse(in);
    SetRecord record;
    record.set = json.at("set"), record.commit = json.at("commit"), record.date = json.at("date");
    record.time_budget = json.at("time_budget"), record.jobs = json.at("jobs");
    record.work_budget = json.value("work_budget", int64_t{0}), record.threads = json.value("threads", 0);
    for (const Json& row : json.at("rows")) record.rows.push_back(RowFromJson(row));
    records.push_back(record);
  }
  return records;
}

namespace {

// The budget of a run, as the summary's run column shows it: work (and a time cap), or the
// time budget of a record made before the work budget.
std::string Budget(const SetRecord& record) {
  if (record.work_budget <= 0) return std::to_string(record.time_budget) + " s";
  std::string text = std::to_string(record.work_budget) + " work";
  if (record.time_budget > 0) text += ", cap " + std::to_string(record.time_budget) + " s";
  if (record.threads > 0) text += ", " + std::to_string(record.threads) + " threads";
  return text;
}

}  // namespace

std::string SummaryRow(const SetRecord& record) {
  std::vector<double> chamfer, f1, nc, lcs, lev, seconds, v4;
  int replays = 0, complete = 0, failed = 0, freeform = 0;
  for (const ResultsRow& r : record.rows) {
    if (!r.ok) {
      ++failed;
      continue;
    }
    chamfer.push_back(r.chamfer), f1.push_back(r.f1_001), seconds.push_back(r.seconds);
    if (std::isfinite(r.normal_consistency)) nc.push_back(r.normal_consistency);
    if (r.lcs >= 0) lcs.push_back(r.lcs), lev.push_back(r.levenshtein);
    if (r.subdivided) v4.push_back(r.valence4);
    replays += r.ReplayOk(), complete += r.search_complete, freeform += r.freeform;
  }
  std::ostringstream md;
  md << "| " << record.set << " | " << (IsHeldOutSet(record.set) ? "held out" : "tuning / dev") << " | "
     << record.rows.size() << (failed ? " (" + std::to_string(failed) + " failed)" : "") << " | "
     << Fixed(Median(chamfer), 4) << " | " << Fixed(Median(f1), 3) << " | " << Fixed(Median(nc), 3) << " | "
     << Fixed(Mean(lcs), 2) << " | " << Fixed(Mean(lev), 2) << " | " << Fixed(Median(v4), 3) << " | " << replays
     << " of " << record.rows.size() << " | " << Fixed(Median(seconds), 1) << " | " << complete << " of "
     << record.rows.size() << " | " << freeform << " | " << record.commit << ", " << record.date << ", " << Budget(record) << ", "
     << record.jobs << " jobs |\n";
  return md.str();
}

std::string ResultsMarkdown(const std::vector<SetRecord>& records, int cloud_points) {
  std::ostringstream md;
  md << "# fit_sequence results on the corpus" << (cloud_points > 0 ? ", point-cloud input" : "") << "\n\n";
  if (cloud_points > 0) {
    md << "Point-cloud input: made by `bash benchmarks/run_results.sh --set all --cloud " << cloud_points
       << "`. Each model is given to `fit_sequence` as " << cloud_points
       << " seeded area-weighted samples of its surface without normals (an XYZ file; the normals are estimated), "
          "and the numbers compare the result with the model mesh itself, as on the mesh-input page "
          "[results.md](results.md).\n\n";
  }
  md << "Made by `bash benchmarks/run_results.sh --set all` (= `build/run_results --set all`; `--set NAME` reruns "
        "one set). It runs `fit_sequence --input MODEL --out DIR` (zero-shot, default seed 1, the budget in the run column) on "
        "every model of the set, several models at once (`--jobs`, default one per core), replays each "
        "`rebuild_blender.py` in real Blender, and compares. Each set's rows are kept in `docs/results/<set>.json` "
        "with the commit, date and budget of the run that made them; this page is rendered from all of them. "
        "The sets and the held-out protocol: [corpus.md](corpus.md).\n\n"
     << "Geometry on the target's unit bounding box (longest side 1): Chamfer = point-to-surface mean distance, both "
        "directions summed; F1 at 0.01 and 0.02; NC = normal consistency. Replay = symmetric point-to-surface "
        "distance between `result.obj` and the mesh Blender builds from `rebuild_blender.py`, relative to the "
        "bounding-box diagonal (✗: above 1e-6 or counts differ). LCS / Lev = normalised LCS and Levenshtein "
        "similarity of our op names to the ground-truth sequence. V4 = fraction of valence-4 vertices (summary: "
        "median over results with a Subdivision). Time = wall time of fit_sequence; (cut) = the budget ended the "
        "search. Free-form = results that kept the final free-form displacements of the cage.\n\n"
     << "## Summary\n\n| set | split | models | median Chamfer | median F1@0.01 | median NC | mean LCS | mean Lev | "
        "V4 (subdivided) | Blender replays | median time s | search complete | free-form | run |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const SetRecord& record : records) md << SummaryRow(record);
  for (const SetRecord& record : records) {
    if (IsHeldOutSet(record.set)) {
      // The protocol: held-out models are measured, never looked at one by one to decide a change.
      md << "\n## " << record.set << "\n\nHeld out: only the summary above is shown; the per-model rows are in "
         << "`docs/results/" << record.set << ".json` for audits, not for tuning.\n";
      continue;
    }
    md << "\n## " << record.set << "\n\n| model | Chamfer | F1@0.01 | F1@0.02 | NC | ops | LCS | Lev | V4 | quads | "
          "replay | time s | sequence |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const ResultsRow& row : record.rows) md << ModelRow(row);
  }
  return md.str();
}

}  // namespace opgraph
