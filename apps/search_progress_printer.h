// Shows a search's progress on a terminal: on a TTY a bar redrawn in place under the decision
// lines (stage, share of the work budget, an ETA, ops, loss); otherwise plain lines, the
// decisions and one progress line per tenth of the budget.
#pragma once

#include <ostream>

#include "search/zero_shot.h"

namespace opgraph {

class SearchProgressPrinter {
 public:
  // `interactive`: `out` is a terminal (the bar is redrawn in place).
  SearchProgressPrinter(std::ostream* out, bool interactive) : out_(out), interactive_(interactive) {}

  // The callback for ZeroShotOptions::on_progress (never cancels).
  bool operator()(const SearchProgress& progress);
  // Ends the bar's line (call once the search has returned).
  void Close();

 private:
  void DrawBar(const SearchProgress& progress);

  std::ostream* out_;
  bool interactive_;
  bool bar_drawn_ = false;
  int last_tenth_ = 0;
};

}  // namespace opgraph
