// Runs fit_sequence (the main job, zero-shot) on the models of one evaluation set, or all of
// them, in parallel over models, and writes docs/results.md (docs/corpus.md has the sets).
//   build/run_results --set all|gt-dev|synth-tune|synth-heldout|real-dev|real-tune|real-heldout
#include <gflags/gflags.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <ctime>
#include <future>
#include <iostream>
#include <map>
#include <mutex>
#include <thread>

#include "apps/cli_flags.h"
#include "benchmarks/results_doc.h"
#include "core/obj_io.h"
#include "core/parallel_for.h"
#include "search/zero_shot.h"

DEFINE_string(set, "all", "the set to run: all, gt-dev, synth-tune, synth-heldout, real-dev, real-tune, real-heldout");
DEFINE_string(data, "../shared/data", "the reference data (gt-dev, real-dev, real-train)");
DEFINE_string(synth, "out/synth", "the synthetic corpus written by build/make_synth");
DEFINE_string(out, "out/results", "where each model's fit_sequence outputs go (out/SET/MODEL)");
DEFINE_string(doc, "docs/results.md", "the results page to write");
DEFINE_string(records, "docs/results", "the folder of per-set records (SET.json) the page is rendered from");
DEFINE_int64(work_budget, 0, "fit_sequence --work-budget per model (0: its default)");
DEFINE_int32(time_budget, 0, "fit_sequence --time-budget per model, a cap in seconds (0: none)");
DEFINE_int32(threads, 0, "fit_sequence --threads per model (0: its default, every hardware thread)");
DEFINE_string(fit_flags, "", "more fit_sequence flags for every model, as given (e.g. '--op-price 0.15')");
DEFINE_int32(jobs, 0, "models run at once (0: one per hardware thread)");
DEFINE_int32(limit, 0,
             "only the first N models of each set (0: all), for quick tuning runs; their records and page go to "
             "out/results_limited unless --records and --doc say otherwise");
DEFINE_int32(cloud, 0,
             "> 0: give fit_sequence each model as a cloud of this many surface samples without normals "
             "(the issue's protocol: 20000), compare with the model mesh; records, page and outputs go to "
             "docs/results-cloud, docs/results-cloud.md and out/results-cloud unless given");
DEFINE_bool(render_only, false, "only re-render the page from the records (no model is run)");
DEFINE_string(commit, "", "the commit named in the records (default: git rev-parse --short HEAD)");

namespace fs = std::filesystem;
using namespace opgraph;

