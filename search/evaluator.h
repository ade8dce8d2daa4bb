// The search's access to the fitter: fits layouts to the target, a batch at a time on the
// option's threads (each document fitted once, later requests answered from a cache keyed by
// the document), keeps the budget in work (and the optional time cap), counts fits, reports
// progress and records the decision log. A batch's results are recorded in the batch's order,
// so the log, the cache and the work count do not depend on which thread fitted what.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "search/layout.h"
#include "search/zero_shot.h"
#include "solver/fitter.h"
#include "solver/target.h"

namespace opgraph {

enum class FitPrecision { kSearch, kFinal };

class Evaluator {
 public:
  Evaluator(const Target& target, const ZeroShotOptions& options);

  // `layout` fitted to the target. Not ok when the layout has more ops than allowed, the fit
  // fails with an engine error (logged), or the fitted sequence would not replay (its
  // selectors re-resolve at the fitted parameters, ops/replay_guards.h).
  Trial Fit(const Layout& layout, FitPrecision precision = FitPrecision::kSearch);
  // Fit() of every layout, the uncached ones in parallel; trials in the order of `layouts`.
  std::vector<Trial> FitAll(const std::vector<Layout>& layouts, FitPrecision precision = FitPrecision::kSearch);
  // Speculation for idle threads: fits the layouts not fitted yet, in parallel, and keeps the
  // outcomes aside. A later Fit or FitAll of the same document takes its outcome (counting its
  // work and logging its error then), as if it fitted it then, so prefetching changes the wall
  // time and nothing else.
  // With `meanwhile`, it runs on the calling thread while the layouts are fitted on the others
  // (it may use this evaluator). With one thread, only `meanwhile` runs.
  void Prefetch(const std::vector<Layout>& layouts, FitPrecision precision = FitPrecision::kSearch,
                const std::function<void()>& meanwhile = nullptr);
  // Whether Fit(layout) would fit it now (not cached, not prefetched).
  bool NeedsFit(const Layout& layout) const;
  // Speculation on `count` lines of search (the beam's branches) that will run here one after
  // another: copies of this evaluator, each fitting on `num_threads` threads, writing no log
  // lines and keeping the outcome of every fit it takes; the first reports progress (without
  // decision lines) to the options' callback, which may cancel. Line i stops where the work of
  // lines 0..i-1 so far and its own have spent the budget (its real run cannot go further).
  // Adopt() then keeps a speculator's outcomes aside here as Prefetch() does, so a later run of
  // the same line here takes them, as if it fitted them then.
  std::vector<Evaluator> Speculators(int count, int num_threads) const;
  void Adopt(Evaluator* speculator);
  // A speculator whose line has ended, with no line left to start: its threads help the lines
  // still running (their batches and prefetches).
  void LendThreads();
  // The threads this evaluator's batches may use now: the options' and those lent to it.
  int Threads() const;
  // The finishing gate fit of `sequence` (parsed from `document`): op gates fitted with the
  // sparsity stage, ops below the threshold pruned. Throws the fitter's errors.
  FitSummary FitGates(Sequence* sequence, const Json& document, const Vec3d& half_extent);
  // `document` parsed with the search's size limit (ZeroShotOptions::max_faces): evaluating it
  // refuses a step above --max-faces, so no sequence the search writes is larger than that.
  Sequence Parse(const Json& document) const;
  // The fitter options of `precision`, with the domain rules of `document`.
  FitterOptions FitOptions(FitPrecision precision, const Json& document, const Vec3d& half_extent) const;

