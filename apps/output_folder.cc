#include "apps/output_folder.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <stdexcept>
#include <system_error>

#include "core/printable.h"

namespace opgraph {
namespace {

namespace fs = std::filesystem;

// A name beside `out_dir` for this process: "<out_dir>.<what>-<pid>".
std::string Beside(const std::string& out_dir, const char* what) {
  fs::path path = fs::path(out_dir).lexically_normal();
  if (path.filename().empty()) path = path.parent_path();  // "out/" -> "out"
  return path.string() + "." + what + "-" + std::to_string(getpid());
}

}  // namespace

std::string CheckOutputFolder(const std::string& out_dir) {
  std::error_code error;
  const fs::path out(out_dir);
  if (fs::exists(out, error) && !fs::is_directory(out, error)) return "--out '" + out_dir + "' exists and is not a folder";
  if (fs::is_directory(out, error)) {
    // Replacing the folder deletes what it holds: only an earlier run's files may be there.
    static const char* const kOurs[] = {"sequence.json", "result.obj",  "result.glb", "rebuild_blender.py",
                                        "metrics.json",  "log.txt",     "blender.obj", "report.html", "steps"};
    for (const fs::directory_entry& entry : fs::directory_iterator(out, error)) {
      const std::string name = entry.path().filename().string();
      if (std::find(std::begin(kOurs), std::end(kOurs), name) == std::end(kOurs)) {
        return "--out '" + out_dir + "' holds '" + Printable(name) +
               "', which opgraph did not write; the folder would be replaced, so choose another";
      }
    }
  }
  fs::path parent = fs::absolute(out, error).lexically_normal();
  if (parent.filename().empty()) parent = parent.parent_path();
  parent = parent.parent_path();
  while (!parent.empty() && !fs::exists(parent, error) && parent != parent.parent_path()) parent = parent.parent_path();
  if (!fs::is_directory(parent, error)) return "--out '" + out_dir + "': '" + parent.string() + "' is not a folder";
  if (access(parent.c_str(), W_OK | X_OK) != 0) return "--out '" + out_dir + "': cannot write in '" + parent.string() + "'";
  return "";
}

StagedOutputFolder::StagedOutputFolder(std::string out_dir)
    : out_dir_(std::move(out_dir)), staging_dir_(Beside(out_dir_, "writing")) {
  std::error_code error;
  fs::remove_all(staging_dir_, error);
  const fs::path parent = fs::path(staging_dir_).parent_path();
  if (!parent.empty()) fs::create_directories(parent, error);
  if (!fs::create_directory(staging_dir_, error)) {
    throw std::runtime_error("cannot create '" + staging_dir_ + "': " + error.message());
  }
}

StagedOutputFolder::~StagedOutputFolder() {
  std::error_code error;
  if (!committed_) fs::remove_all(staging_dir_, error);
}

void StagedOutputFolder::Commit() {
  std::error_code error;
  const std::string old_dir = Beside(out_dir_, "old");
  const bool had_old = fs::exists(out_dir_, error);
  if (had_old) {
    fs::remove_all(old_dir, error);
    fs::rename(out_dir_, old_dir, error);
    if (error) throw std::runtime_error("cannot move the old '" + out_dir_ + "' aside: " + error.message());
  }
  fs::rename(staging_dir_, out_dir_, error);
  if (error) {
    std::error_code restore;
    if (had_old) fs::rename(old_dir, out_dir_, restore);
    throw std::runtime_error("cannot move the outputs into '" + out_dir_ + "': " + error.message());
  }
  committed_ = true;
  if (had_old) fs::remove_all(old_dir, error);
}

}  // namespace opgraph
