// The point-cloud readers behind ReadInput (io/read_input.h): PCD and point PLY through PCL, in a
// child process (io/read_in_child_process.h), and XYZ text. Each throws std::runtime_error
// "PATH: problem"; ReadInput checks the coordinates afterwards.
#pragma once

#include <pcl/console/print.h>

#include <mutex>
#include <string>

#include "io/read_input.h"

namespace opgraph {

InputGeometry ReadPcdPoints(const std::string& path);
InputGeometry ReadPlyPoints(const std::string& path);
// `x y z [nx ny nz]` per line (commas allowed, `#` comments).
InputGeometry ReadXyzPoints(const std::string& path);

// Lowers PCL's process-wide verbosity while any read runs; the first read in saves the host's
// level and the last one out restores it (so overlapping reads on two threads restore it too).
class QuietPcl {
 public:
  QuietPcl() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (readers_++ == 0) {
      saved_ = pcl::console::getVerbosityLevel();
      pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
    }
  }
  ~QuietPcl() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (--readers_ == 0) pcl::console::setVerbosityLevel(saved_);
  }

 private:
  static inline std::mutex mutex_;
  static inline int readers_ = 0;
  static inline pcl::console::VERBOSITY_LEVEL saved_ = pcl::console::L_INFO;
};

}  // namespace opgraph
