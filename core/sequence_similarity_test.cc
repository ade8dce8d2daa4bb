#include "core/sequence_similarity.h"

#include <gtest/gtest.h>

namespace opgraph {
namespace {

using Names = std::vector<std::string>;

TEST(SequenceSimilarity, HandComputedCases) {
  const Names truth = {"GlobalAffineScale", "LoopCut", "EdgeLoopAffineScale", "Subdivision"};
  EXPECT_DOUBLE_EQ(NormalizedLcsSimilarity(truth, truth), 1.0);
  EXPECT_DOUBLE_EQ(LevenshteinSimilarity(truth, truth), 1.0);
  // One op dropped: LCS 3 of 4, one deletion.
  const Names dropped = {"GlobalAffineScale", "LoopCut", "Subdivision"};
  EXPECT_DOUBLE_EQ(NormalizedLcsSimilarity(truth, dropped), 0.75);
  EXPECT_DOUBLE_EQ(LevenshteinSimilarity(truth, dropped), 0.75);
  // Two ops swapped: LCS 3 of 4; Levenshtein needs 2 substitutions.
  const Names swapped = {"LoopCut", "GlobalAffineScale", "EdgeLoopAffineScale", "Subdivision"};
  EXPECT_DOUBLE_EQ(NormalizedLcsSimilarity(truth, swapped), 0.75);
  EXPECT_DOUBLE_EQ(LevenshteinSimilarity(truth, swapped), 0.5);
  // kitten -> sitting as op lists: Levenshtein 3 over 7, LCS 4 ("i t t n").
  const Names kitten = {"k", "i", "t", "t", "e", "n"};
  const Names sitting = {"s", "i", "t", "t", "i", "n", "g"};
  EXPECT_DOUBLE_EQ(LevenshteinSimilarity(kitten, sitting), 1.0 - 3.0 / 7.0);
  EXPECT_DOUBLE_EQ(NormalizedLcsSimilarity(kitten, sitting), 4.0 / 7.0);
  EXPECT_DOUBLE_EQ(NormalizedLcsSimilarity({}, {}), 1.0);
  EXPECT_DOUBLE_EQ(LevenshteinSimilarity({}, {"a"}), 0.0);
}

}  // namespace
}  // namespace opgraph
