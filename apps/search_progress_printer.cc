#include "apps/search_progress_printer.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace opgraph {
namespace {

// "1m05s" or "42s".
std::string Duration(double seconds) {
  const int whole = static_cast<int>(std::lround(std::max(0.0, seconds)));
  std::ostringstream text;
  if (whole >= 60) text << whole / 60 << "m" << std::setw(2) << std::setfill('0') << whole % 60 << "s";
  else text << whole << "s";
  return text.str();
}

std::string Summary(const SearchProgress& progress) {
  std::ostringstream text;
  text << progress.stage << " " << std::setw(3) << static_cast<int>(std::floor(100 * progress.fraction)) << "%";
  // Work is spent at a roughly even rate, so the time left follows from the share done.
  if (progress.fraction > 0.02 && progress.fraction < 1) {
    text << ", ETA " << Duration(progress.seconds * (1 - progress.fraction) / progress.fraction);
  }
  text << ", " << progress.ops << " ops";
  if (std::isfinite(progress.loss)) text << ", loss " << std::setprecision(3) << progress.loss;
  return text.str();
}

}  // namespace

bool SearchProgressPrinter::operator()(const SearchProgress& progress) {
  if (interactive_) {
    if (!progress.line.empty()) *out_ << "\r\033[K" << progress.line << "\n";
    DrawBar(progress);
  } else {
    const int tenth = static_cast<int>(std::floor(10 * progress.fraction));
    if (tenth > last_tenth_) {
      last_tenth_ = tenth;
      *out_ << "[progress] " << Summary(progress) << " (" << Duration(progress.seconds) << ")" << std::endl;
    }
  }
  return true;
}

void SearchProgressPrinter::DrawBar(const SearchProgress& progress) {
  constexpr int kWidth = 30;
  const int filled = std::clamp(static_cast<int>(std::lround(kWidth * progress.fraction)), 0, kWidth);
  *out_ << "\r\033[K[" << std::string(filled, '#') << std::string(kWidth - filled, '.') << "] " << Summary(progress)
        << std::flush;
  bar_drawn_ = true;
}

void SearchProgressPrinter::Close() {
  if (bar_drawn_) *out_ << "\r\033[K" << std::flush;
  bar_drawn_ = false;
}

}  // namespace opgraph
