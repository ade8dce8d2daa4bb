// The output folder of a run, replaced whole or not at all: files are written into a staging
// folder beside it, which takes its place on Commit(). A run that fails leaves the old folder
// as it was, and a rerun leaves no file of the old run (an old step the new sequence lacks).
#pragma once

#include <string>

namespace opgraph {

// Empty when `out_dir` can take a run's outputs, else the problem (for a one-line error before
// any work): it is a file; it is a folder holding anything but an earlier run's outputs
// (replacing it would delete the user's files); or its parent folder cannot be written.
std::string CheckOutputFolder(const std::string& out_dir);

class StagedOutputFolder {
 public:
  // Creates the staging folder beside `out_dir`. Throws std::runtime_error.
  explicit StagedOutputFolder(std::string out_dir);
  StagedOutputFolder(const StagedOutputFolder&) = delete;
  StagedOutputFolder& operator=(const StagedOutputFolder&) = delete;
  // Removes the staging folder unless committed.
  ~StagedOutputFolder();

  // Where to write the outputs until Commit().
  const std::string& staging_dir() const { return staging_dir_; }
  // Puts the staging folder in the place of `out_dir` (an old one is removed after the swap).
  // Throws std::runtime_error.
  void Commit();

 private:
  std::string out_dir_, staging_dir_;
  bool committed_ = false;
};

}  // namespace opgraph
