// The results document: each set's rows kept as docs/results/<set>.json (with the commit,
// date and budget of the run that made them), and docs/results.md rendered from every set on
// record, so a run of one set refreshes its section and leaves the others as they were.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "benchmarks/results_run.h"

namespace opgraph {

struct SetRecord {
  std::string set, commit, date;
  int time_budget = 0, jobs = 0;  // time_budget: a cap in seconds (0: none)
  int64_t work_budget = 0;         // 0: a record made before the work budget
  int threads = 0;                 // fit_sequence --threads (0: its default)
  std::vector<ResultsRow> rows;
};

// Writes `record` to `dir`/<set>.json (atomically).
void SaveSetRecord(const SetRecord& record, const std::filesystem::path& dir);
// Every set on record in `dir`, in ResultsSetNames() order.
std::vector<SetRecord> LoadSetRecords(const std::filesystem::path& dir);

// The one-line summary numbers of a set, as the summary table shows them.
std::string SummaryRow(const SetRecord& record);
// docs/results.md.
// `cloud_points` > 0: the page of a point-cloud run (run_results --cloud N).
std::string ResultsMarkdown(const std::vector<SetRecord>& records, int cloud_points = 0);

}  // namespace opgraph