  // Proposals stop at this share of the budget; the finishing fits (gate pruning, polishing,
  // simplification: 20-40 s on a 20-op sequence) take the rest.
  static constexpr double kSearchShare = 0.65;
  // Under a time cap, the shares of it by which each finishing step ends (the fits are cut, the
  // optional steps skipped), so the run with its outputs ends within the cap: every fit (the
  // search's last batch, gate pruning, polishing) by kFitsShare, Simplify by kSimplifyShare,
  // the free-form fit by kFreeformShare. The rest is for writing the outputs.
  static constexpr double kFitsShare = 0.8, kSimplifyShare = 0.87, kFreeformShare = 0.93;
  // Seconds left until `share` of the time cap (0 when spent); infinite without a cap.
  double SecondsLeft(double share) const;
  bool TimeIsUp(double share) const { return !(SecondsLeft(share) > 0); }
  // The max_seconds of a fit that must end by `share` of the time cap: 0 (none) without a cap;
  // a microsecond once it is spent (the fit is cut at once).
  double FitMaxSeconds(double share) const;
  // A finishing step cut or skipped by the time cap: noted in the log and in the result.
  void NoteCutByTime(const std::string& step, const std::string& line);
  const std::vector<std::string>& cut_by_time() const { return cut_by_time_; }
  // Whether proposals may still be fitted: the search's share of the work budget and of the
  // time cap are not spent, and the progress callback has not cancelled.
  bool InBudget() const;
  double Seconds() const;
  // kComplete unless InBudget() has said no.
  SearchEnd search_end() const { return search_end_; }
  int64_t work() const { return work_; }
  // Each fit's work and wall time, in the order the search used them (the times, unlike the
  // work, depend on the machine): how well work tracks time.
  const std::vector<FitCost>& fit_costs() const { return fit_costs_; }
  // Reports progress to the options' callback (also done after each batch, by Log and by Note).
  void Report(const std::string& line = "") const;
  // The stage named in progress reports ("search" until the finishing steps begin) and the
  // fraction of the whole run it starts at (the search's share of the work budget maps to
  // [0, kSearchProgress]; finishing steps, which take no fixed work, name their own).
  void BeginStage(const std::string& stage, double fraction) { stage_ = stage, stage_fraction_ = fraction; }
  static constexpr double kSearchProgress = 0.85;

  // A decision line: "[zero-shot] stage: what: loss a -> b accepted (n ops, k fits, w work)".
  void Log(const std::string& stage, const Trial& before, const Trial& after, bool accepted, const std::string& what);
  void Note(const std::string& line);  // a line as given, prefixed with "[zero-shot] "

  const Target& target() const { return target_; }
  const ZeroShotOptions& options() const { return options_; }
  int num_fits() const { return num_fits_; }
  int num_fits_ahead() const { return num_fits_ahead_; }
  const std::vector<std::string>& decisions() const { return decisions_; }

 private:
  const Target& target_;
  ZeroShotOptions options_;
  FitterOptions search_options_, final_options_;
  // One fit's trial, work, wall time and engine error.
  struct Outcome {
    Trial trial;
    bool fitted = false;  // the fitter ran (a layout with too many ops is not fitted)
    int64_t work = 0;
    double seconds = 0;
    std::string error;  // the engine's error, when it rejected the layout
    // A speculator's outcome that an earlier line's speculator fitted: the serial run will have
    // it cached by then, so it counts no work here.
    bool from_earlier_line = false;
  };
  Outcome FitUncached(const Layout& layout, FitPrecision precision) const;
  // FitUncached; for a speculator, once per speculation: the outcome another line's
  // speculator fitted or is fitting, if any (lines that reach the same layout, as a beam branch
  // that takes another's main form does, would otherwise fit it twice where the serial run's
  // cache fits it once).
  Outcome FitOnce(const std::string& key, const Layout& layout, FitPrecision precision) const;
  static std::string Key(const Layout& layout, FitPrecision precision);

  std::chrono::steady_clock::time_point start_;
  std::map<std::string, Trial> cache_;
  std::map<std::string, Outcome> prefetched_;  // by key (precision and document)
  mutable SearchEnd search_end_ = SearchEnd::kComplete;
  mutable bool cancelled_ = false;
  std::string stage_ = "search";
  double stage_fraction_ = 0;  // after the search: the finishing step's start
  int num_fits_ = 0, num_fits_ahead_ = 0;
  int64_t work_ = 0;
  std::vector<FitCost> fit_costs_;
  // The best trial logged as accepted, for progress.
  int best_ops_ = 0;
  double best_loss_ = std::numeric_limits<double>::infinity();
  std::vector<std::string> decisions_;
  std::vector<std::string> cut_by_time_;
  // A speculator's: no log lines; the outcomes of its fits, by key, for Adopt().
  bool speculative_ = false;
  std::vector<std::pair<std::string, Outcome>> speculated_;
  // The work each line of a speculation has done so far, shared by its speculators; this one's
  // line, and its work when the speculation began.
  std::shared_ptr<std::vector<std::atomic<int64_t>>> line_work_;
  int line_ = 0;
  int64_t work_at_start_ = 0;
  // The fits of this speculation by key, shared by its speculators (FitOnce).
  struct SharedFits;
  std::shared_ptr<SharedFits> shared_fits_;
  // Threads lent by the speculators whose lines have ended, shared by those still running.
  std::shared_ptr<std::atomic<int>> spare_threads_;
  int BorrowThreads(int wanted) const;
  void ReturnThreads(int count) const;
  // Set when the callback cancels during speculation: every speculator (and, at Adopt, this
  // evaluator) stops.
  std::shared_ptr<std::atomic<bool>> speculation_cancelled_ = std::make_shared<std::atomic<bool>>(false);
};

}  // namespace opgraph