namespace {

std::string Capture(const std::string& command) {
  std::string text;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    char buffer[256];
    while (fgets(buffer, sizeof(buffer), pipe)) text += buffer;
    pclose(pipe);
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

std::string Today() {
  const std::time_t now = std::time(nullptr);
  char date[16];
  std::strftime(date, sizeof(date), "%Y-%m-%d", std::gmtime(&now));
  return date;
}

}  // namespace

int main(int argc, char** argv) {
  ParseCommandLineOrExit(argc, argv,
                         {"run_results", "usage: run_results [--set NAME] [--work_budget N] [--time_budget S] [--jobs N]",
                          __FILE__, /*max_arguments=*/0});
  if (FLAGS_work_budget < 0 || FLAGS_time_budget < 0 || FLAGS_threads < 0 || FLAGS_jobs < 0 || FLAGS_limit < 0) {
    std::cerr << "run_results: --work_budget, --time_budget, --threads, --jobs and --limit must be >= 0\n";
    return 2;
  }
  auto is_default = [](const char* flag) { return gflags::GetCommandLineFlagInfoOrDie(flag).is_default; };
  if (FLAGS_cloud < 0) {
    std::cerr << "run_results: --cloud must be >= 0\n";
    return 2;
  }
  if (FLAGS_cloud > 0 && is_default("records")) FLAGS_records = "docs/results-cloud";
  if (FLAGS_cloud > 0 && is_default("doc")) FLAGS_doc = "docs/results-cloud.md";
  if (FLAGS_cloud > 0 && is_default("out")) FLAGS_out = "out/results-cloud";
  // A limited run never overwrites the full sets' records or page.
  if (FLAGS_limit > 0 && is_default("records")) FLAGS_records = FLAGS_cloud > 0 ? "out/results_limited-cloud" : "out/results_limited";
  if (FLAGS_limit > 0 && is_default("doc")) FLAGS_doc = FLAGS_records + "/results.md";
  if (FLAGS_render_only) {
    WriteFileAtomic(FLAGS_doc, ResultsMarkdown(LoadSetRecords(FLAGS_records), FLAGS_cloud));
    std::cout << "[results] wrote " << FLAGS_doc << std::endl;
    return 0;
  }
  std::vector<ResultsModel> models;
  try {
    models = ListModels(FLAGS_set, FLAGS_data, FLAGS_synth);
    if (FLAGS_limit > 0) {
      std::map<std::string, int> taken;
      std::vector<ResultsModel> limited;
      for (const ResultsModel& model : models) {
        if (taken[model.set]++ < FLAGS_limit) limited.push_back(model);
      }
      models = limited;
    }
  } catch (const std::exception& e) {
    std::cerr << "run_results: " << e.what() << "\n";
    return 2;
  }
  RunOptions options;
  options.fit_sequence = fs::path(argv[0]).parent_path() / "fit_sequence";
  options.out = FLAGS_out;
  options.work_budget = FLAGS_work_budget;
  options.time_budget = FLAGS_time_budget;
  options.threads = FLAGS_threads;
  options.fit_flags = FLAGS_fit_flags;
  options.cloud_points = FLAGS_cloud;
  const int jobs = FLAGS_jobs > 0 ? FLAGS_jobs : std::max(1u, std::thread::hardware_concurrency());
  for (const std::string& set : ResultsSetNames()) fs::create_directories(options.out / set);

  // Smaller sets first, so a run cut short still leaves whole sets on record.
  std::map<std::string, int> set_sizes;
  for (const ResultsModel& model : models) ++set_sizes[model.set];
  std::stable_sort(models.begin(), models.end(), [&](const ResultsModel& a, const ResultsModel& b) {
    return set_sizes[a.set] < set_sizes[b.set];
  });
  const std::string commit = FLAGS_commit.empty() ? Capture("git rev-parse --short HEAD 2>/dev/null") : FLAGS_commit;
  std::vector<ResultsRow> rows(models.size());
  std::vector<bool> finished_rows(models.size(), false);
  std::atomic<size_t> next{0}, done{0};
  std::mutex print;
  // Saves `set`'s record and re-renders the page once all its models are done (under `print`).
  auto save_if_complete = [&](const std::string& set) {
    SetRecord record{set, commit.empty() ? "unknown" : commit, Today(), FLAGS_time_budget, jobs,
                     FLAGS_work_budget > 0 ? FLAGS_work_budget : ZeroShotOptions().work_budget, FLAGS_threads, {}};
    for (size_t k = 0; k < models.size(); ++k) {
      if (models[k].set != set) continue;
      if (!finished_rows[k]) return;
      record.rows.push_back(rows[k]);
    }
    std::sort(record.rows.begin(), record.rows.end(), [](const ResultsRow& a, const ResultsRow& b) { return a.name < b.name; });
    SaveSetRecord(record, FLAGS_records);
    WriteFileAtomic(FLAGS_doc, ResultsMarkdown(LoadSetRecords(FLAGS_records), FLAGS_cloud));
    std::cout << "[results] " << set << " done; wrote " << FLAGS_doc << std::endl;
  };
  const auto start = std::chrono::steady_clock::now();
  // A finished row, printed and saved.
  auto record = [&](size_t k) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const size_t finished = ++done;
    std::lock_guard<std::mutex> lock(print);
    finished_rows[k] = true;
    std::cout << "[results " << finished << "/" << models.size() << ", " << static_cast<int>(elapsed) << " s] "
              << models[k].set << "/" << models[k].name << ": "
              << (rows[k].ok ? "Chamfer " + std::to_string(rows[k].chamfer) : "failed: " + rows[k].error) << ", "
              << static_cast<int>(rows[k].seconds) << " s" << std::endl;
    save_if_complete(models[k].set);
  };
  // With more than one thread a model, a model's Blender replay (one process, mostly one core)
  // runs beside the next model's fit, which leaves a core idle for much of its search; the fits
  // give the same outputs under any load, so only the wall time changes.
  const bool overlap_replays = (FLAGS_threads > 0 ? FLAGS_threads : HardwareThreads()) > 1;
  std::vector<std::thread> workers;
  for (int j = 0; j < jobs; ++j) {
    workers.emplace_back([&] {
      std::future<void> replay;
      size_t replaying = 0;
      auto end_replay = [&] {
        if (!replay.valid()) return;
        replay.get();
        record(replaying);
      };
      for (size_t k; (k = next++) < models.size();) {
        rows[k] = FitModel(models[k], options);
        end_replay();
        if (overlap_replays) {
          replaying = k;
          replay = std::async(std::launch::async, [&, k] { ReplayModel(options, &rows[k]); });
        } else {
          ReplayModel(options, &rows[k]);
          record(k);
        }
      }
      end_replay();
    });
  }
  for (std::thread& worker : workers) worker.join();

  for (const SetRecord& record : LoadSetRecords(FLAGS_records)) std::cout << SummaryRow(record);
  return 0;
}
