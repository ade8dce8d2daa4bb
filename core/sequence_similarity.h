// Similarity of two operation sequences by their op names (the paper's sequence metrics).
#pragma once

#include <string>
#include <vector>

namespace opgraph {

// Longest common subsequence length / the longer length, in [0, 1] (1 for two empty lists).
double NormalizedLcsSimilarity(const std::vector<std::string>& a, const std::vector<std::string>& b);

// 1 - Levenshtein distance (insert, delete, substitute: cost 1) / the longer length, in [0, 1].
double LevenshteinSimilarity(const std::vector<std::string>& a, const std::vector<std::string>& b);

}  // namespace opgraph
