#include "core/sequence_similarity.h"

#include <algorithm>

namespace opgraph {

double NormalizedLcsSimilarity(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  const size_t longer = std::max(a.size(), b.size());
  if (longer == 0) return 1.0;
  // lcs[i][j]: LCS of a[0, i) and b[0, j), one row at a time.
  std::vector<size_t> previous(b.size() + 1, 0), current(b.size() + 1, 0);
  for (size_t i = 1; i <= a.size(); ++i) {
    for (size_t j = 1; j <= b.size(); ++j) {
      current[j] = a[i - 1] == b[j - 1] ? previous[j - 1] + 1 : std::max(previous[j], current[j - 1]);
    }
    std::swap(previous, current);
  }
  return static_cast<double>(previous[b.size()]) / static_cast<double>(longer);
}

double LevenshteinSimilarity(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  const size_t longer = std::max(a.size(), b.size());
  if (longer == 0) return 1.0;
  std::vector<size_t> previous(b.size() + 1), current(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t substitute = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitute});
    }
    std::swap(previous, current);
  }
  return 1.0 - static_cast<double>(previous[b.size()]) / static_cast<double>(longer);
}

}  // namespace opgraph
