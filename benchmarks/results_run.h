// One model of a results run: fit_sequence (zero-shot) on it, real Blender replaying the
// written script, and the numbers of the results table.
#pragma once

#include <filesystem>
#include <string>

#include "benchmarks/results_sets.h"
#include "ops/params.h"

namespace opgraph {

struct ResultsRow {
  std::string set, name;
  bool ok = false;
  std::string error;
  double chamfer = 0, f1_001 = 0, f1_002 = 0, normal_consistency = 0;
  double valence4 = 0, quad = 0, area_cv = 0;
  bool subdivided = false, search_complete = true;
  bool freeform = false;  // the search kept free-form displacements (search/freeform.h)
  int ops = 0;
  double seconds = 0;
  double replay_distance = -1;  // of the diagonal; < 0: Blender failed
  bool replay_counts_equal = false;
  double lcs = -1, levenshtein = -1;  // < 0: no ground truth
  std::string sequence;               // our op names

  bool ReplayOk() const { return replay_distance >= 0 && replay_distance < 1e-6 && replay_counts_equal; }
};

Json RowToJson(const ResultsRow& row);
ResultsRow RowFromJson(const Json& json);

struct RunOptions {
  std::filesystem::path fit_sequence;  // the binary
  std::filesystem::path out;           // per-model folders go to out / set / name
  int64_t work_budget = 0;  // fit_sequence --work-budget (0: its default)
  int time_budget = 0;      // fit_sequence --time-budget, a cap in seconds (0: none)
  int threads = 0;          // fit_sequence --threads (0: its default, every hardware thread)
  std::string fit_flags;    // more fit_sequence flags, as given (a shell word list)
  // > 0: the model is given to fit_sequence as a cloud of this many surface samples (no
  // normals, an XYZ file beside its outputs), and the numbers compare the result with the model
  // mesh itself.
  int cloud_points = 0;
};

// fit_sequence on the model and the row's numbers, without the replay (replay_distance < 0); a
// failure of fit_sequence is a row with `error` set.
ResultsRow FitModel(const ResultsModel& model, const RunOptions& options);
// Real Blender replays the script of a fitted row (ok); sets its replay numbers. Touches only
// the model's folder and `row`, so it may run beside the next model's fit.
void ReplayModel(const RunOptions& options, ResultsRow* row);

}  // namespace opgraph
